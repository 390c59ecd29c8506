// The one interface of SPIKE's planning algorithms (as OMPL's Planner): a
// query from a start cell to a goal cell on an occupancy grid, the
// algorithm's name and what it can honour beyond one query on a fixed grid.
// planner_factory.h makes them by name.
#pragma once

#include <string>
#include <vector>

#include "mrt_spike/grid.h"

namespace mrt::spike {

struct PlanResult {
  bool solved = false;
  std::vector<Cell> path;  ///< waypoints (cell centres), start first, goal last
  double length = 0.0;
  std::string reason;      ///< why not solved (DynamicSpike: "static" when the static plan was kept)
  Cell nearest;            ///< when not solved: the reachable cell nearest the goal
                           ///< (or nearest the start when the start is blocked)
  int expansions = 0;
  bool fallback = false;   ///< SPIKE only: solved by the grid search after the quadtree failed
};

/// What an algorithm honours beyond one query on a grid that never changes.
/// Moving obstacles need both: their footprints change the grid between
/// queries, and a plan they block later is found by checking its segments
/// (DynamicPlanner::still_valid) and re-planned.
struct PlannerCapabilities {
  /// Reads the grid at every query, so cells blocked or freed after
  /// construction count (false: a structure built once, SpikePlanner's).
  bool follows_grid_changes = false;
  /// Every segment of its paths passes the grid's line-of-sight rule
  /// (line_of_sight.h), so a blocked plan can be detected (false: OMPL's
  /// states are checked every half cell and its waypoints rounded to cells).
  bool valid_paths = false;
  bool operator==(const PlannerCapabilities& o) const {
    return follows_grid_changes == o.follows_grid_changes && valid_paths == o.valid_paths;
  }
};

class GridPlanner {
 public:
  virtual ~GridPlanner() = default;
  /// A path from start to goal (cells); when none, the reason and the
  /// nearest reachable cell (diagnose()).
  virtual PlanResult plan(const Cell& start, const Cell& goal) = 0;
  /// The name make_planner() knows it by ("spike", "astar", "jps", "ompl").
  virtual std::string name() const = 0;
  virtual PlannerCapabilities capabilities() const = 0;
};

}  // namespace mrt::spike
