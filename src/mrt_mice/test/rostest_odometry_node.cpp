// rostest of mice_odometry_node fed by hand: 10 samples turning 0.03 rad in
// place, 10 samples of 1 cm straight ahead (manual placement, D = 0.2 m,
// 10000 counts/m), one inconsistent sample and one malformed one; a stamp
// far in the past (a bag loop) resets the odometry; when the readings stop
// the diagnostics say so and the pose stays where it was.
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <mrt_msgs/MiceErrorStats.h>
#include <mrt_msgs/MiceReading.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::ros_common::wait_for;

// The node's outputs as they arrive, and a publisher of readings 20 ms apart.
class MiceOdometryNode : public ::testing::Test {
 protected:
  void SetUp() override {
    so_ = nh_.subscribe<nav_msgs::Odometry>("/odom", 100, [this](const nav_msgs::Odometry::ConstPtr& m) {
      odom = *m;
      ++n_odom;
    });
    ss_ = nh_.subscribe<mrt_msgs::MiceErrorStats>(
        "/mice_errors", 100, [this](const mrt_msgs::MiceErrorStats::ConstPtr& m) { stats = *m; });
    sd_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 10, [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& d) { on_diag(*d); });
    pub_ = nh_.advertise<mrt_msgs::MiceReading>("/mice", 100);
    ASSERT_TRUE(wait_for([&] { return pub_.getNumSubscribers() > 0 && so_.getNumPublishers() > 0; }, 20.0));
    ros::WallDuration(0.3).sleep();
  }

  void on_diag(const diagnostic_msgs::DiagnosticArray& d) {
    for (const auto& s : d.status) {
      if (s.name.find("mice odometry") == std::string::npos) continue;
      level = s.level;
      summary = s.message;
      for (const auto& kv : s.values) {
        if (kv.key == "dropped (malformed)") dropped = kv.value;
        if (kv.key == "resets (time jumped back)") resets = kv.value;
      }
    }
  }

  void send(int ldx, int ldy, int rdx, int rdy) {
    mrt_msgs::MiceReading r;
    t += ros::Duration(0.02);
    r.header.stamp = t;
    r.left.dx = ldx;
    r.left.dy = ldy;
    r.right.dx = rdx;
    r.right.dy = rdy;
    pub_.publish(r);
  }

  void turn_then_ahead() {
    for (int i = 0; i < 10; ++i) send(0, -30, 0, 30);   // 0.03 rad ccw in place
    for (int i = 0; i < 10; ++i) send(0, 100, 0, 100);  // 1 cm ahead
    ASSERT_TRUE(wait_for([&] { return n_odom == 20; }, 10.0)) << n_odom;
    EXPECT_NEAR(odom.pose.pose.position.x, 0.1 * std::cos(0.3), 1e-9);
    EXPECT_NEAR(odom.pose.pose.position.y, 0.1 * std::sin(0.3), 1e-9);
    EXPECT_NEAR(2.0 * std::atan2(odom.pose.pose.orientation.z, odom.pose.pose.orientation.w), 0.3, 1e-9);
    EXPECT_NEAR(odom.twist.twist.linear.x, 0.5, 1e-6);  // 1 cm in 20 ms
    EXPECT_EQ(odom.header.frame_id, "odom");
    EXPECT_EQ(odom.child_frame_id, "base_link");
    EXPECT_FALSE(stats.flagged);
    EXPECT_EQ(stats.samples, 20u);
    EXPECT_NEAR(stats.distance, 0.1, 1e-9);
  }

  void inconsistent_sample() {
    const double var_before = odom.pose.covariance[0];
    EXPECT_GT(var_before, 0.0);
    send(40, 100, 0, 100);  // x_l != x_r by 4 mm: inconsistent
    ASSERT_TRUE(wait_for([&] { return n_odom == 21; }, 10.0));
    EXPECT_TRUE(stats.flagged);
    EXPECT_NEAR(stats.residual, -0.004, 1e-12);
    EXPECT_NE(stats.correction, "none");
    EXPECT_EQ(stats.flagged_samples, 1u);
    EXPECT_GT(odom.pose.covariance[0], var_before + 1e-4);  // (3 * 4 mm)^2 more
  }

  void malformed_and_late_samples() {
    send(0, 60000, 0, 60000);  // beyond ~max_count: malformed, dropped
    send(0, 100, 0, 100);
    ASSERT_TRUE(wait_for([&] { return n_odom == 22; }, 10.0));
    wait_for([&] { return false; }, 0.3);
    EXPECT_EQ(n_odom, 22);
    EXPECT_EQ(stats.samples, 22u);
    EXPECT_TRUE(wait_for([&] { return dropped == "1"; }, 5.0)) << dropped;

    // 0.5 s back (below ~time_jump_reset = 1 s): dropped, not integrated.
    t -= ros::Duration(0.52);
    send(0, 100, 0, 100);
    t += ros::Duration(0.5);
    wait_for([&] { return false; }, 0.3);
    EXPECT_EQ(n_odom, 22);
    EXPECT_TRUE(wait_for([&] { return dropped == "2"; }, 5.0)) << dropped;
  }

  // A bag loop: 50 s back. The odometry starts again from the origin with
  // this sample: 1 cm ahead, one sample, nothing flagged.
  void time_jumps_back() {
    t -= ros::Duration(50.0);
    send(0, 100, 0, 100);
    ASSERT_TRUE(wait_for([&] { return n_odom == 23; }, 10.0));
    EXPECT_NEAR(odom.pose.pose.position.x, 0.01, 1e-12);
    EXPECT_NEAR(odom.pose.pose.position.y, 0.0, 1e-12);
    EXPECT_NEAR(odom.pose.pose.orientation.z, 0.0, 1e-12);
    EXPECT_EQ(stats.samples, 1u);
    EXPECT_EQ(stats.flagged_samples, 0u);
    EXPECT_NEAR(odom.header.stamp.toSec(), t.toSec(), 1e-6);
    EXPECT_TRUE(wait_for([&] { return resets == "1"; }, 5.0)) << resets;
  }

  // Readings stop: after ~stale_timeout (0.5 s here) the diagnostics say
  // ERROR "no mice readings for X s"; nothing is extrapolated meanwhile.
  // Readings come back: OK again, the pose goes on from where it stopped
  // (one every 0.1 s for 2 s, so that a 1 Hz diagnostics update sees them).
  void readings_stop_and_resume() {
    EXPECT_TRUE(wait_for([&] { return level == diagnostic_msgs::DiagnosticStatus::ERROR; }, 5.0))
        << level << " " << summary;
    EXPECT_EQ(summary.rfind("no mice readings for ", 0), 0u) << summary;
    const double stale_for = std::atof(summary.c_str() + std::strlen("no mice readings for "));
    EXPECT_GT(stale_for, 0.5) << summary;
    EXPECT_LT(stale_for, 10.0) << summary;
    EXPECT_EQ(n_odom, 23);
    bool ok_seen = false;
    for (int i = 0; i < 20; ++i) {
      send(0, 100, 0, 100);
      ok_seen = wait_for([&] { return level == diagnostic_msgs::DiagnosticStatus::OK; }, 0.1) || ok_seen;
    }
    ASSERT_TRUE(wait_for([&] { return n_odom == 43; }, 10.0)) << n_odom;
    EXPECT_NEAR(odom.pose.pose.position.x, 0.01 * 21, 1e-12);
    EXPECT_TRUE(ok_seen || wait_for([&] { return level == diagnostic_msgs::DiagnosticStatus::OK; }, 0.3))
        << level << " " << summary;
  }

  ros::NodeHandle nh_;
  ros::Subscriber so_, ss_, sd_;
  ros::Publisher pub_;
  ros::Time t{100.0};
  int n_odom = 0;
  nav_msgs::Odometry odom;
  mrt_msgs::MiceErrorStats stats;
  std::string dropped, resets, summary;
  int level = -1;
};

TEST_F(MiceOdometryNode, HandComputedReadings) {
  ASSERT_NO_FATAL_FAILURE(turn_then_ahead());
  ASSERT_NO_FATAL_FAILURE(inconsistent_sample());
  ASSERT_NO_FATAL_FAILURE(malformed_and_late_samples());
  ASSERT_NO_FATAL_FAILURE(time_jumps_back());
  readings_stop_and_resume();
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mice_odometry_node_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
