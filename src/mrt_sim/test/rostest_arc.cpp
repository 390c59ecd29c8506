// rostest of sim_node: a constant twist moves the robot along the analytic
// arc, and the wheels stop when commands stop for ~cmd_timeout.
//
// Exactness: the node applies a command received between two steps during
// the next step and stamps every message with the sim time after the step,
// and with ~ground_truth_rate = ~rate_hz every step's pose is published. So
// the last stationary message has the stamp t0 at which motion started, and
// a message stamped t must show the pose reached after exactly t - t0 of
// constant-twist motion.
#include <cmath>
#include <cstdio>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <mrt_msgs/WheelCommand.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

struct Pose {
  double x, y, th;
};

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

Pose pose_of(const nav_msgs::Odometry& m) {
  return {m.pose.pose.position.x, m.pose.pose.position.y, yaw_of(m.pose.pose.orientation)};
}

double wrap(double a) { return std::remainder(a, 2.0 * M_PI); }

bool same_pose(const Pose& a, const Pose& b) {
  return std::fabs(a.x - b.x) < 1e-12 && std::fabs(a.y - b.y) < 1e-12 &&
         std::fabs(wrap(a.th - b.th)) < 1e-12;
}

class ArcTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ros::NodeHandle pnh("~");
    pnh.param("robot", robot_, std::string("robot1"));
    pnh.param("rate_hz", rate_hz_, 1000.0);
    pnh.param("cmd_timeout", cmd_timeout_, 1.0);
    gt_sub_ = nh_.subscribe("/" + robot_ + "/ground_truth", 20000, &ArcTest::on_gt, this,
                            ros::TransportHints().tcpNoDelay());
    ws_sub_ = nh_.subscribe("/" + robot_ + "/wheel_state", 1000, &ArcTest::on_ws, this);
    cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("/" + robot_ + "/cmd_vel", 10);
    // Wait for the simulator: ground truth flowing and our command subscribed.
    mrt::ros_common::wait_for([&] { return !gt_.empty() && cmd_pub_.getNumSubscribers() > 0 && !ws_.empty(); },
                              30.0);
    ASSERT_FALSE(gt_.empty()) << "no ground truth from sim_node";
    ASSERT_GT(cmd_pub_.getNumSubscribers(), 0u) << "sim_node does not subscribe to cmd_vel";
  }

  void on_gt(const nav_msgs::Odometry::ConstPtr& m) { gt_.push_back(*m); }
  void on_ws(const mrt_msgs::WheelState::ConstPtr& m) { ws_.push_back(*m); }

  double dt() const { return 1.0 / rate_hz_; }

  // Spins (publishing `cmd` every 20 ms of wall time when `drive`) until
  // `done()` or a wall timeout.
  template <class Done>
  bool spin_until(Done done, bool drive, const geometry_msgs::Twist& cmd, double timeout) {
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(timeout);
    ros::WallTime next_cmd = ros::WallTime::now();
    while (ros::ok() && ros::WallTime::now() < give_up) {
      if (drive && ros::WallTime::now() >= next_cmd) {
        cmd_pub_.publish(cmd);
        next_cmd += ros::WallDuration(0.02);
      }
      ros::spinOnce();
      if (done()) return true;
      ros::WallDuration(0.001).sleep();
    }
    return false;
  }

  ros::NodeHandle nh_;
  std::string robot_;
  double rate_hz_ = 1000.0, cmd_timeout_ = 1.0;
  ros::Subscriber gt_sub_, ws_sub_;
  ros::Publisher cmd_pub_;
  std::vector<nav_msgs::Odometry> gt_;
  std::vector<mrt_msgs::WheelState> ws_;
};

// Index of the first message whose pose differs from the one before it, at
// or after `from`; gt.size() if none.
std::size_t first_motion(const std::vector<nav_msgs::Odometry>& gt, std::size_t from) {
  for (std::size_t i = std::max<std::size_t>(from, 1); i < gt.size(); ++i)
    if (!same_pose(pose_of(gt[i - 1]), pose_of(gt[i]))) return i;
  return gt.size();
}

TEST_F(ArcTest, ConstantTwistFollowsAnalyticArc) {
  const double v = 0.4, w = 0.3, duration = 5.0;
  geometry_msgs::Twist cmd;
  cmd.linear.x = v;
  cmd.angular.z = w;
  const std::size_t start = gt_.size() - 1;  // a message before our first command
  auto covered = [&] {
    const std::size_t i1 = first_motion(gt_, start + 1);
    return i1 < gt_.size() && (gt_.back().header.stamp - gt_[i1 - 1].header.stamp).toSec() > duration + 0.05;
  };
  ASSERT_TRUE(spin_until(covered, true, cmd, 60.0)) << "did not see " << duration << " s of motion";

  const std::size_t i1 = first_motion(gt_, start + 1);
  const Pose p0 = pose_of(gt_[i1 - 1]);
  const double t0 = gt_[i1 - 1].header.stamp.toSec();
  EXPECT_EQ(gt_[i1 - 1].header.frame_id, "world");
  EXPECT_EQ(gt_[i1 - 1].child_frame_id, robot_ + "/base_link_truth");

  double max_err = 0.0, max_heading_err = 0.0, last_t = 0.0;
  std::size_t checked = 0;
  for (std::size_t j = i1; j < gt_.size(); ++j) {
    const double t = gt_[j].header.stamp.toSec() - t0;
    if (t > duration + 1e-9) break;
    // Consecutive steps, none lost: stamps advance by exactly one step.
    ASSERT_NEAR(gt_[j].header.stamp.toSec() - gt_[j - 1].header.stamp.toSec(), dt(), 1e-6) << "at t=" << t;
    const double lx = v / w * std::sin(w * t), ly = v / w * (1.0 - std::cos(w * t));
    const double ex = p0.x + std::cos(p0.th) * lx - std::sin(p0.th) * ly;
    const double ey = p0.y + std::sin(p0.th) * lx + std::cos(p0.th) * ly;
    const Pose p = pose_of(gt_[j]);
    const double err = std::hypot(p.x - ex, p.y - ey);
    const double herr = std::fabs(wrap(p.th - (p0.th + w * t)));
    max_err = std::max(max_err, err);
    max_heading_err = std::max(max_heading_err, herr);
    EXPECT_LT(err, 1e-3) << "at t=" << t;
    EXPECT_LT(herr, 1e-3) << "at t=" << t;
    // The reported body twist is the commanded one.
    EXPECT_NEAR(gt_[j].twist.twist.linear.x, v, 1e-9);
    EXPECT_NEAR(gt_[j].twist.twist.angular.z, w, 1e-9);
    last_t = t;
    ++checked;
  }
  EXPECT_NEAR(last_t, duration, dt() + 1e-9);
  EXPECT_EQ(checked, static_cast<std::size_t>(std::lround(duration * rate_hz_)));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", max_err);
  RecordProperty("max_position_error_m", buf);
  std::snprintf(buf, sizeof buf, "%.3g", max_heading_err);
  RecordProperty("max_heading_error_rad", buf);
  std::printf("arc: %zu poses over %.3f s, max position error %.3g m, max heading error %.3g rad\n",
              checked, last_t, max_err, max_heading_err);
}

TEST_F(ArcTest, WheelsStopAfterCommandTimeout) {
  // Let the previous test's motion time out, then send a single command.
  const geometry_msgs::Twist none;
  auto at_rest = [&] {
    return gt_.size() > 2 && gt_.back().twist.twist.linear.x == 0.0 && gt_.back().twist.twist.angular.z == 0.0;
  };
  ASSERT_TRUE(spin_until(at_rest, false, none, 30.0));
  const std::size_t start = gt_.size() - 1;
  geometry_msgs::Twist cmd;
  cmd.linear.x = 0.2;
  cmd_pub_.publish(cmd);
  auto stopped_again = [&] {
    const std::size_t i1 = first_motion(gt_, start + 1);
    return i1 < gt_.size() && gt_.back().twist.twist.linear.x == 0.0 &&
           (gt_.back().header.stamp - gt_[i1].header.stamp).toSec() > 0.1;
  };
  ASSERT_TRUE(spin_until(stopped_again, false, none, 30.0)) << "the robot never stopped";
  const std::size_t i1 = first_motion(gt_, start + 1);
  std::size_t i2 = i1;
  while (i2 < gt_.size() && gt_[i2].twist.twist.linear.x != 0.0) ++i2;
  ASSERT_LT(i2, gt_.size());
  // Moved during steps stamped (t0, t2]: exactly cmd_timeout of sim time.
  const double moving = (gt_[i2 - 1].header.stamp - gt_[i1 - 1].header.stamp).toSec();
  EXPECT_NEAR(moving, cmd_timeout_, 1.5 * dt());
  const Pose a = pose_of(gt_[i1 - 1]), b = pose_of(gt_[i2]);
  EXPECT_NEAR(std::hypot(b.x - a.x, b.y - a.y), cmd.linear.x * cmd_timeout_, 1e-3);

  // The wheel state reports the watchdog once it has fired.
  const double t_stop = gt_[i2].header.stamp.toSec();
  auto ws_after = [&] { return !ws_.empty() && ws_.back().header.stamp.toSec() > t_stop + 0.05; };
  ASSERT_TRUE(spin_until(ws_after, false, none, 10.0));
  const mrt_msgs::WheelState& s = ws_.back();
  ASSERT_FALSE(s.status.empty());
  EXPECT_TRUE(s.status[0] & mrt_msgs::WheelState::STATUS_WATCHDOG);
  for (double sp : s.speed) EXPECT_EQ(sp, 0.0);
}

TEST_F(ArcTest, WheelCommandOfWrongSizeIsDroppedAndCounted) {
  const geometry_msgs::Twist none;
  auto at_rest = [&] { return gt_.size() > 2 && gt_.back().twist.twist.linear.x == 0.0; };
  ASSERT_TRUE(spin_until(at_rest, false, none, 30.0));
  std::vector<diagnostic_msgs::DiagnosticStatus> diag;
  ros::Subscriber diag_sub = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
        for (const auto& st : m->status)
          if (st.name.find("robot " + robot_) != std::string::npos) diag.push_back(st);
      });
  ros::Publisher wheel_pub = nh_.advertise<mrt_msgs::WheelCommand>("/" + robot_ + "/wheel_cmd", 10);
  auto connected = [&] { return wheel_pub.getNumSubscribers() > 0; };
  ASSERT_TRUE(spin_until(connected, false, none, 10.0));

  // Three wheels for a two-wheel base: dropped, the robot stays put.
  mrt_msgs::WheelCommand bad;
  bad.mode = mrt_msgs::WheelCommand::MODE_SPEED;
  bad.speed = {5.0, 5.0, 5.0};
  wheel_pub.publish(bad);
  const std::size_t start = gt_.size();
  const double t_bad = gt_.back().header.stamp.toSec();
  auto later = [&] { return gt_.back().header.stamp.toSec() > t_bad + 0.3; };
  ASSERT_TRUE(spin_until(later, false, none, 10.0));
  EXPECT_EQ(first_motion(gt_, start), gt_.size()) << "a malformed wheel_cmd moved the robot";

  // Diagnostics count it.
  auto counted = [&] {
    for (const auto& st : diag)
      for (const auto& kv : st.values)
        if (kv.key == "commands dropped" && kv.value != "0") return true;
    return false;
  };
  EXPECT_TRUE(spin_until(counted, false, none, 10.0)) << "no dropped command in /diagnostics";

  // Two equal wheel speeds: straight at wheel speed x wheel radius (0.05 m).
  mrt_msgs::WheelCommand good = bad;
  good.speed = {4.0, 4.0};
  wheel_pub.publish(good);
  auto moving = [&] { return gt_.back().twist.twist.linear.x != 0.0; };
  ASSERT_TRUE(spin_until(moving, false, none, 10.0));
  EXPECT_NEAR(gt_.back().twist.twist.linear.x, 4.0 * 0.05, 1e-9);
  EXPECT_NEAR(gt_.back().twist.twist.angular.z, 0.0, 1e-12);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "arc_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
