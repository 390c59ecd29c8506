// Simple subgoal graph (after Uras, Koenig & Hernandez 2013): the convex
// corners of the obstacles are the vertices, an edge joins two corners that
// reach each other by an octile-shortest path moving first diagonally then
// straight with no other corner in between. A search over it gives the
// shortest octile path; SPIKE then shortens it by string pulling.
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_spike/grid.h"

namespace mrt::spike {

class SubgoalGraph {
 public:
  /// Preprocessing: subgoals, the clearances in the 8 directions, the edges
  /// and, when landmarks > 0, that many landmarks with their distances to
  /// every subgoal (differential heuristic, see set_goal_bounds).
  explicit SubgoalGraph(const OccupancyGrid& grid, int landmarks = 0);

  /// The shortest octile path from start to goal (8-connected, no corner
  /// cutting) as waypoints: the subgoals and, between two of them, the cell
  /// where the diagonal run turns straight. Every segment is a diagonal or a
  /// straight run of valid moves. Empty when there is none (start or goal
  /// blocked, or not connected). `cost` gets the octile length.
  std::vector<Cell> plan(const Cell& start, const Cell& goal, double* cost = nullptr,
                         int* expansions = nullptr);

  const std::vector<Cell>& subgoals() const { return subgoals_; }
  int landmark_count() const { return landmarks_; }
  size_t edge_count() const { return adj_.size(); }
  bool is_subgoal(int x, int y) const { return grid_.inside(x, y) && sub_id_[grid_.index(x, y)] >= 0; }
  /// Subgoals reachable from the free cell c by a diagonal-then-straight
  /// octile path with no subgoal before the end (ids into subgoals()).
  void direct_h_reachable(const Cell& c, std::vector<int>& out) const;

 private:
  bool move_ok(int x, int y, int d) const;
  int clearance(int x, int y, int d) const { return clear_[d][grid_.index(x, y)]; }
  void add_if_subgoal(int x, int y, int d, int k, std::vector<int>& out) const;
  bool direct_octile(const Cell& a, const Cell& b, bool diagonal_first) const;
  std::vector<Cell> unfold(const std::vector<int>& chain, const Cell& start, const Cell& goal) const;
  void build_landmarks(int count);
  void dijkstra(int source, std::vector<double>& dist) const;
  void set_goal_bounds(const Cell& goal, const std::vector<int>& near, int goal_sub);
  double heuristic(int v, const Cell& p, const Cell& goal) const;

  const OccupancyGrid& grid_;
  std::vector<int> sub_id_;
  std::vector<Cell> subgoals_;
  std::vector<std::uint16_t> clear_[8];
  std::vector<int> adj_start_;
  std::vector<int> adj_;
  std::vector<float> adj_cost_;
  // landmarks: lm_dist_[v * landmarks_ + l] = graph distance from landmark l
  // to subgoal v (infinity when not connected); goal_lm_[l] the same for the
  // goal of the current query
  int landmarks_ = 0;
  std::vector<double> lm_dist_;
  std::vector<double> goal_lm_;
  // search state: subgoals 0..n-1, start n, goal n+1
  struct Entry {
    float f;
    float g;
    int v;
  };
  std::vector<double> g_;
  std::vector<double> h_;
  std::vector<Entry> heap_;
  std::vector<int> parent_;
  std::vector<unsigned> stamp_;
  std::vector<unsigned> goal_mark_;
  std::vector<unsigned char> closed_;
  unsigned run_ = 0;
  std::vector<int> scratch_;
};

/// Octile distance between two cells.
double octile(const Cell& a, const Cell& b);

}  // namespace mrt::spike
