// The ROS interface of one simulated robot: its subscriptions (cmd_vel,
// wheel_cmd), its device topics and ground truth, in namespace /<robot>/.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/WheelCommand.h>
#include <ros/ros.h>

#include "camera_interface.h"
#include "conversions.h"
#include "markers.h"
#include "mrt_sim/simulator.h"
#include "node_options.h"

namespace mrt::sim::node {

class RobotInterface {
 public:
  /// Advertises and subscribes in the namespace `<nh namespace>/<robot name>`.
  RobotInterface(ros::NodeHandle& nh, Simulator& sim, std::size_t index, const NodeOptions& opt);

  const std::string& name() const { return name_; }
  const RobotFrames& frames() const { return frames_; }

  /// Before a step: stops the wheels when no command came for cmd_timeout.
  void apply_watchdog();

  /// After a step stamped `stamp`: publishes every sensor that is ready, and
  /// the ground truth (appending its transform to `tfs`) when `ground_truth`.
  void publish(const ros::Time& stamp, bool ground_truth, bool path,
               std::vector<geometry_msgs::TransformStamped>& tfs);

  /// Fixed transforms from the sensor parent frame to the sonar, mouse and
  /// gps frames; none for a robot in ~description_robots (its
  /// robot_state_publisher publishes them from the URDF).
  void static_transforms(std::vector<geometry_msgs::TransformStamped>& out) const;

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) const;

 private:
  RobotState& state() { return sim_.robots()[index_]; }
  const RobotState& state() const { return sim_.robots()[index_]; }
  void on_cmd_vel(const geometry_msgs::Twist::ConstPtr& msg);
  void on_wheel_cmd(const mrt_msgs::WheelCommand::ConstPtr& msg);
  void accepted();
  void dropped(const std::string& why);

  Simulator& sim_;
  std::size_t index_;
  const NodeOptions& opt_;
  std::string name_;
  RobotFrames frames_;

  ros::Subscriber cmd_vel_sub_, wheel_cmd_sub_;
  ros::Publisher ground_truth_pub_, path_pub_, mice_pub_, wheel_state_pub_, percepts_pub_,
      percept_markers_pub_, dgps_pub_, joint_state_pub_;
  std::vector<ros::Publisher> sonar_pubs_;

  std::unique_ptr<CameraInterface> camera_;  // when the robot has a camera

  std::deque<geometry_msgs::PoseStamped> trail_;

  bool commanded_ = false;    // a command is active (not yet timed out)
  bool watchdog_ = false;     // the wheels were stopped by the watchdog
  double last_cmd_time_ = 0.0;
  std::uint64_t commands_ = 0, dropped_ = 0, timeouts_ = 0;
  std::uint64_t mouse_faults_ = 0;
  std::string last_drop_reason_;
};

}  // namespace mrt::sim::node
