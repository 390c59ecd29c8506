// SCARE's world data of the RoboCup team from a robot's world-model
// anchors: the one computation the in-process team session
// (team_session.h) and the bringup's scare_world_node share. ROS-free and
// free of the simulator.
#pragma once

#include <vector>

#include "mrt_robocup/situation.h"
#include "mrt_scare/fuzzy_model.h"

namespace mrt::robocup {

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
