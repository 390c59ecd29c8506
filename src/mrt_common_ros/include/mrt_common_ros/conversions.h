// Conversions every node repeats between mrt_common's SE(2) types and ROS
// messages: yaw <-> quaternion, Pose2D -> Pose / TransformStamped, planar
// odometry with its covariance. Header-only; no publishers, no clocks.
#pragma once

#include <array>
#include <cmath>
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>

#include "mrt_common/pose2d.h"

namespace mrt::ros_common {

/// Quaternion of a rotation by `yaw` radians about z.
inline geometry_msgs::Quaternion yaw_to_quaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

/// Yaw of a quaternion (the z-axis rotation of its ZYX Euler angles), in
/// (-pi, pi]; an unnormalised quaternion gives the same yaw.
inline double quaternion_to_yaw(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z);
}

inline geometry_msgs::Pose to_pose(const mrt::common::Pose2D& p, double z = 0.0) {
  geometry_msgs::Pose m;
  m.position.x = p.x;
  m.position.y = p.y;
  m.position.z = z;
  m.orientation = yaw_to_quaternion(p.theta);
  return m;
}

inline mrt::common::Pose2D to_pose2d(const geometry_msgs::Pose& m) {
  return {m.position.x, m.position.y, quaternion_to_yaw(m.orientation)};
}

inline geometry_msgs::TransformStamped to_transform(const mrt::common::Pose2D& p, const std::string& parent,
                                                    const std::string& child, const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = p.x;
  t.transform.translation.y = p.y;
  t.transform.rotation = yaw_to_quaternion(p.theta);
  return t;
}

/// Planar covariance (x, y, theta), row-major 3x3.
using Covariance2D = std::array<double, 9>;

/// Places a planar 3x3 covariance (x, y, theta) into a 6x6 ROS covariance
/// (x, y, z, roll, pitch, yaw); z, roll and pitch get `unobserved` on the
/// diagonal (REP-105 planar robots: a large value, or 0 for "not given").
inline void set_planar_covariance(const Covariance2D& c, boost::array<double, 36>& out, double unobserved = 0.0) {
  out.fill(0.0);
  static constexpr int kIdx[3] = {0, 1, 5};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) out[kIdx[r] * 6 + kIdx[k]] = c[r * 3 + k];
  out[2 * 6 + 2] = out[3 * 6 + 3] = out[4 * 6 + 4] = unobserved;
}

/// Odometry of a planar body: pose in `frame`, body twist (vx, vy, omega) in
/// `child_frame`, optional planar covariances (zero when not given).
inline nav_msgs::Odometry to_odometry(const mrt::common::Pose2D& pose, double vx, double vy, double omega,
                                      const std::string& frame, const std::string& child_frame,
                                      const ros::Time& stamp, const Covariance2D& pose_cov = {},
                                      const Covariance2D& twist_cov = {}) {
  nav_msgs::Odometry o;
  o.header.stamp = stamp;
  o.header.frame_id = frame;
  o.child_frame_id = child_frame;
  o.pose.pose = to_pose(pose);
  o.twist.twist.linear.x = vx;
  o.twist.twist.linear.y = vy;
  o.twist.twist.angular.z = omega;
  set_planar_covariance(pose_cov, o.pose.covariance);
  set_planar_covariance(twist_cov, o.twist.covariance);
  return o;
}

}  // namespace mrt::ros_common
