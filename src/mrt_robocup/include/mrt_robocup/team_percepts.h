// What the team session gives each robot's MAP: the ideal camera percepts
// of mrt_sim (balls and robots only, seeded noise) as MAP percept objects,
// and the anchors of a MAP world model as the Player's AnchorView (SCARE's
// crisp world data from them: team_crisp.h, free of the simulator).
// ROS-free.
#pragma once

#include <random>
#include <vector>

#include "mrt_map/world_model.h"
#include "mrt_robocup/situation.h"
#include "mrt_sim/sensors.h"

namespace mrt::robocup {

/// The ball and the robots robot at `pose` sees within `range` (mrt_sim's
/// ideal vision: occlusion, no misses), with Gaussian noise on distance
/// (`distance_noise` x distance) and bearing (rad); attributes distance,
/// bearing (with their sigmas as variability) and color.
std::vector<map::PerceptObject> team_percepts(const sim::World& w, const std::vector<sim::OtherRobot>& others,
                                              const Pose2D& pose, double range, double distance_noise,
                                              double bearing_noise, std::mt19937_64& rng);

/// The confirmed and coasting anchors of `wm` at `now`, by class name.
std::vector<AnchorView> anchor_views(const map::WorldModel& wm, double now);

}  // namespace mrt::robocup
