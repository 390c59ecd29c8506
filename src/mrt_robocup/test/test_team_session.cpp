// The team session on the match (README "Team session"): the fast
// versions of the team's rostests. Kick-off against a goalkeeper and a
// static defender: a goal within 120 simulated s in at least 4 of 5 seeds;
// the referee's stop halts every robot at once; a robot taken out has its
// job re-assigned within one coordination cycle (0.1 s) and play goes on.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mrt_robocup/match.h"
#include "mrt_robocup/session_files.h"

namespace mrt::robocup {
namespace {

TeamSessionOptions options(std::uint64_t seed) {
  TeamSessionOptions o = default_session_options(MRT_ROBOCUP_ROOT, MRT_WORLDS_DIR);
  o.seed = seed;
  o.duration = 120.0;
  o.replace_opponents = true;
  OpponentConfig keeper;
  keeper.name = "opp_keeper";
  keeper.role = "goalkeeper";
  keeper.home = {8.4, 0.0};
  keeper.speed = 1.5;
  OpponentConfig defender;
  defender.name = "opp_back";
  defender.role = "static";
  defender.home = {5.0, 0.0};
  o.opponents = {keeper, defender};
  return o;
}

int find_job(const TeamSession& s, const std::string& job) {
  for (std::size_t i = 0; i < s.robots(); ++i)
    if (s.active(i) && s.job(i) == job) return static_cast<int>(i);
  return -1;
}

// Issue 21: "from kick-off, against a static defender and a goalkeeper, the
// team scores within 120 simulated seconds in at least 4 of 5 seeded runs".
// Measured 5 of 5, the first goal 12.8-13.0 s after the start (README
// "Shooting"); each run stops at the first goal.
TEST(TeamSession, ScoresFromKickOffInFourOfFiveSeeds) {
  int scored = 0;
  std::string report;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    TeamSessionOptions o = options(seed);
    o.stop_at_first_goal = true;
    TeamSession s(o);
    s.run();
    const TeamStats& st = s.stats();
    report += "seed " + std::to_string(seed) + ": " + std::to_string(st.score[0]) + "-" +
              std::to_string(st.score[1]) + " first goal " + std::to_string(st.first_goal_time) + " s, kicks " +
              std::to_string(st.kicks) + "\n";
    if (st.first_goal_time >= 0.0 && st.first_goal_time <= 120.0) ++scored;
  }
  EXPECT_GE(scored, 4) << report;
  std::printf("%s", report.c_str());
}

// The stop zeroes every command in the same simulator step (the session
// does what player_node does in its referee callback); 0.5 s later every
// robot still commands zero and stands still.
TEST(TeamSession, RefereeStopHaltsEveryRobot) {
  TeamSession s(options(3));
  while (s.time() < 8.0) s.cycle();
  double moving = 0.0;
  for (std::size_t i = 0; i < s.robots(); ++i) moving += s.true_speed(i);
  ASSERT_GT(moving, 0.1);  // the team was playing
  s.referee(Referee::kStop);
  for (std::size_t i = 0; i < s.robots(); ++i) {
    const common::Twist2D c = s.command(i);
    EXPECT_EQ(c.vx, 0.0);
    EXPECT_EQ(c.vy, 0.0);
    EXPECT_EQ(c.omega, 0.0);
  }
  const double t0 = s.time();
  while (s.time() < t0 + 0.5 - 1e-9) s.cycle();
  for (std::size_t i = 0; i < s.robots(); ++i) {
    EXPECT_EQ(s.command(i).vx, 0.0) << s.robot_name(i);
    EXPECT_EQ(s.command(i).omega, 0.0) << s.robot_name(i);
    EXPECT_NEAR(s.true_speed(i), 0.0, 1e-9) << s.robot_name(i);
  }
}

// The robot recovering the ball leaves at a stoppage (mrt_scare drops a
// `leaving` teammate at once): in the next cycle (0.1 s) another robot has
// RecoverWanderingBall (priority 2 in config/scare/robocup_team.yaml);
// after the start the team plays on (the ball is moved by 0.5 m or more
// within 30 s).
TEST(TeamSession, RemovedRobotsJobIsReassignedWithinOneCycle) {
  TeamSession s(options(2));
  while (s.time() < 3.0 - 1e-9) s.cycle();
  s.referee(Referee::kStop);
  while (s.time() < 4.0 - 1e-9) s.cycle();
  const int recovering = find_job(s, "RecoverWanderingBall");
  ASSERT_GE(recovering, 0);
  const std::string name = s.robot_name(static_cast<std::size_t>(recovering));
  s.remove_robot(name);
  s.cycle();
  const int next = find_job(s, "RecoverWanderingBall");
  ASSERT_GE(next, 0) << "nobody recovers the ball one cycle after " << name << " left";
  EXPECT_NE(s.robot_name(static_cast<std::size_t>(next)), name);
  EXPECT_FALSE(s.active(static_cast<std::size_t>(recovering)));
  const Point2D b0 = s.ball();
  s.referee(Referee::kStart);
  double moved = 0.0;
  while (s.time() < 34.0) {
    s.cycle();
    moved = std::max(moved, std::hypot(s.ball().x - b0.x, s.ball().y - b0.y));
  }
  EXPECT_GT(moved, 0.5);
}

TEST(TeamConfig, ErrorsNameFileLineColumn) {
  try {
    load_team(std::string(MRT_ROBOCUP_TEST_DATA) + "/bad_team.yaml");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    // Line 4, column 52: the unknown key 'speed' of robot2.
    EXPECT_NE(std::string(e.what()).find("bad_team.yaml:4:52"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mrt::robocup
