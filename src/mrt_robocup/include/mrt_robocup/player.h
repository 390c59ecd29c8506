// One robot of the Milan RoboCup team (manual §2.3.3, ch. 12), one control
// cycle at a time: its pose (MUREA), MAP's anchors, SCARE's coordination,
// the referee and the ball possession -> crisp data (situation.h) -> Mr.
// BRIAN (in-process) -> a body twist for the AIRBoard and a kick with its
// strength. The referee's stop (or anything but play) zeroes the command
// in the same cycle, whatever the rules say. ROS-free.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mrt_common/brian_mapping.h"
#include "mrt_brian/brian.h"
#include "mrt_robocup/situation.h"

namespace mrt::robocup {

/// The referee commands (numbers of mrt_msgs/RefereeCommand).
enum class Referee { kStart = 0, kStop = 1, kKickOff = 2, kGoal = 3, kThrowIn = 4, kGoalKick = 5,
                     kCorner = 6, kDropBall = 7, kNone = 255 };

struct PlayerOptions {
  std::string rule_base;          // BrianConfigs.ini (or directory) of the robot's kinematics
  /// "differential" (Speed, Jog) or "omni" (SpeedModule, SpeedAngle, Rotation).
  std::string kinematics = "differential";
  SituationOptions situation;
  double max_speed = 1.2;         // m/s, the twist is clamped to it ...
  double max_omega = 3.0;         // rad/s, ... and to this
  double carry_max_speed = 1.2;   // m/s, while owning the ball (the ball handler loses it faster)
  double carry_max_omega = 1.8;   // rad/s, idem
  double dribble_distance = 0.6;  // m beyond the body: the ball handler is switched on
  std::string kick_name = "Kick"; // Brian's kick output (strength in [0, 1])
  double kick_cooldown = 0.5;     // s between two kicks
  /// rad/s: no kick while the measured turn rate is higher. The pose the
  /// shot is aimed with is 0.1-0.25 s old when the kicker fires (MUREA,
  /// the 10 Hz cycle, the AIRBoard): turning at 0.87 rad/s a kick aimed
  /// within 1 degree left 3 degrees off and hit the post (see
  /// doc/shooting.md); at 0.1 rad/s the error stays under 1.5 degrees.
  double kick_max_omega = 0.1;
  bool play_without_referee = false;  // true: play before any referee command
  /// s the last job is kept while SCARE gives none (a robot waiting for a
  /// teammate to release its new slot keeps doing what it did).
  double job_hold = 1.0;
};

struct PlayerInput {
  double time = 0.0;              // s
  bool pose_valid = false;
  Pose2D pose;                    // world frame (MUREA's estimate)
  std::vector<AnchorView> anchors;  // MAP's world model
  Parameters coordination;        // SCARE's crisp output
  Referee referee = Referee::kNone; // the last referee command
  bool possession_known = false;  // the kicker's ball sensor
  bool possession = false;
  /// rad/s, the measured turn rate (odometry); NaN: unknown (no gate).
  double omega = std::numeric_limits<double>::quiet_NaN();
};

struct PlayerOutput {
  common::Twist2D twist;          // body twist, SI (zero unless playing)
  bool kick = false;
  bool kick_held = false;         // the rules kicked but the robot turned too fast
  double kick_strength = 0.0;     // [0, 1]
  bool dribble = false;           // the ball handler on
  bool halted = true;             // the referee does not let it play (or no pose)
  std::string job;                // the coordination job/role
  brian::CrispDataList crisp;     // what Brian was given
  brian::CommandList commands;    // what Brian proposed
  /// The active behaviours with their weight, "GoToBall 1.00 AvoidObstacle 0.40" (debug).
  std::string behaviors;
  Situation situation;
};

class Player {
 public:
  /// Throws mrt::common::ParseError (file:line) for a bad rule base and
  /// std::invalid_argument for bad options.
  explicit Player(PlayerOptions o);
  ~Player();

  PlayerOutput cycle(const PlayerInput& in);
  const PlayerOptions& options() const { return o_; }
  /// Whether the referee lets the robot move (start given, no stop since).
  static bool playing(Referee r, bool play_without_referee);

 private:
  PlayerOptions o_;
  std::unique_ptr<brian::Brian> brian_;
  common::BrianMapping mapping_;
  SituationAssessor assessor_;
  double last_kick_ = -1e9;
  Parameters held_;          // the last coordination with a job
  double held_since_ = -1e9;
};

/// "differential"/"omni" -> the mapping of that kinematics' rule base;
/// throws std::invalid_argument otherwise.
common::BrianMappingParams mapping_for(const std::string& kinematics);

}  // namespace mrt::robocup
