#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common_ros/conversions.h"

using mrt::common::Pose2D;
namespace rc = mrt::ros_common;

// A yaw of 90 deg is the quaternion (0, 0, sin 45, cos 45) = (0, 0, 0.70711, 0.70711).
TEST(Conversions, YawQuaternion) {
  const auto q = rc::yaw_to_quaternion(M_PI / 2);
  EXPECT_NEAR(q.z, 0.7071068, 1e-7);
  EXPECT_NEAR(q.w, 0.7071068, 1e-7);
  EXPECT_NEAR(rc::quaternion_to_yaw(q), M_PI / 2, 1e-12);
  for (double yaw : {-3.0, -1.0, 0.0, 0.5, 3.1}) EXPECT_NEAR(rc::quaternion_to_yaw(rc::yaw_to_quaternion(yaw)), yaw, 1e-12);
  // Scaled by 2 it is the same rotation.
  geometry_msgs::Quaternion s = rc::yaw_to_quaternion(1.0);
  s.z *= 2; s.w *= 2;
  EXPECT_NEAR(rc::quaternion_to_yaw(s), 1.0, 1e-12);
}

TEST(Conversions, TransformAndPose) {
  const auto t = rc::to_transform(Pose2D(1.5, -2.0, M_PI), "map", "odom", ros::Time(3.0));
  EXPECT_EQ(t.header.frame_id, "map");
  EXPECT_EQ(t.child_frame_id, "odom");
  EXPECT_EQ(t.header.stamp.toSec(), 3.0);
  EXPECT_EQ(t.transform.translation.x, 1.5);
  EXPECT_NEAR(std::fabs(t.transform.rotation.z), 1.0, 1e-12);
  const Pose2D back = rc::to_pose2d(rc::to_pose(Pose2D(0.3, 0.4, -2.0)));
  EXPECT_NEAR(back.x, 0.3, 1e-12);
  EXPECT_NEAR(back.theta, -2.0, 1e-12);
}

// The planar covariance's rows x, y, theta land on rows 0, 1, 5 of the 6x6
// (x, y, z, roll, pitch, yaw) matrix: element (theta, x) = index 5*6+0 = 30.
TEST(Conversions, OdometryCovariance) {
  const rc::Covariance2D c = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  const auto o = rc::to_odometry(Pose2D(1, 2, 0), 0.5, 0.0, 0.1, "odom", "base_link", ros::Time(1.0), c);
  EXPECT_EQ(o.pose.covariance[0], 1);
  EXPECT_EQ(o.pose.covariance[1], 2);
  EXPECT_EQ(o.pose.covariance[5], 3);
  EXPECT_EQ(o.pose.covariance[6], 4);
  EXPECT_EQ(o.pose.covariance[7], 5);
  EXPECT_EQ(o.pose.covariance[11], 6);
  EXPECT_EQ(o.pose.covariance[30], 7);
  EXPECT_EQ(o.pose.covariance[31], 8);
  EXPECT_EQ(o.pose.covariance[35], 9);
  EXPECT_EQ(o.pose.covariance[14], 0);
  EXPECT_EQ(o.twist.twist.linear.x, 0.5);
  EXPECT_EQ(o.twist.twist.angular.z, 0.1);
  EXPECT_EQ(o.child_frame_id, "base_link");
}
