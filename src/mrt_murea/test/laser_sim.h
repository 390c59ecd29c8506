// The laser robot of murea_node's laser rostests: scans ray-cast in a
// world file (laser_cast.h) from known poses, the odometry tf
// odom -> base_link of a drifting odometry and the static mount
// base_link -> laser.
#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <random>
#include <string>

#include "laser_cast.h"
#include "mrt_common_ros/conversions.h"

namespace mrt::murea::test {

class LaserSim {
 public:
  // The laser: 360 beams over the full turn, 0.05 .. 8 m, Gaussian range
  // noise of sd `noise` m; mounted at `mount` in base_link.
  LaserSim(const std::string& world_file, const Pose2D& mount, double noise = 0.01)
      : caster_(world_file), mount_(mount), noise_(noise) {}

  sensor_msgs::LaserScan scan(const Pose2D& base, const ros::Time& stamp, const std::string& frame) {
    sensor_msgs::LaserScan m;
    m.header.stamp = stamp;
    m.header.frame_id = frame;
    m.angle_min = static_cast<float>(-M_PI);
    m.angle_increment = static_cast<float>(2 * M_PI / 360);
    m.angle_max = static_cast<float>(m.angle_min + 359 * m.angle_increment);
    m.range_min = 0.05f;
    m.range_max = 8.0f;
    // Beyond range_max: inf (as many lasers report it).
    m.ranges = caster_.ranges(base * mount_, 360, m.angle_min, m.angle_increment, m.range_max, noise_, rng_);
    return m;
  }

  const Pose2D& mount() const { return mount_; }

 private:
  LaserCaster caster_;
  Pose2D mount_;
  double noise_;
  std::mt19937 rng_{35};
};

// The robot on ROS: at each step the odometry tf odom -> base (stamped
// `stamp`), then the scan of the true pose in `laser` (mounted through a
// static tf base -> laser).
class LaserRobot {
 public:
  LaserRobot(LaserSim& sim, DriftingOdometry& odom, const std::string& odom_frame, const std::string& base_frame,
             const std::string& laser_frame, const std::string& scan_topic = "scan")
      : sim_(sim), odom_(odom), odom_frame_(odom_frame), base_frame_(base_frame), laser_frame_(laser_frame) {
    ros::NodeHandle nh;
    scan_pub_ = nh.advertise<sensor_msgs::LaserScan>(scan_topic, 20);
    static_tf_.sendTransform(mrt::ros_common::to_transform(sim.mount(), base_frame, laser_frame, ros::Time::now()));
  }
  bool connected() const { return scan_pub_.getNumSubscribers() > 0; }
  // Publishes the odometry at `truth` and its scan; returns the scan.
  sensor_msgs::LaserScan step(const Pose2D& truth, const ros::Time& stamp) {
    tf_.sendTransform(mrt::ros_common::to_transform(odom_.update(truth), odom_frame_, base_frame_, stamp));
    sensor_msgs::LaserScan s = sim_.scan(truth, stamp, laser_frame_);
    scan_pub_.publish(s);
    return s;
  }
  // Only the odometry (the robot standing still, no scan).
  void odom_only(const Pose2D& truth, const ros::Time& stamp) {
    tf_.sendTransform(mrt::ros_common::to_transform(odom_.update(truth), odom_frame_, base_frame_, stamp));
  }

 private:
  LaserSim& sim_;
  DriftingOdometry& odom_;
  std::string odom_frame_, base_frame_, laser_frame_;
  ros::Publisher scan_pub_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
};

}  // namespace mrt::murea::test
