// Assembles one Mr. BRIAN cycle's crisp data for the Roby rule base
// (config/roby/brian): the SCARE goal, the Auto/Manual flag, the sonar
// sectors, the remote controller and the previous cycle's commands (the
// Parser and Messenger of manual §10.3.10 / §10.4.10). ROS-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mrt_scare/sequencer.h"

namespace mrt::scare {

struct Crisp {
  std::string name;
  double value = 0.0;
  double reliability = 1.0;
};

/// The remote controller (tele-operation), SI units.
struct RemoteCommand {
  double speed = 0.0;     // m/s forward
  double turn = 0.0;      // rad/s counter-clockwise
};

struct CrispInputs {
  std::optional<GoalCrisp> goal;            // none: HaveGoal 0
  Mode mode = Mode::kAuto;
  std::vector<std::string> sector_names;    // e.g. ObstacleFront
  std::vector<double> sector_distances;     // m
  std::optional<RemoteCommand> remote;      // none: remote stopped
  double last_speed_cm = 0.0;               // previous cycle's Speed, cm/s
  double last_jog_deg = 0.0;                // previous cycle's Jog, deg/s
};

/// Crisp data in the rule base's units: GoalDistance (cm), GoalBearing
/// (deg, (-180, 180]), HaveGoal (0/1), Status (0 MANUAL / 1 AUTO), each
/// sector (cm), FreeSide = min(FrontLeft, Left) - min(FrontRight, Right)
/// (cm, positive when the left is freer), RemoteSpeed (cm/s), RemoteTurn
/// (deg/s), LastSpeed (cm/s), LastJog (deg/s).
std::vector<Crisp> build_crisp(const CrispInputs& in);

}  // namespace mrt::scare
