// One Mr. BRIAN cycle's crisp data for the Roby rule base (config/brian),
// in the rule base's units (the Parser and Messenger of manual §10.3.10 /
// §10.4.10). Each datum has exactly one owner, one function here:
//
//   goal_crisp_data      Status, HaveGoal, GoalDistance, GoalBearing  (the sequencer)
//   remote_crisp_data    RemoteSpeed, RemoteTurn                      (the remote controller)
//   sonar_crisp_data     Obstacle<sector>..., FreeSide                (the sonar belt)
//   feedback_crisp_data  LastSpeed, LastJog                           (the previous commands)
//
// roby_scare_node publishes the first two, sonar_crisp_node appends the last
// two to them; the closed loop calls build_crisp(). ROS-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mrt_brian/types.h"
#include "mrt_scare/sequencer.h"

namespace mrt::roby {

using brian::CrispDataList;
using brian::CrispDatum;
using scare::GoalCrisp;
using scare::Mode;

/// The remote controller (tele-operation), SI units.
struct RemoteCommand {
  double speed = 0.0;     // m/s forward
  double turn = 0.0;      // rad/s counter-clockwise
};

/// Status (0 MANUAL / 1 AUTO), HaveGoal (0/1) and, with a goal,
/// GoalDistance (cm) and GoalBearing (deg, (-180, 180]).
void goal_crisp_data(Mode mode, const std::optional<GoalCrisp>& goal, CrispDataList& out);

/// RemoteSpeed (cm/s) and RemoteTurn (deg/s); no command (none, or too old)
/// reads as the remote stopped.
void remote_crisp_data(const std::optional<RemoteCommand>& remote, CrispDataList& out);

/// Each sector (cm) and FreeSide = min(FrontLeft, Left) - min(FrontRight,
/// Right) (cm, positive when the left is freer; only when both sides exist).
void sonar_crisp_data(const std::vector<std::string>& sector_names, const std::vector<double>& sector_distances,
                      CrispDataList& out);

/// LastSpeed (cm/s) and LastJog (deg/s): the previous cycle's commands.
void feedback_crisp_data(double last_speed_cm, double last_jog_deg, CrispDataList& out);

struct CrispInputs {
  std::optional<GoalCrisp> goal;            // none: HaveGoal 0
  Mode mode = Mode::kAuto;
  std::vector<std::string> sector_names;    // e.g. ObstacleFront
  std::vector<double> sector_distances;     // m
  std::optional<RemoteCommand> remote;      // none: remote stopped
  double last_speed_cm = 0.0;               // previous cycle's Speed, cm/s
  double last_jog_deg = 0.0;                // previous cycle's Jog, deg/s
};

/// The whole cycle: goal, sonar, remote and feedback data, in that order.
CrispDataList build_crisp(const CrispInputs& in);

}  // namespace mrt::roby
