// What the team session gives each robot's MAP and SCARE: the ideal camera
// percepts of mrt_sim (balls and robots only, seeded noise) as MAP percept
// objects, the anchors of a MAP world model as the Player's AnchorView, and
// SCARE's crisp world data from them. ROS-free.
#pragma once

#include <random>
#include <vector>

#include "mrt_map/world_model.h"
#include "mrt_robocup/situation.h"
#include "mrt_scare/fuzzy_model.h"
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

/// SCARE's world data (m, [0, 1]) for the activity file
/// (config/scare/robocup_team.yaml): BallX, BallY, BallSeen, BallOwned
/// (`team_owns`: a teammate's kicker holds it), ShotClear (the ball more
/// than shot_range from the aim; or, beyond the shooting spot, no opponent
/// within shot_clearance of the line from the ball to the spot; or else
/// plan_shot's shot from the ball clear: situation.h),
/// Threat (the ball in the own third with an opponent within 1.5 m of it),
/// ReceiveX/ReceiveY (the receiver's spot, as situation.cpp's target).
scare::CrispMap team_crisp(const std::vector<AnchorView>& anchors, bool team_owns, const SituationOptions& o);

}  // namespace mrt::robocup
