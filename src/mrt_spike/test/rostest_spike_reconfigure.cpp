// spike_node's dynamic_reconfigure on test/data/reconfigure_wall.yaml: one
// wall from (5, -3) up to (5, 0), the robot at (0, -1), the goal (10, -1).
// The plan turns round the wall's top end E = (5, 0); its closest approach
// to E is the inflation d (robot radius + safety distance) within the grid's
// error: at least d - 0.071 (a wall cell's centre may lie half a cell's
// diagonal, 0.0707 m, from the wall), at most d + 0.24 (the corner of the
// path is a free cell diagonal-adjacent to an inflated one: 0.0707 + 0.1414
// beyond d, plus half the 0.05 m spacing between poses).
//
// Its length is at least the taut string from S = (0, -1) to G = (10, -1)
// round a disc of radius r at E (S and G at L = sqrt 26 from E, 2.7468 rad
// apart as seen from E): 2 sqrt(L^2 - r^2) + r (2 pi - 2.7468 - 2 acos(r/L)).
// With d = 0.8 and r = d - 0.15 = 0.65 (the grid's error twice): 10.5377 m.
#include <dynamic_reconfigure/Reconfigure.h>
#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <cmath>
#include <cstdio>
#include <mutex>
#include <vector>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::wait_for;

namespace {

geometry_msgs::PoseStamped pose(double x, double y) {
  geometry_msgs::PoseStamped p;
  p.header.frame_id = "map";
  p.pose.position.x = x, p.pose.position.y = y;
  p.pose.orientation.w = 1.0;
  return p;
}

double closest_to_wall_end(const nav_msgs::Path& path) {
  double d = 1e9;
  for (const auto& p : path.poses) d = std::min(d, std::hypot(p.pose.position.x - 5.0, p.pose.position.y));
  return d;
}

double length(const nav_msgs::Path& path) {
  double l = 0.0;
  for (size_t i = 1; i < path.poses.size(); ++i)
    l += std::hypot(path.poses[i].pose.position.x - path.poses[i - 1].pose.position.x,
                    path.poses[i].pose.position.y - path.poses[i - 1].pose.position.y);
  return l;
}

nav_msgs::Path make_plan() {
  nav_msgs::GetPlan srv;
  srv.request.start = pose(0, -1);
  srv.request.goal = pose(10, -1);
  EXPECT_TRUE(ros::service::call("make_plan", srv));
  return srv.response.plan;
}

bool set_safety_distance(double value, dynamic_reconfigure::Config& out) {
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::DoubleParameter p;
  p.name = "safety_distance";
  p.value = value;
  srv.request.config.doubles.push_back(p);
  if (!ros::service::call("spike/set_parameters", srv)) return false;
  out = srv.response.config;
  return true;
}

double value_of(const dynamic_reconfigure::Config& c, const std::string& name) {
  for (const auto& d : c.doubles)
    if (d.name == name) return d.value;
  return NAN;
}

}  // namespace

TEST(SpikeNodeReconfigure, ALargerSafetyDistanceKeepsThePlanFurtherFromTheWall) {
  ros::NodeHandle nh;
  std::mutex m;
  std::vector<nav_msgs::Path> plans;
  auto sub = nh.subscribe<nav_msgs::Path>("plan", 10, [&](const nav_msgs::PathConstPtr& p) {
    const std::lock_guard<std::mutex> lock(m);
    plans.push_back(*p);
  });
  auto goal_pub = nh.advertise<geometry_msgs::PoseStamped>("goal", 1, true);
  ASSERT_TRUE(ros::service::waitForService("make_plan", ros::Duration(20)));
  ASSERT_TRUE(ros::service::waitForService("spike/set_parameters", ros::Duration(20)));
  ASSERT_TRUE(wait_for([&] { return goal_pub.getNumSubscribers() > 0 && sub.getNumPublishers() > 0; }, 20));
  const auto count = [&] {
    const std::lock_guard<std::mutex> lock(m);
    return plans.size();
  };

  // the start-up values: robot radius 0.3 + safety 0.1 = 0.4 m
  const nav_msgs::Path narrow = make_plan();
  ASSERT_GT(narrow.poses.size(), 10u);
  EXPECT_GE(closest_to_wall_end(narrow), 0.4 - 0.071);
  EXPECT_LE(closest_to_wall_end(narrow), 0.4 + 0.24);
  goal_pub.publish(pose(10, -1));  // the robot's goal: re-planned on reconfiguration
  ASSERT_TRUE(wait_for([&] { return count() > 0; }, 10));

  // safety 0.5: inflation 0.8 m, both make_plan and the goal's plan
  const size_t before = count();
  dynamic_reconfigure::Config applied;
  ASSERT_TRUE(set_safety_distance(0.5, applied));
  EXPECT_DOUBLE_EQ(value_of(applied, "safety_distance"), 0.5);
  EXPECT_DOUBLE_EQ(value_of(applied, "robot_radius"), 0.3);
  const nav_msgs::Path wide = make_plan();
  ASSERT_GT(wide.poses.size(), 10u);
  EXPECT_GE(closest_to_wall_end(wide), 0.8 - 0.071);
  EXPECT_LE(closest_to_wall_end(wide), 0.8 + 0.24);
  EXPECT_GE(length(wide), 10.5377 - 0.01);
  EXPECT_GT(length(wide), length(narrow));
  EXPECT_NEAR(wide.poses.back().pose.position.x, 10, 0.051);
  std::printf("reconfigure: closest to the wall's end %.3f m -> %.3f m, length %.3f m -> %.3f m\n",
              closest_to_wall_end(narrow), closest_to_wall_end(wide), length(narrow), length(wide));
  ASSERT_TRUE(wait_for([&] { return count() > before; }, 5));
  {
    const std::lock_guard<std::mutex> lock(m);
    EXPECT_GE(closest_to_wall_end(plans.back()), 0.8 - 0.071);
  }

  // back to 0.1: the first plan's clearance again
  ASSERT_TRUE(set_safety_distance(0.1, applied));
  const nav_msgs::Path again = make_plan();
  EXPECT_NEAR(closest_to_wall_end(again), closest_to_wall_end(narrow), 1e-6);
  EXPECT_NEAR(length(again), length(narrow), 1e-6);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "spike_reconfigure_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  tf2_ros::StaticTransformBroadcaster tf;  // the robot stands at (0, -1)
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "map";
  t.child_frame_id = "base_link";
  t.transform.translation.x = 0.0, t.transform.translation.y = -1.0;
  t.transform.rotation.w = 1.0;
  tf.sendTransform(t);
  return RUN_ALL_TESTS();
}
