// Shared pieces of the Roby rostests: ground truth, clearance, task status
// (the waiting itself is mrt_common_ros's wait_for).
#pragma once

#include <gtest/gtest.h>
#include <mrt_msgs/TaskStatus.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/rostest_helpers.h"
#include "mrt_roby/roby_loop.h"
#include "mrt_sim/world.h"

namespace roby_test {

/// Collects ground truth, the clearance to every obstacle of the world file
/// (ground truth, footprint to surface) and every task status.
class Observer {
 public:
  explicit Observer(const std::string& world_file) : world_(mrt::sim::load_world(world_file)) {
    radius_ = world_.robots.at(0).base.body_radius;
    ros::NodeHandle nh;
    gt_sub_ = nh.subscribe("ground_truth", 100, &Observer::on_truth, this);
    status_sub_ = nh.subscribe("task_status", 100, &Observer::on_status, this);
  }

  void on_truth(const nav_msgs::Odometry& o) {
    const auto& p = o.pose.pose;
    x_ = p.position.x;
    y_ = p.position.y;
    theta_ = mrt::ros_common::quaternion_to_yaw(p.orientation);
    vx_ = o.twist.twist.linear.x;
    omega_ = o.twist.twist.angular.z;
    std::string what;
    const double c = mrt::roby::world_clearance(&world_, x_, y_, radius_, &what);
    if (c < min_clearance_) {
      min_clearance_ = c;
      nearest_ = what;
    }
    ++truths_;
  }

  void on_status(const mrt_msgs::TaskStatus& s) { statuses_.push_back(s); last_ = s; }

  /// Spins until pred() holds or `sim_seconds` of ROS time pass (or the
  /// wall-clock guard); returns pred().
  template <class Pred>
  bool wait(Pred pred, double sim_seconds, double wall_guard = 200.0) {
    const ros::Time end = ros::Time::now() + ros::Duration(sim_seconds);
    auto sim_time_up = [&] { return !ros::Time::now().isZero() && ros::Time::now() > end; };
    mrt::ros_common::wait_for([&] { return pred() || sim_time_up(); }, wall_guard, 0.002);
    return pred();
  }

  bool saw_event(const std::string& e) const {
    for (const auto& s : statuses_)
      if (s.event == e) return true;
    return false;
  }

  mrt::sim::World world_;
  double radius_ = 0.0;
  double x_ = 0, y_ = 0, theta_ = 0, vx_ = 0, omega_ = 0;
  double min_clearance_ = 1e9;
  std::string nearest_;
  std::size_t truths_ = 0;
  std::vector<mrt_msgs::TaskStatus> statuses_;
  mrt_msgs::TaskStatus last_;
  ros::Subscriber gt_sub_, status_sub_;
};

}  // namespace roby_test
