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
#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::common::Pose2D;
using mrt::ros_common::wait_for;

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

Pose2D pose_of(const nav_msgs::Odometry& m) {
  return Pose2D(m.pose.pose.position.x, m.pose.pose.position.y, yaw_of(m.pose.pose.orientation));
}

class MiceOdometryNode : public ::testing::Test {
 protected:
  void SetUp() override {
    ros::NodeHandle pnh("~");
    pnh.param("robot", robot_, std::string("robot1"));
    pnh.param("distance", distance_, 20.0);
    sub_gt_ = nh_.subscribe<nav_msgs::Odometry>("/" + robot_ + "/ground_truth", 1000,
                                                [this](const nav_msgs::Odometry::ConstPtr& m) {
                                                  const Pose2D p = pose_of(*m);
                                                  if (have_gt_) gt_path_ += std::hypot(p.x - gt_last_.x, p.y - gt_last_.y);
                                                  gt_last_ = p;
                                                  gt_ = *m;
                                                  have_gt_ = true;
                                                });
    sub_odom_ = nh_.subscribe<nav_msgs::Odometry>("/" + robot_ + "/odom", 1000,
                                                  [this](const nav_msgs::Odometry::ConstPtr& m) {
                                                    odom_ = *m;
                                                    have_odom_ = true;
                                                  });
    sub_stats_ = nh_.subscribe<mrt_msgs::MiceErrorStats>(
        "/" + robot_ + "/mice_errors", 1000, [this](const mrt_msgs::MiceErrorStats::ConstPtr& m) {
          stats_ = *m;
          have_stats_ = true;
        });
    cmd_ = nh_.advertise<geometry_msgs::Twist>("/" + robot_ + "/cmd_vel", 10);
    wait_for([&] { return have_gt_ && have_odom_ && cmd_.getNumSubscribers() > 0; }, 30.0, 0.005);
    ASSERT_TRUE(have_gt_) << "no ground truth";
    ASSERT_TRUE(have_odom_) << "no odometry from mice_odometry_node";
    ASSERT_GT(cmd_.getNumSubscribers(), 0u);
  }

  // 1 m/s: straight, left arc, right arc, straight, until `distance` is
  // done; then stop and let the last samples arrive: 0.5 s of sim time, and
  // until the odometry and the ground truth have both caught up with the
  // stop (on a loaded machine the odometry node may be some samples behind).
  void drive_and_stop() {
    const ros::Time t0 = ros::Time::now();
    const ros::WallTime wall_limit = ros::WallTime::now() + ros::WallDuration(60.0);
    while (ros::ok() && gt_path_ < distance_ && ros::WallTime::now() < wall_limit) {
      const double t = (ros::Time::now() - t0).toSec();
      geometry_msgs::Twist tw;
      tw.linear.x = 1.0;
      tw.angular.z = t < 5 ? 0.0 : t < 10 ? 0.4 : t < 15 ? -0.3 : 0.0;
      cmd_.publish(tw);
      ros::spinOnce();
      ros::WallDuration(0.002).sleep();
    }
    ASSERT_GE(gt_path_, distance_) << "the drive did not finish";
    const ros::Time stop = ros::Time::now();
    const ros::Time settled = stop + ros::Duration(0.3);
    while (ros::ok() &&
           ((ros::Time::now() - stop).toSec() < 0.5 || odom_.header.stamp < settled || gt_.header.stamp < settled) &&
           ros::WallTime::now() < wall_limit + ros::WallDuration(10.0)) {
      cmd_.publish(geometry_msgs::Twist());
      ros::spinOnce();
      ros::WallDuration(0.002).sleep();
    }
  }

  // tf (~publish_tf), listened to only now so that the simulator's busy
  // /tf does not slow the drive down: the robot stands still, the tf and
  // the odometry hold the same pose.
  void check_tf() {
    geometry_msgs::TransformStamped tf;
    int n_tf = 0;
    auto sub_tf = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
      for (const auto& t : m->transforms)
        if (t.header.frame_id == robot_ + "/odom" && t.child_frame_id == robot_ + "/base_link") {
          tf = t;
          ++n_tf;
        }
    });
    const ros::WallTime tf_limit = ros::WallTime::now() + ros::WallDuration(10.0);
    while (ros::ok() && n_tf < 5 && ros::WallTime::now() < tf_limit) {
      cmd_.publish(geometry_msgs::Twist());
      ros::spinOnce();
      ros::WallDuration(0.002).sleep();
    }
    ASSERT_GE(n_tf, 5) << "no tf " << robot_ << "/odom -> " << robot_ << "/base_link";
    EXPECT_NEAR(tf.transform.translation.x, odom_.pose.pose.position.x, 1e-9);
    EXPECT_NEAR(tf.transform.translation.y, odom_.pose.pose.position.y, 1e-9);
    EXPECT_NEAR(tf.transform.rotation.z, odom_.pose.pose.orientation.z, 1e-9);
    EXPECT_NEAR(tf.transform.rotation.w, odom_.pose.pose.orientation.w, 1e-9);
  }

  ros::NodeHandle nh_;
  std::string robot_;
  double distance_ = 20.0;
  ros::Subscriber sub_gt_, sub_odom_, sub_stats_;
  ros::Publisher cmd_;
  nav_msgs::Odometry gt_, odom_;
  mrt_msgs::MiceErrorStats stats_;
  bool have_gt_ = false, have_odom_ = false, have_stats_ = false;
  double gt_path_ = 0.0;
  Pose2D gt_last_;
};

TEST_F(MiceOdometryNode, Follows20mDriveWithin1Percent) {
  const Pose2D gt0 = pose_of(gt_);
  const Pose2D odom0 = pose_of(odom_);
  gt_path_ = 0.0;
  ASSERT_NO_FATAL_FAILURE(drive_and_stop());
  const Pose2D truth = gt0.inverse() * pose_of(gt_);
  const Pose2D est = odom0.inverse() * pose_of(odom_);
  const double err = std::hypot(est.x - truth.x, est.y - truth.y);
  RecordProperty("position_error_m", std::to_string(err));
  std::printf("drive %.3f m: odometry (%.4f, %.4f, %.4f), truth (%.4f, %.4f, %.4f), error %.4f m (%.3f %%)\n",
              gt_path_, est.x, est.y, est.theta, truth.x, truth.y, truth.theta, err, 100.0 * err / gt_path_);
  EXPECT_LT(err, 0.01 * gt_path_);
  EXPECT_LT(std::fabs(mrt::common::angle_diff(est.theta, truth.theta)), 0.01);
  EXPECT_NEAR(stats_.distance, gt_path_, 0.01 * gt_path_);
  ASSERT_TRUE(have_stats_);
  EXPECT_EQ(stats_.flagged_samples, 0u);
  EXPECT_GT(stats_.samples, 900u);
  EXPECT_EQ(odom_.header.frame_id, robot_ + "/odom");
  EXPECT_EQ(odom_.child_frame_id, robot_ + "/base_link");
  EXPECT_GT(odom_.pose.covariance[0], 0.0);
  check_tf();
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mice_odometry_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
