// Conversions between the simulator core's types and ROS messages (the rviz
// markers are in markers.h). Pure functions: no publishers, no parameters,
// no clocks.
#pragma once

#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/TransformStamped.h>
#include <mrt_msgs/MiceReading.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/Range.h>

#include "mrt_common_ros/conversions.h"
#include "mrt_sim/simulator.h"

namespace mrt::sim::node {

// Pose and transform of a Pose2D: the stack's one copy, in mrt_common_ros.
using mrt::ros_common::to_pose;
using mrt::ros_common::to_transform;

/// Frame names of one robot: "<prefix><robot>/<suffix>".
struct RobotFrames {
  std::string base_truth;   // <robot>/base_link_truth: ground truth body frame
  std::string base;         // <robot>/base_link: the body as estimated by odometry
  std::string sensor_parent;  // one of the two above, parent of the sensor frames
  std::string prefix;       // "<prefix><robot>/"
  std::string sonar(std::size_t i) const { return prefix + "sonar_" + std::to_string(i); }
  std::string mouse(const std::string& id) const { return prefix + "mouse_" + id; }
  std::string gps() const { return prefix + "gps"; }
};
RobotFrames make_frames(const std::string& frame_prefix, const std::string& robot,
                        const std::string& sensor_parent_suffix);

/// Ground truth: pose in the world frame, twist in the body frame (the twist
/// applied during the last step), zero covariance.
nav_msgs::Odometry to_odometry(const RobotState& r, const std::string& world_frame,
                               const RobotFrames& f, const ros::Time& stamp);

mrt_msgs::MiceReading to_mice(const MiceSample& m, const RobotFrames& f, const ros::Time& stamp);

/// Wheel state; duty is the measured speed over the maximum wheel speed;
/// status flags SATURATED and WATCHDOG apply to every wheel.
mrt_msgs::WheelState to_wheel_state(const RobotState& r, bool watchdog, const ros::Time& stamp);

/// The wheel joints of the robot description: names from
/// wheel_joint_names, positions = encoder ticks as angles (rad), velocities =
/// measured wheel speeds (rad/s).
sensor_msgs::JointState to_joint_state(const RobotState& r, const ros::Time& stamp);

sensor_msgs::Range to_range(const SonarConfig& s, double range, const std::string& frame,
                            const ros::Time& stamp);

/// The omnidirectional camera's percept: one object per seen object with the
/// numeric attributes distance [m], bearing [rad], x, y [m] (in `frame`) and
/// the symbolic attribute color (when the object has one).
mrt_msgs::Percept to_percept(const std::vector<SeenObject>& seen, const SensorsConfig& cfg,
                             const std::string& robot, const std::string& frame,
                             const ros::Time& stamp);

/// The DGPS fix of world position `p`: latitude/longitude by
/// mrt::common::LocalTangentPlane around the datum (the world origin, x east
/// and y north).
sensor_msgs::NavSatFix to_navsat(const Point2D& p, const SensorsConfig& cfg, const std::string& frame,
                                 const ros::Time& stamp);

}  // namespace mrt::sim::node
