// The replay bringup (mrt_recvision/launch/replay.launch) against the
// bag's ground truth. The bag (test/make_replay_bag.cpp) drives robot1 from
// (-2, 0, 0) on an arc of radius 0.5 / 0.25 = 2 m for 4 s (2 m, 1 rad),
// 40 camera frames; the ball lies at the centre spot (0, 0), 0.83 to 2 m
// from the robot.
// - every frame yields a percept message in robot1/base_link (none dropped);
// - the ball, in every frame, within 2 % in distance (the bound up
//   to 5 m) and 0.03 rad in bearing of the truth interpolated at the
//   frame's stamp (truth at 50 Hz: at 0.5 m/s the interpolation error is
//   under 1 mm);
// - mice odometry: after the run, the pose in odom equals the truth's
//   displacement from the start within 2 cm and 1 degree (1 % of the 2 m
//   driven: the counts' quantisation and the sim's 1 % count noise).
#include <gtest/gtest.h>

#include <mrt_msgs/Percept.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>
#include <map>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::to_pose2d;
using mrt::ros_common::wait_for;

namespace {
constexpr double kStart = 100.0, kSeconds = 4.0;
constexpr int kFrames = 40;

double attr(const mrt_msgs::PerceptObject& o, const std::string& name) {
  for (const auto& a : o.attributes)
    if (a.name == name) return a.value;
  return NAN;
}

// Truth interpolated at `t` between the two samples around it.
mrt::common::Pose2D truth_at(const std::map<double, mrt::common::Pose2D>& truth, double t) {
  auto hi = truth.lower_bound(t);
  if (hi == truth.end()) return std::prev(hi)->second;
  if (hi == truth.begin()) return hi->second;
  auto lo = std::prev(hi);
  const double a = (t - lo->first) / (hi->first - lo->first);
  return {lo->second.x + a * (hi->second.x - lo->second.x), lo->second.y + a * (hi->second.y - lo->second.y),
          lo->second.theta + a * std::remainder(hi->second.theta - lo->second.theta, 2 * M_PI)};
}
}  // namespace

TEST(Replay, OdometryAndPerceptsAgreeWithTheBagsTruth) {
  ros::NodeHandle nh;
  std::map<double, mrt::common::Pose2D> truth;
  std::vector<mrt_msgs::Percept> percepts;
  nav_msgs::Odometry odom;
  auto t_sub = nh.subscribe<nav_msgs::Odometry>("/robot1/ground_truth", 500, [&](const nav_msgs::OdometryConstPtr& m) {
    truth[m->header.stamp.toSec()] = to_pose2d(m->pose.pose);
  });
  auto o_sub = nh.subscribe<nav_msgs::Odometry>("/robot1/odom", 500,
                                                [&](const nav_msgs::OdometryConstPtr& m) { odom = *m; });
  auto p_sub = nh.subscribe<mrt_msgs::Percept>("/robot1/percepts", 100,
                                               [&](const mrt_msgs::PerceptConstPtr& m) { percepts.push_back(*m); });
  const double end = kStart + kSeconds - 0.03;
  ASSERT_TRUE(wait_for([&] { return percepts.size() >= kFrames && odom.header.stamp.toSec() >= end; }, 45.0))
      << percepts.size() << " percept messages, odometry up to " << odom.header.stamp.toSec();
  ros::WallDuration(0.5).sleep();  // anything more would arrive now
  ros::spinOnce();
  ASSERT_GE(truth.size(), 190u);  // 50 Hz over 4 s
  EXPECT_EQ(percepts.size(), static_cast<std::size_t>(kFrames));

  int balls = 0;
  for (const auto& p : percepts) {
    EXPECT_EQ(p.header.frame_id, "robot1/base_link");
    const auto pose = truth_at(truth, p.header.stamp.toSec());
    const double want_d = std::hypot(pose.x, pose.y);
    const double want_b = std::remainder(std::atan2(-pose.y, -pose.x) - pose.theta, 2 * M_PI);
    for (const auto& o : p.objects) {
      if (o.membership_class != "Ball") continue;
      ++balls;
      EXPECT_NEAR(attr(o, "distance"), want_d, 0.02 * want_d) << "at " << p.header.stamp;
      EXPECT_NEAR(std::remainder(attr(o, "bearing") - want_b, 2 * M_PI), 0.0, 0.03) << "at " << p.header.stamp;
    }
  }
  EXPECT_EQ(balls, kFrames);

  // Truth's displacement from the start pose (-2, 0, 0), in the start frame.
  const auto last = truth_at(truth, odom.header.stamp.toSec());
  const auto got = to_pose2d(odom.pose.pose);
  EXPECT_NEAR(got.x, last.x + 2.0, 0.02);
  EXPECT_NEAR(got.y, last.y, 0.02);
  EXPECT_NEAR(std::remainder(got.theta - last.theta, 2 * M_PI), 0.0, M_PI / 180);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "recvision_replay_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
