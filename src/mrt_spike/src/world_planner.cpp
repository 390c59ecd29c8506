#include "mrt_spike/world_planner.h"

#include <cmath>

#include "mrt_spike/planner_factory.h"

namespace mrt::spike {

WorldPlanner::WorldPlanner(const WorldGrid& map, const WorldPlannerOptions& options)
    : map_(map), options_(options), planner_(make(options)) {}

std::unique_ptr<DynamicPlanner> WorldPlanner::make(const WorldPlannerOptions& options) const {
  const double inflation = (options.robot_radius + options.safety_distance) / map_.frame.resolution;
  PlannerOptions po;
  po.spike = options.spike;
  return make_dynamic_planner(options.planner, inflate(map_.grid, inflation), inflation, options.horizon, po);
}

bool WorldPlanner::reconfigure(const WorldPlannerOptions& options) {
  const WorldPlannerOptions& o = options_;
  const bool rebuild = options.robot_radius != o.robot_radius || options.safety_distance != o.safety_distance ||
                       options.horizon != o.horizon || options.planner != o.planner;
  if (rebuild) {
    std::unique_ptr<DynamicPlanner> fresh = make(options);  // may throw: nothing changed yet
    for (const auto& [id, m] : moving_) fresh->obstacles().set(id, m);
    planner_ = std::move(fresh);
  }
  options_ = options;
  return rebuild;
}

const Quadtree* WorldPlanner::quadtree() const {
  const auto* spike = dynamic_cast<const DynamicSpike*>(planner_.get());
  return spike ? &spike->static_planner().quadtree() : nullptr;
}

WorldPlan WorldPlanner::plan(double x0, double y0, double x1, double y1, double tolerance) {
  WorldPlan out = plan_exact(x0, y0, x1, y1);
  if (out.solved || !(tolerance > 0.0)) return out;
  const Cell s = map_.cell_at(x0, y0);
  if (with_obstacles().blocked(s.x, s.y)) return out;  // the start's problem: no relaxing
  const Cell n = map_.cell_at(out.nearest_x, out.nearest_y);
  if (with_obstacles().blocked(n.x, n.y)) return out;  // nothing reachable at all
  if (std::hypot(out.nearest_x - x1, out.nearest_y - y1) > tolerance) return out;
  WorldPlan relaxed = plan_exact(x0, y0, out.nearest_x, out.nearest_y);
  if (!relaxed.solved) return out;
  relaxed.goal_relaxed = true;
  relaxed.reason = out.reason;
  return relaxed;
}

WorldPlan WorldPlanner::plan_exact(double x0, double y0, double x1, double y1) {
  WorldPlan out;
  const Cell s = map_.cell_at(x0, y0), g = map_.cell_at(x1, y1);
  const PlanResult r = planner_->plan(s, g);
  const GridFrame& f = map_.frame;
  if (!r.solved) {
    out.reason = r.reason;
    out.nearest_x = f.origin_x + f.resolution * r.nearest.x;
    out.nearest_y = f.origin_y + f.resolution * r.nearest.y;
    return out;
  }
  out.solved = true;
  out.waypoints = r.path;
  out.length = r.length * f.resolution;
  out.poses = to_poses(r.path, options_.spacing, f);
  if (out.poses.size() == 1 && r.path.size() == 1) out.poses.front().yaw = 0.0;
  return out;
}

void WorldPlanner::set_obstacle(int id, double x, double y, double r, double vx, double vy) {
  const GridFrame& f = map_.frame;
  const MovingObstacle m{(x - f.origin_x) / f.resolution, (y - f.origin_y) / f.resolution, r / f.resolution,
                         vx / f.resolution, vy / f.resolution};
  planner_->obstacles().set(id, m);
  moving_[id] = m;
}

void WorldPlanner::remove_obstacle(int id) {
  planner_->obstacles().remove(id);
  moving_.erase(id);
}

bool WorldPlanner::still_valid(const WorldPlan& p) const { return p.solved && planner_->still_valid(p.waypoints); }

}  // namespace mrt::spike
