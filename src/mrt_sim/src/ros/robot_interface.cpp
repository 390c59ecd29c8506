#include "robot_interface.h"

#include <algorithm>
#include <cmath>

#include <mrt_msgs/MiceReading.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/Range.h>
#include <visualization_msgs/MarkerArray.h>

namespace mrt::sim::node {

RobotInterface::RobotInterface(ros::NodeHandle& nh, Simulator& sim, std::size_t index,
                               const NodeOptions& opt)
    : sim_(sim), index_(index), opt_(opt) {
  const RobotConfig& cfg = state().config;
  name_ = cfg.name;
  frames_ = make_frames(opt.frame_prefix, name_, opt.sensor_parent);
  ros::NodeHandle rnh(nh, name_);

  cmd_vel_sub_ = rnh.subscribe("cmd_vel", 10, &RobotInterface::on_cmd_vel, this,
                               ros::TransportHints().tcpNoDelay());
  wheel_cmd_sub_ = rnh.subscribe("wheel_cmd", 10, &RobotInterface::on_wheel_cmd, this,
                                 ros::TransportHints().tcpNoDelay());

  ground_truth_pub_ = rnh.advertise<nav_msgs::Odometry>("ground_truth", 100);
  path_pub_ = rnh.advertise<nav_msgs::Path>("ground_truth_path", 1);
  wheel_state_pub_ = rnh.advertise<mrt_msgs::WheelState>("wheel_state", 50);
  if (opt.joint_states_for(name_)) joint_state_pub_ = rnh.advertise<sensor_msgs::JointState>("joint_states", 50);
  const SensorsConfig& s = cfg.sensors;
  if (s.rate_mice > 0.0 && !s.mice.empty())
    mice_pub_ = rnh.advertise<mrt_msgs::MiceReading>("mice", 100);
  if (s.rate_vision > 0.0) {
    percepts_pub_ = rnh.advertise<mrt_msgs::Percept>("percepts", 20);
    percept_markers_pub_ = rnh.advertise<visualization_msgs::MarkerArray>("percept_markers", 5);
  }
  if (s.rate_sonar > 0.0)
    for (std::size_t i = 0; i < s.sonars.size(); ++i)
      sonar_pubs_.push_back(rnh.advertise<sensor_msgs::Range>("sonar/" + std::to_string(i), 20));
  if (s.rate_dgps > 0.0) dgps_pub_ = rnh.advertise<sensor_msgs::NavSatFix>("dgps/fix", 20);
  if (s.camera.rate > 0.0) camera_ = std::make_unique<CameraInterface>(rnh, sim_, index_, frames_.prefix);
}

void RobotInterface::accepted() {
  ++commands_;
  commanded_ = true;
  watchdog_ = false;
  last_cmd_time_ = sim_.time();
}

void RobotInterface::dropped(const std::string& why) {
  ++dropped_;
  last_drop_reason_ = why;
  ROS_WARN_THROTTLE(1.0, "%s: dropped a command (%s); %llu dropped so far", name_.c_str(),
                    why.c_str(), static_cast<unsigned long long>(dropped_));
}

void RobotInterface::on_cmd_vel(const geometry_msgs::Twist::ConstPtr& msg) {
  const Twist2D t{msg->linear.x, msg->linear.y, msg->angular.z};
  if (!std::isfinite(t.vx) || !std::isfinite(t.vy) || !std::isfinite(t.omega)) {
    dropped("cmd_vel with a non-finite component");
    return;
  }
  sim_.set_twist(index_, t);
  accepted();
}

void RobotInterface::on_wheel_cmd(const mrt_msgs::WheelCommand::ConstPtr& msg) {
  const BaseConfig& base = state().config.base;
  const std::size_t n = base.wheel_count();
  std::vector<double> w;
  if (msg->mode == mrt_msgs::WheelCommand::MODE_SPEED) {
    w = msg->speed;
  } else if (msg->mode == mrt_msgs::WheelCommand::MODE_PWM) {
    // An ideal unloaded motor: the duty cycle scales the maximum wheel speed.
    w.reserve(msg->duty.size());
    for (double d : msg->duty) w.push_back(std::clamp(d, -1.0, 1.0) * base.max_wheel_speed);
  } else {
    dropped("wheel_cmd with unknown mode " + std::to_string(msg->mode));
    return;
  }
  if (w.size() != n) {
    dropped("wheel_cmd with " + std::to_string(w.size()) + " wheels, the " + base.name + " base has " +
            std::to_string(n));
    return;
  }
  for (double v : w)
    if (!std::isfinite(v)) {
      dropped("wheel_cmd with a non-finite wheel speed");
      return;
    }
  sim_.set_wheel_speeds(index_, w);
  accepted();
}

void RobotInterface::apply_watchdog() {
  if (!commanded_ || opt_.cmd_timeout <= 0.0) return;
  // Half a step of slack absorbs the rounding of the accumulated sim time.
  if (sim_.time() - last_cmd_time_ + 0.5 * sim_.dt() < opt_.cmd_timeout) return;
  sim_.set_wheel_speeds(index_, std::vector<double>(state().config.base.wheel_count(), 0.0));
  commanded_ = false;
  watchdog_ = true;
  ++timeouts_;
}

void RobotInterface::publish(const ros::Time& stamp, bool ground_truth, bool path,
                             std::vector<geometry_msgs::TransformStamped>& tfs) {
  const RobotState& r = state();
  const SensorsConfig& s = r.config.sensors;

  if (ground_truth) {
    if (ground_truth_pub_.getNumSubscribers() > 0)
      ground_truth_pub_.publish(to_odometry(r, opt_.world_frame, frames_, stamp));
    tfs.push_back(to_transform(r.pose, opt_.world_frame, frames_.base_truth, stamp));
  }
  if (path && opt_.path_length > 0) {
    geometry_msgs::PoseStamped p;
    p.header.stamp = stamp;
    p.header.frame_id = opt_.world_frame;
    p.pose = to_pose(r.pose);
    trail_.push_back(p);
    while (trail_.size() > static_cast<std::size_t>(opt_.path_length)) trail_.pop_front();
    if (path_pub_.getNumSubscribers() > 0) {
      nav_msgs::Path msg;
      msg.header = p.header;
      msg.poses.assign(trail_.begin(), trail_.end());
      path_pub_.publish(msg);
    }
  }
  if (r.mice_ready && mice_pub_) {
    if (r.mice.left_fault) ++mouse_faults_;
    if (r.mice.right_fault) ++mouse_faults_;
    mice_pub_.publish(to_mice(r.mice, frames_, stamp));
  }
  if (r.encoders_ready) wheel_state_pub_.publish(to_wheel_state(r, watchdog_, stamp));
  if (r.encoders_ready && joint_state_pub_) joint_state_pub_.publish(to_joint_state(r, stamp));
  if (r.sonar_ready)
    for (std::size_t i = 0; i < sonar_pubs_.size() && i < r.sonar.size(); ++i)
      sonar_pubs_[i].publish(to_range(s.sonars[i], r.sonar[i], frames_.sonar(i), stamp));
  if (r.vision_ready && percepts_pub_) {
    percepts_pub_.publish(to_percept(r.vision, s, name_, frames_.sensor_parent, stamp));
    if (percept_markers_pub_.getNumSubscribers() > 0)
      percept_markers_pub_.publish(percept_markers(r.vision, r.pose, opt_.world_frame, stamp));
  }
  if (r.dgps_ready && dgps_pub_) dgps_pub_.publish(to_navsat(r.dgps, s, frames_.gps(), stamp));
  if (camera_) camera_->publish(stamp);
}

void RobotInterface::static_transforms(std::vector<geometry_msgs::TransformStamped>& out) const {
  if (opt_.described(name_)) return;
  const SensorsConfig& s = state().config.sensors;
  const ros::Time stamp;
  for (std::size_t i = 0; i < s.sonars.size(); ++i)
    out.push_back(to_transform(s.sonars[i].mount, frames_.sensor_parent, frames_.sonar(i), stamp));
  for (const MouseConfig& m : s.mice)
    out.push_back(to_transform(m.mount, frames_.sensor_parent, frames_.mouse(m.id), stamp));
  if (s.rate_dgps > 0.0)
    out.push_back(to_transform(Pose2D(), frames_.sensor_parent, frames_.gps(), stamp));
  if (camera_) out.push_back(camera_->mount_transform(frames_.sensor_parent));
}

void RobotInterface::diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) const {
  if (watchdog_)
    s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "wheels stopped: no command within cmd_timeout");
  else if (dropped_ > 0)
    s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "malformed commands dropped");
  else
    s.summary(diagnostic_msgs::DiagnosticStatus::OK, commanded_ ? "commanded" : "idle");
  const RobotState& r = state();
  s.add("commands accepted", commands_);
  s.add("commands dropped", dropped_);
  s.add("last drop reason", last_drop_reason_);
  s.add("command timeouts", timeouts_);
  s.add("mouse faults injected", mouse_faults_);
  s.add("x [m]", r.pose.x);
  s.add("y [m]", r.pose.y);
  s.add("theta [rad]", r.pose.theta);
  s.add("wheels saturated", r.saturated);
  s.add("bumped", r.bumped);
  if (camera_) {
    s.add("camera frames", camera_->frames());
    s.add("camera render time [ms]", camera_->render_ms());
  }
}

}  // namespace mrt::sim::node
