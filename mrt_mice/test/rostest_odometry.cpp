// rostest of mice_odometry_node on mrt_sim: over a 20 m drive of straight
// legs and arcs the odometry stays within 1 % of the distance from the
// ground truth, with no sample flagged (no faults are injected), and the
// tf odom -> base_link (~publish_tf) carries the odometry's pose.
#include <cmath>

#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <mrt_msgs/MiceErrorStats.h>
#include <nav_msgs/Odometry.h>
#include <tf2_msgs/TFMessage.h>
#include <ros/ros.h>

#include "mrt_common/pose2d.h"

namespace {

using mrt::common::Pose2D;

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

Pose2D pose_of(const nav_msgs::Odometry& m) {
  return Pose2D(m.pose.pose.position.x, m.pose.pose.position.y, yaw_of(m.pose.pose.orientation));
}

TEST(MiceOdometryNode, Follows20mDriveWithin1Percent) {
  ros::NodeHandle nh, pnh("~");
  std::string robot;
  double distance;
  pnh.param("robot", robot, std::string("robot1"));
  pnh.param("distance", distance, 20.0);
  nav_msgs::Odometry gt, odom;
  mrt_msgs::MiceErrorStats stats;
  bool have_gt = false, have_odom = false, have_stats = false;
  double gt_path = 0.0;
  Pose2D gt_last;
  auto sub_gt = nh.subscribe<nav_msgs::Odometry>("/" + robot + "/ground_truth", 1000,
                                                 [&](const nav_msgs::Odometry::ConstPtr& m) {
                                                   const Pose2D p = pose_of(*m);
                                                   if (have_gt) gt_path += std::hypot(p.x - gt_last.x, p.y - gt_last.y);
                                                   gt_last = p;
                                                   gt = *m;
                                                   have_gt = true;
                                                 });
  auto sub_odom = nh.subscribe<nav_msgs::Odometry>("/" + robot + "/odom", 1000,
                                                   [&](const nav_msgs::Odometry::ConstPtr& m) {
                                                     odom = *m;
                                                     have_odom = true;
                                                   });
  auto sub_stats = nh.subscribe<mrt_msgs::MiceErrorStats>(
      "/" + robot + "/mice_errors", 1000, [&](const mrt_msgs::MiceErrorStats::ConstPtr& m) {
        stats = *m;
        have_stats = true;
      });
  auto cmd = nh.advertise<geometry_msgs::Twist>("/" + robot + "/cmd_vel", 10);

  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::ok() && ros::WallTime::now() < give_up &&
         (!have_gt || !have_odom || cmd.getNumSubscribers() == 0)) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  ASSERT_TRUE(have_gt) << "no ground truth";
  ASSERT_TRUE(have_odom) << "no odometry from mice_odometry_node";
  ASSERT_GT(cmd.getNumSubscribers(), 0u);
  const Pose2D gt0 = pose_of(gt);
  const Pose2D odom0 = pose_of(odom);
  gt_path = 0.0;

  // 1 m/s: straight, left arc, right arc, straight, until `distance` is done.
  const ros::Time t0 = ros::Time::now();
  const ros::WallTime wall_limit = ros::WallTime::now() + ros::WallDuration(60.0);
  while (ros::ok() && gt_path < distance && ros::WallTime::now() < wall_limit) {
    const double t = (ros::Time::now() - t0).toSec();
    geometry_msgs::Twist tw;
    tw.linear.x = 1.0;
    tw.angular.z = t < 5 ? 0.0 : t < 10 ? 0.4 : t < 15 ? -0.3 : 0.0;
    cmd.publish(tw);
    ros::spinOnce();
    ros::WallDuration(0.002).sleep();
  }
  ASSERT_GE(gt_path, distance) << "the drive did not finish";
  // Stop and let the last samples arrive: 0.5 s of sim time, and until the
  // odometry and the ground truth have both caught up with the stop (on a
  // loaded machine the odometry node may be some samples behind).
  const ros::Time stop = ros::Time::now();
  const ros::Time settled = stop + ros::Duration(0.3);
  while (ros::ok() &&
         ((ros::Time::now() - stop).toSec() < 0.5 || odom.header.stamp < settled || gt.header.stamp < settled) &&
         ros::WallTime::now() < wall_limit + ros::WallDuration(10.0)) {
    cmd.publish(geometry_msgs::Twist());
    ros::spinOnce();
    ros::WallDuration(0.002).sleep();
  }
  const Pose2D truth = gt0.inverse() * pose_of(gt);
  const Pose2D est = odom0.inverse() * pose_of(odom);
  const double err = std::hypot(est.x - truth.x, est.y - truth.y);
  RecordProperty("position_error_m", std::to_string(err));
  std::printf("drive %.3f m: odometry (%.4f, %.4f, %.4f), truth (%.4f, %.4f, %.4f), error %.4f m (%.3f %%)\n",
              gt_path, est.x, est.y, est.theta, truth.x, truth.y, truth.theta, err,
              100.0 * err / gt_path);
  EXPECT_LT(err, 0.01 * gt_path);
  EXPECT_LT(std::fabs(mrt::common::angle_diff(est.theta, truth.theta)), 0.01);
  EXPECT_NEAR(stats.distance, gt_path, 0.01 * gt_path);
  ASSERT_TRUE(have_stats);
  EXPECT_EQ(stats.flagged_samples, 0u);
  EXPECT_GT(stats.samples, 900u);
  EXPECT_EQ(odom.header.frame_id, robot + "/odom");
  EXPECT_EQ(odom.child_frame_id, robot + "/base_link");
  EXPECT_GT(odom.pose.covariance[0], 0.0);
  // tf (~publish_tf), listened to only now so that the simulator's busy
  // /tf does not slow the drive down: the robot stands still, the tf and
  // the odometry hold the same pose.
  geometry_msgs::TransformStamped tf;
  int n_tf = 0;
  auto sub_tf = nh.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
    for (const auto& t : m->transforms)
      if (t.header.frame_id == robot + "/odom" && t.child_frame_id == robot + "/base_link") {
        tf = t;
        ++n_tf;
      }
  });
  const ros::WallTime tf_limit = ros::WallTime::now() + ros::WallDuration(10.0);
  while (ros::ok() && n_tf < 5 && ros::WallTime::now() < tf_limit) {
    cmd.publish(geometry_msgs::Twist());
    ros::spinOnce();
    ros::WallDuration(0.002).sleep();
  }
  ASSERT_GE(n_tf, 5) << "no tf " << robot << "/odom -> " << robot << "/base_link";
  EXPECT_NEAR(tf.transform.translation.x, odom.pose.pose.position.x, 1e-9);
  EXPECT_NEAR(tf.transform.translation.y, odom.pose.pose.position.y, 1e-9);
  EXPECT_NEAR(tf.transform.rotation.z, odom.pose.pose.orientation.z, 1e-9);
  EXPECT_NEAR(tf.transform.rotation.w, odom.pose.pose.orientation.w, 1e-9);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mice_odometry_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
