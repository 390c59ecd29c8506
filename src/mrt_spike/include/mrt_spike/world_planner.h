// SPIKE in world units (metres, radians): the map, robot radius, safety
// distance, output spacing, the algorithm (planner_factory.h) and the moving
// obstacles; what spike_node wraps.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mrt_spike/map_sources.h"
#include "mrt_spike/moving_obstacles.h"
#include "mrt_spike/obstacle_tracker.h"
#include "mrt_spike/poses.h"

namespace mrt::spike {

struct WorldPlannerOptions {
  double robot_radius = 0.3;     ///< m
  double safety_distance = 0.1;  ///< m, added to the robot radius
  double spacing = 0.25;         ///< m between output poses
  double horizon = 0.5;          ///< s of an obstacle's motion its footprint covers
  /// The algorithm (make_dynamic_planner): spike, astar or jps.
  std::string planner = "spike";
  SpikeOptions spike;
};

struct WorldPlan {
  bool solved = false;
  std::vector<Pose> poses;       ///< world frame, every `spacing`, last at the goal
  std::vector<Cell> waypoints;   ///< the path's corners, cells
  double length = 0.0;           ///< m
  std::string reason;            ///< when not solved
  double nearest_x = 0.0, nearest_y = 0.0;  ///< when not solved: nearest reachable point
  /// Solved to the nearest reachable point instead of the goal (within the
  /// tolerance of plan(); `reason` says why the goal itself was not).
  bool goal_relaxed = false;
};

class WorldPlanner : public ObstacleSink {
 public:
  /// `map` is the raw map (resolution = the finest); it is inflated by robot
  /// radius + safety distance here (preprocessing, once). An algorithm that
  /// cannot plan among moving obstacles: std::invalid_argument saying why.
  WorldPlanner(const WorldGrid& map, const WorldPlannerOptions& options);
  /// A plan from (x0, y0) to (x1, y1), m. With `tolerance` > 0 (m, as
  /// navfn's make_plan), a goal inside an obstacle or not reachable is
  /// replaced by the reachable free cell nearest to it when that cell's
  /// centre lies within `tolerance` of the goal (goal_relaxed); a start
  /// inside an obstacle is never relaxed.
  WorldPlan plan(double x0, double y0, double x1, double y1, double tolerance = 0.0);
  /// A moving obstacle at (x, y) m of radius r m moving at (vx, vy) m/s.
  void set_obstacle(int id, double x, double y, double r, double vx, double vy) override;
  void remove_obstacle(int id) override;
  /// True while the waypoints are still free of every obstacle.
  bool still_valid(const WorldPlan& p) const;
  const WorldGrid& map() const { return map_; }
  const OccupancyGrid& inflated() const { return planner_->obstacles().base(); }
  const OccupancyGrid& with_obstacles() const { return planner_->obstacles().grid(); }
  /// SPIKE's quadtree; nullptr for the algorithms without one.
  const Quadtree* quadtree() const;
  const DynamicPlanner& planner() const { return *planner_; }
  const WorldPlannerOptions& options() const { return options_; }
  /// New options at run time (spike_node's dynamic_reconfigure): a change of
  /// robot radius, safety distance, horizon or algorithm re-inflates the map
  /// and rebuilds the algorithm (preprocessing again, with the new `spike`
  /// options, which alone do not trigger it), keeping the moving obstacles;
  /// the spacing applies to the next plan.
  /// Returns true when it rebuilt. On an error (std::invalid_argument, as
  /// the constructor) the planner is unchanged.
  bool reconfigure(const WorldPlannerOptions& options);

 private:
  WorldPlan plan_exact(double x0, double y0, double x1, double y1);
  std::unique_ptr<DynamicPlanner> make(const WorldPlannerOptions& options) const;

  WorldGrid map_;
  WorldPlannerOptions options_;
  std::unique_ptr<DynamicPlanner> planner_;
  std::map<int, MovingObstacle> moving_;  ///< what set_obstacle wrote, cells (for a rebuild)
};

}  // namespace mrt::spike
