// rostest (issue 21): the referee's stop command halts every robot within
// 0.5 s. stop.test runs the whole team (robocup.launch: four robots, each
// with its chain, the referee box over DCDT); once play is on and the team
// moves, the test sends the operator's `stop` (/referee/operator); from the
// stamp of the referee's `stop` on /referee, every robot's true twist
// (mrt_sim's ground truth, 100 Hz) must fall below 0.02 m/s and 0.05 rad/s
// within 0.5 s of sim time and stay there for the second after.
// Worked out by hand: the path is refbox bridge -> DCDT -> robot bridge ->
// player (stop) -> AIRBoard driver (50 Hz) -> board ramp 6 m/s^2 at the rim
// (IANUS3 120 rad/s^2 x 0.05 m, Triskar and omni4 150 x 0.04 m: 6 m/s^2 each): from
// the top speed of 1.2 m/s the ramp alone takes 0.2 s, leaving 0.3 s for the
// messages and one driver cycle (20 ms).
#include <gtest/gtest.h>

#include "mrt_common_ros/rostest_helpers.h"
#include "rostest_team.h"

using mrt::robocup::test::Sample;
using mrt::robocup::test::TeamWatch;
using mrt::ros_common::wait_for;

namespace {

const std::vector<std::string> kRobots{"robot1", "robot2", "robot3", "robot4"};
constexpr double kSpeedStill = 0.02, kOmegaStill = 0.05, kDeadline = 0.5, kWatch = 1.5;

// The first time from which the robot stays still up to the end of the
// samples (NaN when it never does).
double halted_at(const std::vector<Sample>& s, double from) {
  double since = std::nan("");
  for (const Sample& p : s) {
    if (p.t < from) continue;
    const bool still = p.speed < kSpeedStill && std::abs(p.omega) < kOmegaStill;
    if (!still) since = std::nan("");
    else if (std::isnan(since)) since = p.t;
  }
  return since;
}

TEST(RoboCupReferee, StopHaltsEveryRobotWithinHalfASecond) {
  ros::NodeHandle nh;
  TeamWatch team(kRobots);
  ros::Publisher op = nh.advertise<mrt_msgs::RefereeCommand>("/referee/operator", 5);
  ASSERT_TRUE(wait_for([&] { return team.command("start") != nullptr; }, 90.0)) << "the match never started";
  const double start = team.command("start")->header.stamp.toSec();
  for (const auto& r : kRobots) ASSERT_TRUE(wait_for([&] { return team.latest(r) != nullptr; }, 30.0)) << r;
  // Play on and the team moving: at least two robots faster than 0.3 m/s.
  auto moving = [&] {
    int n = 0;
    for (const auto& r : kRobots) n += team.latest(r)->speed > 0.3;
    return n >= 2;
  };
  ASSERT_TRUE(wait_for(moving, 60.0)) << "the team does not move after the start at " << start << " s";
  ASSERT_EQ(team.command("stop", start), nullptr) << "the referee stopped play by itself";
  mrt_msgs::RefereeCommand stop;
  stop.name = "stop";
  op.publish(stop);
  ASSERT_TRUE(wait_for([&] { return team.command("stop", start) != nullptr; }, 10.0)) << "no stop on /referee";
  const double t0 = team.command("stop", start)->header.stamp.toSec();
  ASSERT_TRUE(wait_for([&] {
    for (const auto& r : kRobots)
      if (team.latest(r)->t < t0 + kWatch) return false;
    return true;
  }, 60.0));
  for (const auto& r : kRobots) {
    const double h = halted_at(team.truth[r], t0);
    ASSERT_FALSE(std::isnan(h)) << r << " still moves " << kWatch << " s after the stop";
    EXPECT_LE(h - t0, kDeadline) << r << " halted " << h - t0 << " s after the stop";
    ROS_INFO("%s halted %.3f s after the referee's stop", r.c_str(), h - t0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rostest_robocup_stop");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
