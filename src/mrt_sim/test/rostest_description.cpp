// rostest: robot_description loads; robot_state_publisher publishes every
// link of the Roby robot (P3-AT) as robot1/<link>; the sonar frames sit
// where the simulator's world file mounts them; the wheel joint angles
// follow the encoders while the robot drives a known distance.
#include <cmath>
#include <map>
#include <string>

#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_listener.h>
#include <urdf/model.h>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::ros_common::spin_for;
using mrt::ros_common::wait_for;

struct Fixture : ::testing::Test {
  ros::NodeHandle nh;  // in /robot1
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener{buffer};
  std::map<std::string, double> joints;
  bool have_joints = false;
  nav_msgs::Odometry truth;
  bool have_truth = false;
  ros::Subscriber js_sub = nh.subscribe<sensor_msgs::JointState>("joint_states", 50, [this](const auto& m) {
    for (std::size_t i = 0; i < m->name.size() && i < m->position.size(); ++i) joints[m->name[i]] = m->position[i];
    have_joints = true;
  });
  ros::Subscriber gt_sub = nh.subscribe<nav_msgs::Odometry>("ground_truth", 50, [this](const auto& m) {
    truth = *m;
    have_truth = true;
  });
};

TEST_F(Fixture, DescriptionFramesAndWheelAngles) {
  std::string xml;
  ASSERT_TRUE(wait_for([&] { return nh.getParam("robot_description", xml); }, 10.0));
  urdf::Model model;
  ASSERT_TRUE(model.initString(xml));
  EXPECT_EQ(model.getName(), "p3at");
  ASSERT_TRUE(wait_for([&] { return have_joints && have_truth; }, 20.0));

  // Every link (4 wheels, 16 sonars, 2 mice, gps, base_link) reaches base_link.
  EXPECT_EQ(model.links_.size(), 24u);
  for (const auto& kv : model.links_) {
    const std::string frame = "robot1/" + kv.first;
    EXPECT_TRUE(wait_for([&] { return buffer.canTransform("robot1/base_link", frame, ros::Time(0)); }, 5.0))
        << frame;
  }
  // sonar_3 at 3 * 22.5 = 67.5 deg on the 0.33 m footprint circle
  // (mrt_sim's `count` ring): (0.33 cos 67.5, 0.33 sin 67.5) = (0.126286, 0.304880).
  const auto s3 = buffer.lookupTransform("robot1/base_link", "robot1/sonar_3", ros::Time(0));
  EXPECT_NEAR(s3.transform.translation.x, 0.126286, 1e-5);
  EXPECT_NEAR(s3.transform.translation.y, 0.304880, 1e-5);

  // Drive straight at 0.4 m/s for 2.5 s of sim time: the wheels turn by the
  // distance over the wheel radius 0.11 m (1 m -> 9.0909 rad).
  spin_for(0.3);
  const double l0 = joints.at("left_wheel_joint"), r0 = joints.at("right_wheel_joint");
  const double x0 = truth.pose.pose.position.x, y0 = truth.pose.pose.position.y;
  ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);
  geometry_msgs::Twist t;
  t.linear.x = 0.4;
  const ros::Time end = ros::Time::now() + ros::Duration(2.5);
  while (ros::ok() && ros::Time::now() < end) {
    cmd.publish(t);
    spin_for(0.05);
  }
  cmd.publish(geometry_msgs::Twist());
  spin_for(1.0);
  const double d = std::hypot(truth.pose.pose.position.x - x0, truth.pose.pose.position.y - y0);
  EXPECT_GT(d, 0.5);  // about 1 m, less the acceleration ramp
  // Tolerance: one encoder tick (2 pi / 2000 = 0.0031 rad) plus the last
  // messages' timing (one 50 Hz encoder sample at 3.6 rad/s = 0.073 rad).
  EXPECT_NEAR(joints.at("left_wheel_joint") - l0, d / 0.11, 0.08);
  EXPECT_NEAR(joints.at("right_wheel_joint") - r0, d / 0.11, 0.08);
  // The wheel frame turns with the joint: robot_state_publisher's transform
  // of left_wheel is a rotation about y by the joint angle.
  const auto w = buffer.lookupTransform("robot1/base_link", "robot1/left_wheel", ros::Time(0));
  EXPECT_NEAR(std::fabs(w.transform.rotation.y), std::fabs(std::sin(joints.at("left_wheel_joint") / 2)), 0.05);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "description_rostest");
  return RUN_ALL_TESTS();
}
