// Simulation of a RoboCup Middle Size League match on top of mrt_sim's
// Simulator (ROS-free): the robots' pneumatic kickers and ball handling,
// scripted opponents (goalkeeper, defenders, attackers) and an automatic
// referee box issuing start, stop, kick-off, goal, throw-in, goal kick,
// corner and drop ball. The field is taken from the world's two goals.
// The match is a StepHook of the simulator (mrt_sim/step_hook.h): it steers
// the opponents before every physics step and kicks, handles the ball and
// judges after it. Format and rules: mrt_robocup/doc/match.md.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mrt_sim/simulator.h"
#include "mrt_sim/step_hook.h"
#include "mrt_sim/world.h"

namespace mrt::robocup {

/// The pneumatic kicker and the ball handler of the world's robots.
struct KickerConfig {
  double max_speed = 8.0;          // m/s, ball speed of a kick at strength 1
  double reach = 0.05;             // m beyond the body where the ball can be kicked/held
  double half_angle = 0.4;         // rad, the ball's bearing window around the heading
  double dribble_max_speed = 1.5;  // m/s, faster than this the ball is lost
  double dribble_max_omega = 2.0;  // rad/s, turning faster than this the ball is lost
  /// s a set_dribbler(on) holds unless repeated (the handler's watchdog: a
  /// robot whose software died lets the ball go); 0: until switched off.
  /// Not in the match file: the match plugin's ~<name>/dribble_timeout.
  double dribble_timeout = 0.0;
};

/// A scripted opponent, simulated as a mover (a cylinder without heading).
struct OpponentConfig {
  std::string name;
  std::string role = "defender";  // goalkeeper, defender, attacker, static
  common::Point2D home;           // start and kick-off position
  double radius = 0.25;           // m
  double speed = 1.0;             // m/s
};

struct RefereeConfig {
  double restart_delay = 2.0;    // s between a stoppage, the placement and the restart
  double stuck_timeout = 20.0;   // s of play with the ball within 0.2 m: drop ball (0 = never)
  int kickoff_team = 0;          // team taking the first kick-off
  double restart_wait = 5.0;     // s after the start of team 0's restart during which the
                                 // opponents do not go for the ball (unless it moved 0.3 m)
  bool auto_start = true;        // kick-off and start at time 0 without an operator
};

struct MatchConfig {
  std::array<std::string, 2> teams{"cyan", "magenta"};  // 0: the world's robots, 1: the opponents
  std::string own_goal = "blue_goal";       // the goal team 0 defends (team 1 defends the other)
  double field_half_width = 6.0;            // m, touch lines at y = +-this
  double ball_robot_restitution = 0.3;      // ball bouncing off robots and opponents
  KickerConfig kicker;
  double opponent_kick_speed = 5.0;         // m/s, opponents' kicks
  double keeper_distance = 0.6;             // m from the goal-mouth centre towards the ball
  double defender_distance = 2.0;           // m from the ball towards the own goal
  std::vector<OpponentConfig> opponents;
  bool clear_movers = true;                 // remove the world's other movers
  RefereeConfig referee;
};

/// Loads a match file (format: mrt_robocup/doc/match.md, "Match file");
/// throws mrt::common::ParseError naming file:line:column.
MatchConfig load_match_config(const std::string& path);
MatchConfig parse_match_config(const std::string& yaml_text, const std::string& file);

/// The referee commands (the same numbers as mrt_msgs/RefereeCommand).
enum class RefereeCommand { kStart = 0, kStop = 1, kKickOff = 2, kGoal = 3, kThrowIn = 4,
                            kGoalKick = 5, kCorner = 6, kDropBall = 7 };
const char* to_string(RefereeCommand c);
/// "start" -> kStart ...; throws std::invalid_argument for an unknown name.
RefereeCommand referee_command_from_string(const std::string& name);

struct RefereeEvent {
  RefereeCommand command = RefereeCommand::kStop;
  int team = -1;          // the team the command is for, -1 for both
  common::Point2D position;  // ball placement (world frame), where it applies
  std::array<int, 2> score{0, 0};
  double time = 0.0;      // s, simulated
  std::string reason;
};

/// Prepares `world` for a match: removes its movers (if clear_movers),
/// adds the opponents as movers of class Robot in team 1's colour, enables
/// the ball and sets its restitution against robots. Throws
/// std::invalid_argument if the world lacks the two goals.
void setup_match_world(const MatchConfig& cfg, sim::World& world);

class Match : public sim::StepHook {
 public:
  enum class State { kStopped, kPlaying };

  /// `sim` was built on a world prepared by setup_match_world; it must
  /// outlive the match. The match attaches itself to `sim`
  /// (Simulator::add_hook) and detaches in its destructor, so every
  /// sim.step() from now on is a match step.
  Match(MatchConfig cfg, sim::Simulator& sim);
  ~Match() override;
  Match(const Match&) = delete;
  Match& operator=(const Match&) = delete;

  /// Fires robot `robot`'s kicker during the next step at `strength`
  /// (clamped to [0, 1]): if the ball is then in reach it leaves at
  /// strength * max_speed along the robot's heading.
  void kick(std::size_t robot, double strength);
  /// Switches the ball handler of robot `robot` on or off (on: for
  /// kicker.dribble_timeout when that is > 0).
  void set_dribbler(std::size_t robot, bool on);
  /// The ball is touching the front of robot `robot` (kick/hold window).
  bool in_reach(std::size_t robot) const;

  /// An operator command (start, stop, drop ball, kick-off ...): applied
  /// at once and reported by the next take_events() (or step()).
  void command(RefereeCommand c, int team = -1);

  /// The hook (Simulator::step() calls them): before the physics step the
  /// opponents are steered; after it come the robots' kicks, ball
  /// handling, the opponents' kicks, the last touch and the referee.
  void before_step(sim::Simulator& sim) override;
  void after_step(sim::Simulator& sim) override;

  /// The referee's commands issued since the last call, oldest first.
  std::vector<RefereeEvent> take_events();
  /// One step: sim.step() (which runs this match's hook), then
  /// take_events().
  std::vector<RefereeEvent> step();

  State state() const { return state_; }
  const std::array<int, 2>& score() const { return score_; }
  int holder() const { return holder_; }             // robot holding the ball, -1 if none
  int last_touch() const { return last_touch_; }     // team that touched the ball last, -1 if none
  int kicks() const { return kicks_; }               // kicks that reached the ball
  int dribble_timeouts() const { return dribble_timeouts_; }  // handlers off by the watchdog
  const MatchConfig& config() const { return cfg_; }
  /// Mouth centre of the goal team `team` defends.
  const sim::Goal& goal_of(int team) const { return team == 0 ? own_goal_ : other_goal_; }
  sim::Simulator& simulator() { return sim_; }

 private:
  void steer_opponents();
  common::Point2D opponent_target(std::size_t k) const;
  bool opponents_wait() const;
  void robot_kicks();
  void ball_handling();
  void opponent_kicks();
  void track_touch();
  void referee();
  void emit(RefereeCommand c, int team, const common::Point2D& p, const std::string& reason);
  void place_ball(const common::Point2D& p);
  /// Where the referee puts the ball for a restart at p: p, or, when a
  /// robot or an opponent stands on it, the nearest point of the field
  /// clear of every body (the ball placed inside a body was pushed over
  /// the line again at once: throw-in after throw-in).
  common::Point2D free_spot(const common::Point2D& p) const;
  void stoppage(RefereeCommand restart, int team, const common::Point2D& p, const std::string& reason);

  MatchConfig cfg_;
  sim::Simulator& sim_;
  sim::Goal own_goal_, other_goal_;
  std::vector<std::size_t> opponent_movers_;   // index of each opponent in sim.movers()
  std::vector<double> pending_kick_;           // strength, < 0 none
  std::vector<bool> dribbler_;
  std::vector<double> dribbler_since_;  // sim time of each handler's last on
  int dribble_timeouts_ = 0;
  std::vector<double> opponent_cooldown_;      // s until an opponent may kick again
  State state_ = State::kStopped;
  std::array<int, 2> score_{0, 0};
  int holder_ = -1, last_touch_ = -1, kicks_ = 0;
  // A restart waiting for its time: the command, its team and placement.
  bool restart_pending_ = false, start_pending_ = false;
  RefereeCommand restart_ = RefereeCommand::kKickOff;
  int restart_team_ = -1;
  common::Point2D restart_position_;
  double restart_time_ = 0.0;
  int restart_for_ = -1;                       // team of the restart play started with
  common::Point2D restart_spot_;
  double play_since_ = 0.0;
  common::Point2D stuck_anchor_;
  double stuck_since_ = 0.0;
  std::vector<RefereeEvent> events_;
};

}  // namespace mrt::robocup
