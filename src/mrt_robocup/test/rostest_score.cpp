// rostest (issue 21): from kick-off, against a static defender and a
// goalkeeper (test/data/keeper_static_defender.yaml), the team scores within
// 120 simulated seconds. score.test runs the whole team (robocup.launch,
// ideal vision, the simulator's noise seeded with the test's `seed`
// argument); rostests.cmake registers it for five seeds, and the issue's
// criterion is at least 4 of those 5 runs (README "Tests").
// The referee announces a goal for cyan with score[0] = 1 (mrt_sim README
// "Referee box"); the time is counted from the stamp of cyan's kick-off
// (clock 0 when this node subscribed after it).
#include <gtest/gtest.h>

#include "mrt_common_ros/rostest_helpers.h"
#include "rostest_team.h"

using mrt::robocup::test::TeamWatch;
using mrt::ros_common::wait_for;

namespace {

constexpr double kLimit = 120.0;  // simulated seconds from the kick-off

TEST(RoboCupMatch, TeamScoresFromKickOffWithin120SimulatedSeconds) {
  TeamWatch team({"robot1", "robot2", "robot3", "robot4"});
  // The opening kick-off (cyan's, 0-0) is stamped at clock 0, before the
  // simulator's first /clock: this node may subscribe after it. Then the
  // first command it hears is a later one, and the kick-off was at 0 (seen:
  // cyan scored at 60.6 s, and the magenta kick-off after it was taken
  // for the opening one).
  ASSERT_TRUE(wait_for([&] { return !team.referee.empty(); }, 90.0)) << "no referee command";
  const mrt_msgs::RefereeCommand& first = team.referee.front();
  const bool opening = first.name == "kick_off";
  if (opening) {
    EXPECT_EQ(first.team, "cyan");
  }
  const double t0 = opening ? first.header.stamp.toSec() : 0.0;
  // Wall time: the team may run slower than real time on a loaded machine.
  const bool scored = wait_for([&] { return team.goals() >= 1 || ros::Time::now().toSec() > t0 + kLimit; }, 600.0);
  ASSERT_TRUE(scored) << "the simulation stopped before " << kLimit << " s of play";
  const mrt_msgs::RefereeCommand* goal = team.command("goal", t0);
  ASSERT_NE(goal, nullptr) << "no goal in " << ros::Time::now().toSec() - t0 << " s";
  EXPECT_EQ(goal->team, "cyan");
  EXPECT_LE(goal->header.stamp.toSec() - t0, kLimit);
  int seed = -1;
  ros::param::get("~seed", seed);
  ROS_INFO("seed %d: goal for %s %.1f s after the kick-off", seed, goal->team.c_str(),
           goal->header.stamp.toSec() - t0);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rostest_robocup_score");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
