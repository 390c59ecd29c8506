// The simulator's camera through recvision_node, against ground truth:
// over 10 percept messages, the ball (world (0, 0), the robot at (-2, 0)
// facing +x: 2.0 m at bearing 0) within 2 % in distance and 0.02 rad in
// bearing; the blue goal (mouth centre (-9, 0): 7.0 m at bearing pi) within
// 0.3 m and 0.05 rad; at least 20 field-line points per message, at most
// 2 % of them farther than 10 cm from a line of the world file. The
// node's check of sim_node's camera_info (mrt_omni_profile: centre, tilt
// and mirror profile) against config/msl_omni.yaml says "matches".
#include <gtest/gtest.h>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <mrt_msgs/Percept.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/rostest_helpers.h"
#include "mrt_sim/world.h"

using mrt::ros_common::wait_for;

namespace {
double attr(const mrt_msgs::PerceptObject& o, const std::string& name) {
  for (const auto& a : o.attributes)
    if (a.name == name) return a.value;
  return NAN;
}
std::string color(const mrt_msgs::PerceptObject& o) {
  for (const auto& a : o.attributes)
    if (a.name == "color") return a.symbol;
  return "";
}
}  // namespace

TEST(SimCamera, PerceptsAgreeWithGroundTruth) {
  ros::NodeHandle nh, pnh("~");
  std::string world_file;
  ASSERT_TRUE(pnh.getParam("world", world_file));
  const mrt::sim::World world = mrt::sim::load_world(world_file);
  std::vector<mrt_msgs::Percept> got;
  nav_msgs::Odometry truth;
  bool have_truth = false;
  auto t_sub = nh.subscribe<nav_msgs::Odometry>("/robot1/ground_truth", 10, [&](const nav_msgs::OdometryConstPtr& m) {
    truth = *m;
    have_truth = true;
  });
  auto p_sub = nh.subscribe<mrt_msgs::Percept>("/robot1/vision_percepts", 20, [&](const mrt_msgs::PerceptConstPtr& m) {
    if (have_truth) got.push_back(*m);
  });
  std::string info_check;
  auto d_sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArrayConstPtr& m) {
    for (const auto& s : m->status)
      for (const auto& kv : s.values)
        if (kv.key == "camera_info: last check" && kv.value != "none received") info_check = kv.value;
  });
  ASSERT_TRUE(wait_for([&] { return got.size() >= 10; }, 45.0)) << got.size() << " percept messages";
  EXPECT_TRUE(wait_for([&] { return !info_check.empty(); }, 10.0));
  EXPECT_EQ(info_check, "matches");
  const mrt::common::Pose2D pose = mrt::ros_common::to_pose2d(truth.pose.pose);
  EXPECT_NEAR(pose.x, -2.0, 0.01);
  EXPECT_NEAR(pose.y, 0.0, 0.01);
  for (const auto& p : got) {
    EXPECT_EQ(p.header.frame_id, "robot1/base_link");
    int balls = 0, goals = 0, lines = 0, far = 0;
    for (const auto& o : p.objects) {
      const double d = attr(o, "distance"), b = attr(o, "bearing");
      if (o.membership_class == "Ball") {
        ++balls;
        EXPECT_NEAR(d, 2.0, 0.04);
        EXPECT_NEAR(b, 0.0, 0.02);
      } else if (o.membership_class == "Goal" && color(o) == "blue") {
        ++goals;
        EXPECT_NEAR(d, 7.0, 0.3);
        EXPECT_NEAR(std::abs(std::remainder(b - M_PI, 2 * M_PI)), 0.0, 0.05);
      } else if (o.membership_class == "Line") {
        ++lines;
        const mrt::sim::Point2D g{pose.x + std::cos(pose.theta) * attr(o, "x") - std::sin(pose.theta) * attr(o, "y"),
                                  pose.y + std::sin(pose.theta) * attr(o, "x") + std::cos(pose.theta) * attr(o, "y")};
        double best = 1e9;
        for (const auto& s : world.field_lines) best = std::min(best, mrt::sim::distance_to_segment(g, s));
        far += best > 0.10;
      }
    }
    EXPECT_EQ(balls, 1);
    EXPECT_EQ(goals, 1);
    EXPECT_GE(lines, 20);
    EXPECT_LE(far, 0.02 * lines) << far << " of " << lines << " line points farther than 10 cm";
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "recvision_sim_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
