// Multi-resolution decomposition of the free space: a region quadtree whose
// leaves are free squares, large in open space and one cell wide next to
// obstacles and in narrow passages.
#pragma once

#include <vector>

#include "mrt_spike/grid.h"

namespace mrt::spike {

struct QuadLeaf {
  int x = 0;     ///< top-left column
  int y = 0;     ///< top-left row
  int size = 1;  ///< side in cells (a power of two)
  int corners[5] = {-1, -1, -1, -1, -1};  ///< search vertices: corner cells, centre cell (-1: none)
  bool contains(int cx, int cy) const { return cx >= x && cy >= y && cx < x + size && cy < y + size; }
};

struct QuadtreeOptions {
  int max_leaf_size = 64;  ///< cap on a leaf's side (bounds the detour through a leaf's centre)
  bool centre_only = true;  ///< one vertex per leaf (its centre cell); false: corners + centre
};

class Quadtree {
 public:
  /// Builds the leaves over the free cells of `grid` and the search graph:
  /// vertices at the leaves' corner cells; edges between the corners of one
  /// leaf (a free square: always valid) and from each corner to the corners
  /// of the leaves touching it, kept when valid by the line-of-sight rule.
  Quadtree(const OccupancyGrid& grid, QuadtreeOptions options = {});

  const std::vector<QuadLeaf>& leaves() const { return leaves_; }
  /// Leaf covering cell (x, y), -1 when blocked or outside.
  int leaf_at(int x, int y) const {
    return grid_->inside(x, y) ? leaf_of_cell_[grid_->index(x, y)] : -1;
  }
  const std::vector<Cell>& vertices() const { return vertices_; }
  /// Neighbours of vertex i: [begin, end) into neighbour()/cost().
  int adj_begin(int i) const { return adj_start_[i]; }
  int adj_end(int i) const { return adj_start_[i + 1]; }
  int neighbour(int k) const { return adj_[k]; }
  float cost(int k) const { return adj_cost_[k]; }
  size_t edge_count() const { return adj_.size(); }
  /// line_of_sight() on the grid, jumping over the cells of large leaves
  /// (known free): O(leaves crossed + small cells crossed). Same answer.
  bool line_of_sight(const Cell& a, const Cell& b) const;
  const OccupancyGrid& grid() const { return *grid_; }

 private:
  void build(int x, int y, int size, const std::vector<int>& sat);
  void build_adjacency();

  const OccupancyGrid* grid_;
  QuadtreeOptions options_;
  std::vector<QuadLeaf> leaves_;
  std::vector<int> leaf_of_cell_;
  std::vector<Cell> vertices_;
  std::vector<int> adj_start_;
  std::vector<int> adj_;
  std::vector<float> adj_cost_;
};

}  // namespace mrt::spike
