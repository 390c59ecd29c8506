// The Milan RoboCup team in one process, without ROS (like mrt_followme's
// FollowMeSession): the Match (match.h) on mrt_sim's simulator with N robots; per robot and per cycle
// the ideal camera percepts (seeded noise) -> its own MAP WorldModel
// (fusing its teammates' anchors) -> its SCARE Coordinator (exchanging
// messages with the others') -> its Player (Mr. BRIAN) -> wheel set-points,
// kicks and ball handler. Poses are the ground truth (MUREA is left out of
// this loop; the bringup runs it). Used by robocup_run, the gtests and
// robocup_bench. ROS-free.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "mrt_robocup/player.h"
#include "mrt_robocup/match.h"

namespace mrt::robocup {

struct TeamRobot {
  std::string name, base;           // base: an mrt_sim preset (ianus3, triskar, omni4)
  Pose2D pose;                      // kick-off pose
  Point2D home;                     // Positioning spot
};

/// config/team.yaml; throws mrt::common::ParseError naming file:line:column.
std::vector<TeamRobot> load_team(const std::string& path);

struct TeamSessionOptions {
  std::string world;                // mrt_sim world (the field; its robots are replaced)
  std::string match;                // match file (doc/match.md)
  std::string team;                 // config/team.yaml
  std::string rule_bases;           // config/brian (differential/, omni/ below)
  std::string activities;           // config/scare/robocup_team.yaml
  std::string map_model;            // config/map/robocup_team.yaml
  std::uint64_t seed = 1;
  double duration = 120.0;          // s simulated
  double rate = 10.0;               // Hz: MAP, SCARE and the players
  double dt = 0.005;                // s, simulator step
  double vision_range = 12.0;       // m, ideal percepts
  double distance_noise = 0.02;     // fraction of the distance, 1 sigma
  double bearing_noise = 0.01;      // rad, 1 sigma
  bool replace_opponents = false;   // use `opponents` instead of the match file's
  std::vector<OpponentConfig> opponents;
  bool stop_at_first_goal = false;
};

struct TeamStats {
  std::array<int, 2> score{0, 0};
  double first_goal_time = -1.0;    // s, our first goal
  double possession = 0.0;          // fraction of play time team 0 touched the ball last
  int kicks = 0;
  int passes = 0;                   // a kick followed by a teammate's possession, no opponent touch
  int role_changes = 0;             // job changes of all robots (after the first job)
  double sim_time = 0.0, play_time = 0.0;
  double role_changes_per_minute() const { return play_time > 0 ? role_changes * 60.0 / play_time : 0.0; }
};

class TeamSession {
 public:
  explicit TeamSession(const TeamSessionOptions& o);
  ~TeamSession();
  TeamSession(const TeamSession&) = delete;
  TeamSession& operator=(const TeamSession&) = delete;

  /// One control cycle (1 / rate s of simulated time); false when the time
  /// is up (or the first goal, with stop_at_first_goal).
  bool cycle();
  void run();

  /// Operator's referee command (the match's referee box), applied at once:
  /// a stop zeroes every robot's command in the same simulator step.
  void referee(Referee command);
  /// Takes robot `name` out: it leaves (its coordinator says so) and is
  /// carried off the field.
  void remove_robot(const std::string& name);

  double time() const;
  const TeamStats& stats() const;
  std::size_t robots() const;
  const std::string& robot_name(std::size_t i) const;
  /// The job/role robot i executes ("" none) and whether it is in the game.
  const std::string& job(std::size_t i) const;
  bool active(std::size_t i) const;
  /// The twist last commanded to robot i and its true speed (m/s).
  common::Twist2D command(std::size_t i) const;
  double true_speed(std::size_t i) const;
  /// Ground truth: robot i's pose, the ball, the robot holding it (-1 none).
  Pose2D pose(std::size_t i) const;
  Point2D ball() const;
  int holder() const;
  /// Ground truth: the opponents' positions (the match's movers).
  std::vector<Point2D> opponents() const;
  /// Robot i's last player output (debug).
  const PlayerOutput& output(std::size_t i) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mrt::robocup
