// Roby in one process, without ROS: the mrt_sim world, the DGPS localizer,
// the planner stand-in, the SCARE sequencer, the sonar adapter and Mr. BRIAN
// in closed loop, in simulated time. Used by `roby_run`, the gtests and the
// benchmark; the ROS bringup wires the same pieces as nodes. ROS-free.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mrt_roby/route_planner.h"
#include "mrt_scare/sequencer.h"

namespace mrt::roby {

using common::Pose2D;
using scare::SequencerEvent;

struct RobyLoopOptions {
  std::string world;        // mrt_sim world file
  std::string map;          // road map of the planner stand-in
  std::string tasks;        // sequencer task file
  std::string brian;        // rule base directory
  std::string robot = "robot1";
  double duration = 300.0;  // s of simulated time at most
  double brian_rate = 10.0; // Hz
  bool use_ground_truth = false;  // pose from the truth instead of DGPS + encoders
};

struct RobyLoopResult {
  std::size_t route_points = 0;   // path points of the first plan
  std::size_t reached = 0;
  std::size_t failed = 0;
  std::size_t replans = 0;
  bool completed = false;
  double time = 0.0;               // s until the route was completed (or the end)
  double min_clearance = 1e9;      // m, footprint to nearest obstacle, ground truth
  std::string nearest;             // what it was
  double max_pose_error = 0.0;     // m, localizer vs truth
  std::vector<SequencerEvent> events;
};

/// Computes the clearance of a robot footprint (centre, radius) to every
/// wall, post and mover of a world; `what` names the nearest.
double world_clearance(const void* world, double x, double y, double radius, std::string* what);

RobyLoopResult run_roby_loop(const RobyLoopOptions& o,
                             const std::function<void(double, const RobyLoopResult&)>& tick = {});

}  // namespace mrt::roby
