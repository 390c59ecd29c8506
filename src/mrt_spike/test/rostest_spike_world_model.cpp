// spike_node with ~use_world_model on the Roby outdoor map: the anchors of
// MAP's world model (mrt_msgs/WorldModel) of the obstacle classes become
// moving obstacles inflated by size, position uncertainty and speed; the
// diagnostics count them.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <mrt_msgs/WorldModel.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <algorithm>
#include <cmath>
#include <map>

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

mrt_msgs::Anchor anchor(unsigned id, const std::string& cls, unsigned char status, double x, double y, double vx,
                        double vy, double var) {
  mrt_msgs::Anchor a;
  a.id = id, a.membership_class = cls, a.status = status;
  a.x = x, a.y = y, a.vx = vx, a.vy = vy;
  a.covariance[0] = a.covariance[5] = var;
  return a;
}

double distance_to_segment(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

}  // namespace

TEST(SpikeNode, ObstaclesFromTheWorldModel) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Path> plans;
  std::map<std::string, std::string> diag;  // the planner's key/values, last seen
  auto sub = nh.subscribe<nav_msgs::Path>("plan", 10, [&](const nav_msgs::PathConstPtr& p) { plans.push_back(*p); });
  auto dsub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArrayConstPtr& d) {
        for (const auto& s : d->status)
          if (s.name.find("planner") != std::string::npos)
            for (const auto& kv : s.values) diag[kv.key] = kv.value;
      });
  auto goal_pub = nh.advertise<geometry_msgs::PoseStamped>("goal", 1, true);
  auto model_pub = nh.advertise<mrt_msgs::WorldModel>("world_model", 5, true);
  ASSERT_TRUE(wait_for([&] { return goal_pub.getNumSubscribers() > 0 && model_pub.getNumSubscribers() > 0; }, 20));
  // the straight way from (18, 10.5) to (28, 10.5), between buildings B and C
  goal_pub.publish(pose(28, 10.5));
  ASSERT_TRUE(wait_for([&] { return !plans.empty(); }, 10));
  for (const auto& p : plans.back().poses) EXPECT_NEAR(p.pose.position.y, 10.5, 0.051);
  ASSERT_TRUE(wait_for([&] { return diag.count("obstacles") && diag["map loaded"] == "True"; }, 5));
  EXPECT_EQ(diag["obstacles"], "0");
  // An opponent 1.5 m beside the line at (23, 12) coming at 2 m/s towards
  // it: standing still its disc (0.25 + 1 sigma 0.1 + robot 0.3 + safety 0.1
  // = 0.75 m) would leave the line free, but over the 0.5 s horizon it sweeps
  // down to (23, 11), 0.5 m from the line: the plan is blocked. A tentative
  // anchor and a ball (not an obstacle class) on the line are ignored.
  mrt_msgs::WorldModel m;
  m.header.frame_id = "map";
  m.header.stamp = ros::Time::now();
  m.robot = "robot1";
  m.anchors.push_back(anchor(1, "Opponent", mrt_msgs::Anchor::CONFIRMED, 23.0, 12.0, 0.0, -2.0, 0.01));
  m.anchors.push_back(anchor(2, "Opponent", mrt_msgs::Anchor::TENTATIVE, 25.5, 10.5, 0.0, 0.0, 0.01));
  m.anchors.push_back(anchor(3, "Ball", mrt_msgs::Anchor::CONFIRMED, 20.5, 10.5, 0.0, 0.0, 0.01));
  const size_t before = plans.size();
  const ros::WallTime t0 = ros::WallTime::now();
  model_pub.publish(m);
  ASSERT_TRUE(wait_for([&] { return plans.size() > before; }, 10));
  EXPECT_LT((ros::WallTime::now() - t0).toSec(), 2.0);
  const nav_msgs::Path& second = plans.back();
  ASSERT_FALSE(second.poses.empty());
  double closest = 1e9;
  for (const auto& p : second.poses)
    closest = std::min(closest, distance_to_segment(p.pose.position.x, p.pose.position.y, 23, 12, 23, 11));
  EXPECT_GE(closest, 0.75 - 0.071);  // less half a cell's diagonal
  EXPECT_NEAR(second.poses.back().pose.position.x, 28, 0.051);
  // the diagnostics count one obstacle (the other two were ignored)
  ASSERT_TRUE(wait_for([&] { return diag["obstacles"] == "1"; }, 5));
  EXPECT_GE(std::stoi(diag["re-plans"]), 2);
  EXPECT_EQ(diag["last failure"], "none");
  // the next model without the opponent removes it
  m.anchors.clear();
  m.header.stamp = ros::Time::now();
  model_pub.publish(m);
  EXPECT_TRUE(wait_for([&] { return diag["obstacles"] == "0"; }, 5));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "spike_world_model_rostest");
  tf2_ros::StaticTransformBroadcaster tf;  // the robot stands at (18, 10.5)
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "map";
  t.child_frame_id = "base_link";
  t.transform.translation.x = 18.0, t.transform.translation.y = 10.5;
  t.transform.rotation.w = 1.0;
  tf.sendTransform(t);
  return RUN_ALL_TESTS();
}
