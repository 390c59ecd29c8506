// Shared pieces of the Roby rostests: ground truth, clearance, task status.
#pragma once

#include <gtest/gtest.h>
#include <mrt_msgs/TaskStatus.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "mrt_scare/roby_loop.h"
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
    theta_ = std::atan2(2.0 * p.orientation.w * p.orientation.z, 1.0 - 2.0 * p.orientation.z * p.orientation.z);
    vx_ = o.twist.twist.linear.x;
    omega_ = o.twist.twist.angular.z;
    std::string what;
    const double c = mrt::scare::world_clearance(&world_, x_, y_, radius_, &what);
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
    const ros::WallTime wall_end = ros::WallTime::now() + ros::WallDuration(wall_guard);
    while (ros::ok() && ros::WallTime::now() < wall_end) {
      ros::spinOnce();
      if (pred()) return true;
      if (!ros::Time::now().isZero() && ros::Time::now() > end) break;
      ros::WallDuration(0.002).sleep();
    }
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
