// Helpers shared by the rostests of every package.
#pragma once

#include <ros/ros.h>

namespace mrt::ros_common {

/// Spins (ros::spinOnce every `period` seconds of wall time) until `pred`
/// holds or `seconds` of wall time have passed; returns the last value of
/// `pred`. Wall time, so that a test waiting on a simulator that publishes
/// /clock cannot hang when the simulator is gone.
template <class Pred>
bool wait_for(Pred pred, double seconds, double period = 0.01) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    if (pred()) return true;
    ros::WallDuration(period).sleep();
  }
  ros::spinOnce();
  return pred();
}

}  // namespace mrt::ros_common

namespace mrt::ros_common {

/// Spins for `seconds` of wall time (callbacks run meanwhile).
inline void spin_for(double seconds, double period = 0.005) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(period).sleep();
  }
}

}  // namespace mrt::ros_common
