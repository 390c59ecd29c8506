// Planners over an occupancy grid: SPIKE (any-angle search over the
// quadtree) and the baseline octile A*, both GridPlanners (grid_planner.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrt_spike/grid.h"
#include "mrt_spike/grid_planner.h"
#include "mrt_spike/quadtree.h"
#include "mrt_spike/subgoal_graph.h"

namespace mrt::spike {

/// Why there is no path, and the nearest reachable point, in O(cells):
/// a blocked start gives the free cell nearest it; a blocked goal or an
/// unreachable one gives the cell reachable from the start nearest the goal.
/// Returns an empty reason when the goal is reachable.
PlanResult diagnose(const OccupancyGrid& grid, const Cell& start, const Cell& goal);

/// Plain octile A* on the grid: 8-connected, cost 1 and sqrt(2), no corner
/// cutting (a diagonal move needs both adjacent straight cells free), binary
/// heap, octile heuristic. The baseline. Reads the grid at every query (its
/// size fixed): it follows the grid's changes.
class GridAstar final : public GridPlanner {
 public:
  explicit GridAstar(const OccupancyGrid& grid);
  PlanResult plan(const Cell& start, const Cell& goal) override;
  std::string name() const override { return "astar"; }
  PlannerCapabilities capabilities() const override { return kCapabilities; }
  static constexpr PlannerCapabilities kCapabilities{true, true};
  /// The same search restricted to the cells c with mask[index(c)] == stamp.
  PlanResult plan_within(const Cell& start, const Cell& goal, const std::vector<unsigned>& mask,
                         unsigned stamp);

 private:
  PlanResult run(const Cell& start, const Cell& goal, const std::vector<unsigned>* mask, unsigned stamp);
  const OccupancyGrid& grid_;
  std::vector<double> g_;
  std::vector<int> parent_;
  std::vector<unsigned> stamp_;
  std::vector<unsigned char> closed_;
  unsigned run_ = 0;
};

struct SpikeOptions {
  /// Search graph: the subgoal graph (octile-optimal, then string pulling;
  /// the default) or the quadtree's leaves (Lazy Theta*, optionally refined).
  enum class Graph { subgoal, quadtree };
  Graph graph = Graph::subgoal;
  /// Landmarks of the differential heuristic over the subgoal graph (0: the
  /// octile heuristic alone). Preprocessing: one Dijkstra over the graph each.
  int landmarks = 16;
  QuadtreeOptions quadtree;
  bool smooth = true;  ///< final string pulling
  bool refine = true;  ///< octile A* + string pulling in the corridor of leaves around the path
};

/// SPIKE: Lazy Theta* over the quadtree leaves (vertices: the leaves'
/// representative cells; parents may be any earlier vertex in line of sight
/// on the fine grid), then string pulling. The quadtree is built once
/// (preprocessing); queries reuse it, so later changes of the grid are not
/// seen (DynamicSpike adds moving obstacles).
class SpikePlanner final : public GridPlanner {
 public:
  SpikePlanner(const OccupancyGrid& grid, SpikeOptions options = {});
  PlanResult plan(const Cell& start, const Cell& goal) override;
  std::string name() const override { return "spike"; }
  PlannerCapabilities capabilities() const override { return kCapabilities; }
  static constexpr PlannerCapabilities kCapabilities{false, true};
  const Quadtree& quadtree() const { return *tree_; }
  /// The subgoal graph (null when options.graph is quadtree).
  const SubgoalGraph* subgoal_graph() const { return subgoals_.get(); }
  const OccupancyGrid& grid() const { return grid_; }

 private:
  double search(const Cell& start, const Cell& goal, std::vector<Cell>& path, int& expansions);
  int set_vertex(int s, int n_leaves);
  std::vector<Cell> refine(const std::vector<Cell>& path);

  const OccupancyGrid& grid_;
  SpikeOptions options_;
  std::unique_ptr<Quadtree> tree_;
  std::unique_ptr<GridAstar> fallback_;
  std::unique_ptr<SubgoalGraph> subgoals_;
  // search state, indexed by leaf id; start = n, goal = n + 1
  std::vector<double> g_;
  std::vector<int> parent_;
  std::vector<unsigned> stamp_;
  std::vector<unsigned char> closed_;
  std::vector<Cell> point_;
  unsigned run_ = 0;
  std::vector<unsigned> leaf_mark_;
  std::vector<unsigned> cell_mark_;
  unsigned mark_ = 0;
};

/// Removes waypoints while the straight segment stays valid (greedy string
/// pulling from the first waypoint). Never lengthens the path.
std::vector<Cell> string_pull(const OccupancyGrid& grid, const std::vector<Cell>& path);
std::vector<Cell> string_pull(const Quadtree& tree, const std::vector<Cell>& path);

}  // namespace mrt::spike
