// The fixture of the airboard_node rostests (rostest_airboard.cpp): the
// emulator as a child process, the diagnostics recorder, and the test class
// that drives the node and records what it publishes.
#pragma once

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <mrt_msgs/AirboardStatus.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/WheelCommand.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <algorithm>
#include <cstring>
#include <limits>
#include <cerrno>
#include <csignal>
#include <cmath>
#include <cstdint>
#include <fcntl.h>
#include <pty.h>
#include <string>
#include <sys/prctl.h>
#include <termios.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>
#include "mrt_common/pose2d.h"
#include "mrt_common_ros/rostest_helpers.h"

namespace airboard_test {

using mrt::common::Pose2D;

using mrt::ros_common::wait_for;

// The emulator as a child process of the test (reconnect.test): started with
// fork/exec on the node's port path, always stopped by the destructor.
class EmulatorProcess {
 public:
  ~EmulatorProcess() { stop(); }
  void start(const std::string& link) {
    stop();
    pid_ = ::fork();
    if (pid_ == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // never outlive a crashed test
      ::execl(AIRBOARD_EMULATOR, AIRBOARD_EMULATOR, "--link", link.c_str(), "--motors", "2", "--cpr", "8192", "--baud", "115200",
              static_cast<char*>(nullptr));
      ::_exit(127);
    }
  }
  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
};

struct Sample {
  double t;
  Pose2D pose;
  double vx, vy, omega;
};

// The node's two diagnostic entries ("<node>: AIRBoard link" / "... motors")
// as they arrive on /diagnostics.
class DiagRecorder {
 public:
  explicit DiagRecorder(ros::NodeHandle& nh) : sub_(nh.subscribe("/diagnostics", 100, &DiagRecorder::on, this)) {}
  std::vector<diagnostic_msgs::DiagnosticStatus> link, motors;
  static std::string value(const diagnostic_msgs::DiagnosticStatus& d, const std::string& key) {
    for (const auto& kv : d.values)
      if (kv.key == key) return kv.value;
    ADD_FAILURE() << "no key '" << key << "' in diagnostic entry '" << d.name << "'";
    return "";
  }
  static double number(const diagnostic_msgs::DiagnosticStatus& d, const std::string& key) {
    const std::string v = value(d, key);
    return v.empty() ? -1.0 : std::stod(v);
  }

 private:
  static bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
  }
  void on(const diagnostic_msgs::DiagnosticArray& a) {
    for (const auto& d : a.status) {
      if (ends_with(d.name, "AIRBoard link")) link.push_back(d);
      if (ends_with(d.name, "AIRBoard motors")) motors.push_back(d);
    }
  }
  ros::Subscriber sub_;
};

class Airboard : public ::testing::Test {
 protected:
  void SetUp() override {
    cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    odom_sub_ = nh_.subscribe("odom", 1000, &Airboard::on_odom, this);
    status_sub_ = nh_.subscribe("airboard_status", 1000, &Airboard::on_status, this);
    wheel_sub_ = nh_.subscribe("wheel_state", 1000, &Airboard::on_wheels, this);
    pnh_.param("vx", vx_, 0.3);
    pnh_.param("vy", vy_, 0.0);
    pnh_.param("omega", omega_, 0.5);
    if (pnh_.getParam("start_emulator", emu_link_)) emu_.start(emu_link_);
    // Wait for the node to be connected to the emulator.
    ASSERT_TRUE(wait_for([&] { return connected_; }, 20.0)) << "airboard_node never connected to the emulator";
  }

  // Publishes the twist at 50 Hz for `seconds` of wall time.
  void drive(double seconds, double vx, double vy, double omega) {
    geometry_msgs::Twist t;
    t.linear.x = vx;
    t.linear.y = vy;
    t.angular.z = omega;
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      cmd_pub_.publish(t);
      ros::spinOnce();
      ros::WallDuration(0.02).sleep();
    }
  }

  void on_odom(const nav_msgs::Odometry& m) {
    const auto& q = m.pose.pose.orientation;
    odom_.push_back({m.header.stamp.toSec(),
                     Pose2D(m.pose.pose.position.x, m.pose.pose.position.y, 2.0 * std::atan2(q.z, q.w)),
                     m.twist.twist.linear.x, m.twist.twist.linear.y, m.twist.twist.angular.z});
  }
  void on_status(const mrt_msgs::AirboardStatus& s) {
    if (s.connected && s.board_time > 0.0) connected_ = true;
    status_.push_back(s);
  }
  void on_wheels(const mrt_msgs::WheelState& w) { wheels_.push_back(w); }

  EmulatorProcess emu_;
  std::string emu_link_;
  ros::NodeHandle nh_, pnh_{"~"};
  DiagRecorder diag_{nh_};
  ros::Publisher cmd_pub_;
  ros::Subscriber odom_sub_, status_sub_, wheel_sub_;
  double vx_ = 0, vy_ = 0, omega_ = 0;
  bool connected_ = false;
  std::vector<Sample> odom_;
  std::vector<mrt_msgs::AirboardStatus> status_;
  std::vector<mrt_msgs::WheelState> wheels_;
};

}  // namespace airboard_test
