// SPIKE's planning algorithms chosen by name, as OMPL's planners are:
// "spike" (SpikePlanner), "astar" (GridAstar, the baseline), "jps"
// (JumpPointSearch) and "ompl" (OmplPlanner: RRT* or PRM*). make_planner
// plans on a fixed grid (spike_plan, the benchmark); make_dynamic_planner
// plans among moving obstacles (WorldPlanner, spike_node) and refuses an
// algorithm whose capabilities do not allow it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrt_spike/grid_planner.h"
#include "mrt_spike/moving_obstacles.h"
#include "mrt_spike/ompl_planner.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

/// Every algorithm's options; each takes its own part.
struct PlannerOptions {
  SpikeOptions spike;  ///< "spike"
  OmplOptions ompl;    ///< "ompl"
};

/// One algorithm of the registry.
struct PlannerInfo {
  std::string name;
  std::string summary;
  PlannerCapabilities capabilities;  ///< of what make_planner returns
};

/// The registry, in the order spike, astar, jps, ompl.
const std::vector<PlannerInfo>& planners();
/// Their names, in the same order.
std::vector<std::string> planner_names();
/// The registry's entry of `name`; std::invalid_argument listing the names
/// when unknown.
const PlannerInfo& planner_info(const std::string& name);

/// The algorithm `name` over `grid` (kept by reference: it must outlive the
/// planner). Unknown name: std::invalid_argument listing the names; bad
/// options: the algorithm's own std::invalid_argument.
std::unique_ptr<GridPlanner> make_planner(const std::string& name, const OccupancyGrid& grid,
                                          const PlannerOptions& options = {});

/// Throws std::invalid_argument, saying why, unless `name` can plan among
/// moving obstacles: "spike" (DynamicSpike, SPIKE's own re-planning) or an
/// algorithm that follows the grid's changes and whose paths are valid by
/// the line-of-sight rule (astar, jps). "ompl" is refused: its paths are
/// not valid by the rule, so a plan blocked later would go unnoticed.
void check_dynamic_planner(const std::string& name);

/// The names check_dynamic_planner accepts, in the registry's order.
std::vector<std::string> dynamic_planner_names();

/// `name` among moving obstacles over `static_grid` (copied): "spike" is
/// DynamicSpike; another accepted algorithm plans on the obstacle layer's
/// grid (static cells plus footprints) at every query. `inflation` (cells)
/// and `horizon` (s) are the ObstacleLayer's.
std::unique_ptr<DynamicPlanner> make_dynamic_planner(const std::string& name, const OccupancyGrid& static_grid,
                                                     double inflation, double horizon,
                                                     const PlannerOptions& options = {});

}  // namespace mrt::spike
