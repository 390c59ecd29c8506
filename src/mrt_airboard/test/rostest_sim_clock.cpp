// sim_clock.test: the emulated AIRBoard on mrt_sim's /clock at a real-time
// factor of 2. cmd_vel (0.3 m/s, 0.5 rad/s) goes to airboard_node, whose
// board's measured wheel speeds drive the simulated base (the emulator's
// --sim-wheel-cmd).
// Over 4 s of simulated time in steady state (from the first to the last
// board message received, at their reception in simulated time; the counts'
// least-squares rate over them), each wheel's board counts (8192 a revolution) must equal the simulator's wheel
// speeds integrated over the same interval: about (0.3 -+ 0.5 * 0.19) /
// 0.05 = 4.1 and 7.9 rad/s, 16.4 and 31.6 rad, within 1 %. With the board on the wall clock (before), it counts over 2 s of
// wall time only: half of that.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <mrt_msgs/WheelState.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::wait_for;

namespace {
constexpr double kCountsPerRev = 8192.0;
}

TEST(SimClock, BoardCountsFollowTheSimulatedWheels) {
  ros::NodeHandle nh;
  ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("/robot1/cmd_vel", 10);
  struct Sample {
    double t;  // simulated time: the board's counts at reception, the simulator's speeds at their stamp
    std::vector<double> v;
  };
  std::vector<Sample> board, sim;
  bool measuring = false, have_board = false;
  ros::Subscriber bs = nh.subscribe<mrt_msgs::WheelState>("/robot1/airboard/wheel_state", 50,
                                                         [&](const mrt_msgs::WheelState::ConstPtr& m) {
    have_board = m->ticks.size() == 2;
    if (measuring && have_board)
      board.push_back({ros::Time::now().toSec(), {double(m->ticks[0]), double(m->ticks[1])}});
  });
  ros::Subscriber ss = nh.subscribe<mrt_msgs::WheelState>("/robot1/wheel_state", 50,
                                                         [&](const mrt_msgs::WheelState::ConstPtr& m) {
    if (measuring && m->speed.size() == 2) sim.push_back({m->header.stamp.toSec(), m->speed});
  });
  ASSERT_TRUE(wait_for([&] { return cmd.getNumSubscribers() > 0 && have_board && !ros::Time::now().isZero(); }, 30.0));
  geometry_msgs::Twist t;
  t.linear.x = 0.3;
  t.angular.z = 0.5;
  // Commands every 20 ms of wall time until `until` (simulated time).
  auto drive_until = [&](const ros::Time& until) {
    return wait_for([&] {
      cmd.publish(t);
      return ros::Time::now() >= until;
    }, 20.0, 0.02);
  };
  ASSERT_TRUE(drive_until(ros::Time::now() + ros::Duration(2.0)));  // steady state
  measuring = true;
  const ros::WallTime wall0 = ros::WallTime::now();
  ASSERT_TRUE(drive_until(ros::Time::now() + ros::Duration(4.0)));
  measuring = false;
  const double wall = (ros::WallTime::now() - wall0).toSec();
  ASSERT_GT(board.size(), 10u);
  ASSERT_GT(sim.size(), 10u);
  const double t0 = board.front().t, t1 = board.back().t;
  std::printf("simulated %.3f s in %.3f s of wall time (real-time factor %.2f)\n", t1 - t0, wall, (t1 - t0) / wall);
  EXPECT_GT((t1 - t0) / wall, 1.2);  // really faster than real time
  for (int k = 0; k < 2; ++k) {
    // The board's counts against their reception time: the least-squares
    // slope (reception jitters by a few ms of wall time, twice that in
    // simulated time; the slope averages it out) times the interval.
    double mt = 0.0, mc = 0.0;
    for (const Sample& b : board) mt += b.t / board.size(), mc += b.v[k] / board.size();
    double stc = 0.0, stt = 0.0;
    for (const Sample& b : board) stc += (b.t - mt) * (b.v[k] - mc), stt += (b.t - mt) * (b.t - mt);
    const double board_angle = stc / stt * (t1 - t0) * 2.0 * M_PI / kCountsPerRev;
    // The simulator's wheel angle over [t0, t1]: its speeds held between
    // its messages (each message's speed from its stamp on).
    double sim_angle = 0.0;
    for (std::size_t i = 0; i + 1 < sim.size(); ++i) {
      const double a = std::max(t0, sim[i].t), b = std::min(t1, sim[i + 1].t);
      if (b > a) sim_angle += sim[i].v[k] * (b - a);
    }
    std::printf("wheel %d: board %.4f rad, simulator %.4f rad over %.3f s\n", k, board_angle, sim_angle, t1 - t0);
    EXPECT_GT(std::fabs(sim_angle), 10.0) << k;  // really turning
    EXPECT_NEAR(board_angle, sim_angle, 0.01 * std::fabs(sim_angle))
        << "wheel " << k << " over " << t1 - t0 << " s simulated, " << wall << " s wall";
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_clock_test");
  return RUN_ALL_TESTS();
}
