// Time to reach from a path planner (SPIKE's `make_plan`), ROS-free: the
// coordinator asks for the time to each role's target every cycle, far more
// often than a planner can answer, so the answers are cached as a *detour
// factor* per target (path length / straight-line distance when the path
// was planned, >= 1) and the time is straight-line distance x detour /
// max_speed. A target is keyed by its position rounded to `resolution`; a
// target never planned, or whose answer is older than `max_age`, is queued
// for the planner (the node's planning thread asks next_query()), and until
// then the last factor (or 1: the straight line) is used. A target the
// planner cannot reach takes an infinite time (the role's fit is 0).
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <utility>

#include "mrt_scare/coordinator.h"

namespace mrt::scare {

struct PlannerCostOptions {
  double resolution = 0.5;  // m: targets closer than this share a plan
  double max_age = 2.0;     // s: a plan older than this is asked for again
};

class PlannerCost : public CostModel {
 public:
  explicit PlannerCost(PlannerCostOptions o = {}) : options_(o) {}

  /// The time stamp of the requests that follow (the node sets it every
  /// cycle, before the coordinator asks for its times).
  void set_time(double now);

  /// Straight-line distance x the target's detour factor / max_speed
  /// (infinite when the planner found no path); records the request.
  double time(const RobotSpec& robot, const Pose2D& from, const Point2D& to) const override;

  /// What the planner should compute next at `now`: the requested target
  /// never planned, else the one with the oldest answer past max_age, with
  /// the pose it was last requested from. Empty when every requested target
  /// is fresh. Targets not requested for max_age are forgotten (the ball
  /// moved on).
  std::optional<std::pair<Pose2D, Point2D>> next_query(double now) const;

  /// The planner's answer for (from, to): the path length in m, or empty
  /// when there is no path. Stored for to's key at time `now`.
  void record(const Pose2D& from, const Point2D& to, std::optional<double> length, double now);

  /// The detour factor held for a target (1 when none; infinity: no path).
  double detour(const Point2D& to) const;

 private:
  using Key = std::pair<long, long>;
  struct Entry {
    Pose2D from;              // last request's pose
    Point2D to;
    double factor = 1.0;      // path / straight line, >= 1; inf: unreachable
    double planned = -1.0;    // time of the answer; < 0: never planned
    double requested = 0.0;   // time of the last request
  };
  Key key(const Point2D& p) const;
  PlannerCostOptions options_;
  mutable std::mutex mutex_;
  mutable std::map<Key, Entry> entries_;
  double now_ = 0.0;
};

}  // namespace mrt::scare
