// airboard_node: the AIRBoard driver. Wiring only: parameters -> session
// options (ParamReader), messages <-> core types, timers, diagnostics; the
// link session, stream switching, command arbitration and speed estimation
// live in the ROS-free BoardSession (include/mrt_airboard/board_session.h).
// dynamic_reconfigure (cfg/Airboard.cfg): the wheel speed and acceleration
// limits; one mutex serializes every callback with the reconfiguration.
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/AirboardStatus.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/WheelCommand.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "mrt_airboard/AirboardConfig.h"
#include "mrt_airboard/board_session.h"
#include "mrt_common/angle.h"
#include "mrt_common/base_kinematics.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"

namespace mrt::airboard::node {

namespace {

using mrt::ros_common::ParamReader;

struct NodeOptions {
  std::string port = "/tmp/airboard";
  int baud = 115200;
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  bool publish_tf = true;
  std::vector<std::string> joint_names;  // ~joint_names; empty: wheel_joint_names(base type)
  SessionOptions session;
};

// Base: start from the preset, then override what is given.
BaseParams load_base(ParamReader& p) {
  std::string preset = "ianus3";
  p.get("base/preset", preset);
  BaseParams b = base_preset(preset);
  const ros::NodeHandle& nh = p.node_handle();
  std::string type;
  p.get("base/type", type);
  if (nh.hasParam("base/type")) b.type = parse_base_type(type);
  p.get("base/name", b.name)
      .get("base/wheel_radius", b.wheel_radius)
      .get("base/track", b.track)
      .get("base/wheel_distance", b.wheel_distance)
      .get("base/wheel_angles", b.wheel_angles)  // rad (REP-103)
      .get("base/max_wheel_speed", b.max_wheel_speed)
      .get("base/max_wheel_accel", b.max_wheel_accel)
      .get("base/deadband_linear", b.deadband_linear)
      .get("base/deadband_angular", b.deadband_angular)
      .get("base/counts_per_rev", b.counts_per_rev);
  return b;  // validated with the session options
}

BrianMappingParams load_brian(ParamReader& p, BaseType type) {
  BrianMappingParams b = BrianMappingParams::for_base(type);
  std::string mode;
  p.get("brian/mode", mode);
  if (p.node_handle().hasParam("brian/mode")) b.mode = BrianMappingParams::parse_mode(mode);
  p.get("brian/speed", b.speed_name)
      .get("brian/angle", b.angle_name)
      .get("brian/rotation", b.rotation_name)
      .get("brian/speed_scale", b.speed_scale)
      .get("brian/angle_scale", b.angle_scale)
      .get("brian/rotation_scale", b.rotation_scale);
  return b;  // validated with the session options
}

NodeOptions load_options(const ros::NodeHandle& pnh) {
  ParamReader p(pnh);
  NodeOptions o;
  SessionOptions& s = o.session;
  std::string format = "auto";
  p.get("port", o.port)
      .get("baud", o.baud)
      .get("odom_frame", o.odom_frame)
      .get("base_frame", o.base_frame)
      .get("publish_tf", o.publish_tf)
      .get("joint_names", o.joint_names)
      .get("rate", s.rate)
      .get("cmd_timeout", s.cmd_timeout)
      .get("link_timeout", s.link_timeout)
      .get("stream_period_ms", s.stream_period_ms)
      .get("state_format", format)
      .get("compact_period_ms", s.compact_period_ms)
      .get("reconnect_min", s.reconnect_min)
      .get("reconnect_max", s.reconnect_max)
      .get("checked_commands", s.checked_commands);
  ParamReader::check(!o.port.empty(), "port", "a non-empty device path");
  s.state_format = SessionOptions::parse_state_format(format);
  s.set_gains = pnh.hasParam("gains/kp") || pnh.hasParam("gains/ki");
  p.get("gains/kp", s.kp).get("gains/ki", s.ki);
  s.base = load_base(p);
  s.brian = load_brian(p, s.base.type);
  if (o.joint_names.empty()) o.joint_names = mrt::common::wheel_joint_names(s.base);
  ParamReader::check(o.joint_names.size() == s.base.wheel_count(), "joint_names",
                     "one joint name per wheel (" + std::to_string(s.base.wheel_count()) + ")");
  return o;  // BoardSession validates o.session
}

}  // namespace

class AirboardNode : public SessionListener {
 public:
  AirboardNode(ros::NodeHandle& nh, ros::NodeHandle& pnh)
      : o_(load_options(pnh)),
        session_(o_.session, std::make_unique<SerialLink>(o_.port, o_.baud), this),
        n_(session_.wheel_count()) {
    wheel_pub_ = nh.advertise<mrt_msgs::WheelState>("wheel_state", 10);
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    status_pub_ = nh.advertise<mrt_msgs::AirboardStatus>("airboard_status", 10);
    joint_pub_ = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
    cmd_sub_ = nh.subscribe("cmd_vel", 10, &AirboardNode::on_cmd_vel, this);
    brian_sub_ = nh.subscribe("brian_commands", 10, &AirboardNode::on_brian, this);
    wheel_sub_ = nh.subscribe("wheel_cmd", 10, &AirboardNode::on_wheel_cmd, this);
    diag_.setHardwareID("AIRBoard on " + o_.port);
    diag_.add("AIRBoard link", this, &AirboardNode::diag_link);
    diag_.add("AIRBoard motors", this, &AirboardNode::diag_motors);
    control_timer_ = nh.createTimer(ros::Duration(1.0 / o_.session.rate), [this](const ros::TimerEvent&) {
      const std::lock_guard<std::mutex> lock(mutex_);
      session_.control(ros::Time::now().toSec());
    });
    read_timer_ = nh.createTimer(ros::Duration(0.002), [this](const ros::TimerEvent&) {
      const std::lock_guard<std::mutex> lock(mutex_);
      session_.read(ros::Time::now().toSec());
    });
    diag_timer_ = nh.createTimer(ros::Duration(1.0), &AirboardNode::on_diag, this);
    ROS_INFO("airboard_node: base '%s' (%zu wheels), port %s at %d baud", o_.session.base.name.c_str(), n_,
             o_.port.c_str(), o_.baud);
    // The limits start from ~base/max_wheel_speed and ~base/max_wheel_accel
    // (validated with the base), not from the server's own parameters.
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<mrt_airboard::AirboardConfig>>(reconfigure_mutex_, pnh);
    reconfigure_->updateConfig(current_limits());
    reconfigure_->setCallback([this](mrt_airboard::AirboardConfig& c, uint32_t) { on_reconfigure(c); });
  }

 private:
  // ------------------------------------------------------------ inputs
  mrt_airboard::AirboardConfig current_limits() const {
    mrt_airboard::AirboardConfig c = mrt_airboard::AirboardConfig::__getDefault__();
    c.max_wheel_speed = session_.options().base.max_wheel_speed;
    c.max_wheel_accel = session_.options().base.max_wheel_accel;
    return c;
  }

  // New limits from the next control period; refused ones (the session
  // validates them) are logged and `c` gets the current ones back.
  void on_reconfigure(mrt_airboard::AirboardConfig& c) {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      session_.set_limits(c.max_wheel_speed, c.max_wheel_accel);
      ROS_INFO("airboard_node: wheel limits %.3f rad/s, %.3f rad/s^2 (0 = none)", c.max_wheel_speed,
               c.max_wheel_accel);
    } catch (const std::invalid_argument& e) {
      ROS_WARN("airboard_node: reconfiguration refused: %s", e.what());
    }
    c = current_limits();
  }

  void on_cmd_vel(const geometry_msgs::Twist& m) {
    const std::lock_guard<std::mutex> lock(mutex_);
    session_.command_twist(Twist2D{m.linear.x, m.linear.y, m.angular.z}, ros::Time::now().toSec());
  }

  void on_brian(const mrt_msgs::CommandArray& m) {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::pair<std::string, double>> c;
    for (const auto& x : m.commands) c.emplace_back(x.name, x.value);
    session_.command_brian(c, ros::Time::now().toSec());
  }

  void on_wheel_cmd(const mrt_msgs::WheelCommand& m) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const double now = ros::Time::now().toSec();
    if (m.mode == mrt_msgs::WheelCommand::MODE_PWM)
      session_.command_wheels(BoardSession::WheelMode::kPwm, m.duty, now);
    else if (m.mode == mrt_msgs::WheelCommand::MODE_SPEED)
      session_.command_wheels(BoardSession::WheelMode::kSpeed, m.speed, now);
    else
      session_.drop_input("a wheel_cmd of unknown mode " + std::to_string(int(m.mode)));
  }

  // ------------------------------------------------------------ session events
  void log(Level level, const std::string& key, const std::string& text) override {
    if (!key.empty()) {
      const double now = ros::WallTime::now().toSec();
      auto it = last_log_.find(key);
      if (it != last_log_.end() && now - it->second < 5.0) return;
      last_log_[key] = now;
    }
    if (level == Level::kInfo)
      ROS_INFO("airboard_node: %s", text.c_str());
    else if (level == Level::kWarn)
      ROS_WARN("airboard_node: %s", text.c_str());
    else
      ROS_ERROR("airboard_node: %s", text.c_str());
  }

  void on_state(const BoardState& s) override {
    const StateTracker& tracker = session_.tracker();
    const std::vector<int64_t>& counts = tracker.counts();
    const ros::Time stamp(tracker.host_stamp());
    mrt_msgs::WheelState ws;
    ws.header.stamp = stamp;
    ws.header.frame_id = o_.base_frame;
    for (std::size_t i = 0; i < n_; ++i) {
      const MotorState& m = s.motors[i];
      ws.setpoint.push_back(m.setpoint);
      ws.speed.push_back(m.speed);
      ws.duty.push_back(m.duty);
      ws.ticks.push_back(counts[i]);
      ws.status.push_back(m.status);
    }
    wheel_pub_.publish(ws);
    publish_joint_states(ws);
    publish_odometry(stamp);
    publish_status(stamp, &s);
  }

  // The wheel joints of the robot description: angle from the encoder
  // counts, velocity = measured wheel speed.
  void publish_joint_states(const mrt_msgs::WheelState& ws) {
    sensor_msgs::JointState j;
    j.header.stamp = ws.header.stamp;
    j.name = o_.joint_names;
    j.velocity = ws.speed;
    for (int64_t c : ws.ticks) j.position.push_back(mrt::common::encoder_angle(c, o_.session.base.counts_per_rev));
    joint_pub_.publish(j);
  }

  void publish_odometry(const ros::Time& stamp) {
    namespace rc = mrt::ros_common;
    const WheelOdometry& odom = session_.odometry();
    // Encoder odometry: small, growing-free diagonal covariances (x, y, yaw);
    // z, roll, pitch: not measured.
    const rc::Covariance2D pose_cov = {1e-3, 0, 0, 0, 1e-3, 0, 0, 0, 1e-2};
    const rc::Covariance2D twist_cov = {1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-3};
    nav_msgs::Odometry od = rc::to_odometry(odom.pose(), odom.twist().vx, odom.twist().vy, odom.twist().omega,
                                            o_.odom_frame, o_.base_frame, stamp);
    rc::set_planar_covariance(pose_cov, od.pose.covariance, 1e6);
    rc::set_planar_covariance(twist_cov, od.twist.covariance, 1e6);
    odom_pub_.publish(od);
    // Two board states can arrive within one tick of simulated time (the
    // four-wheel base's longer frames): tf refuses a repeated stamp
    // (TF_REPEATED_DATA), so the transform goes out once per stamp.
    if (o_.publish_tf && stamp != last_tf_stamp_) {
      tf_.sendTransform(rc::to_transform(odom.pose(), o_.odom_frame, o_.base_frame, stamp));
      last_tf_stamp_ = stamp;
    }
  }

  void publish_status(const ros::Time& stamp, const BoardState* s) {
    mrt_msgs::AirboardStatus st;
    st.header.stamp = stamp;
    st.header.frame_id = o_.base_frame;
    st.connected = session_.link_up();
    if (s) {
      st.board_time = session_.tracker().valid() ? session_.tracker().board_time() : s->time_ms * 1e-3;
      st.since_command = s->since_cmd_ms * 1e-3;
      st.status = s->status;
      st.watchdog_trips = s->watchdog_trips;
      st.board_frames_bad = s->frames_bad;
    }
    const SessionStats& c = session_.stats();
    st.frames_good = session_.frame_stats().frames_ok;
    st.frames_bad = session_.frame_stats().frames_bad();
    st.reconnects = c.reconnects;
    st.commands_sent = c.commands_sent;
    st.commands_saturated = c.commands_saturated;
    status_pub_.publish(st);
  }

  void on_link_lost() override {
    mrt_msgs::WheelState ws;
    ws.header.stamp = ros::Time::now();
    ws.header.frame_id = o_.base_frame;
    ws.setpoint.assign(n_, 0.0);
    ws.speed.assign(n_, 0.0);
    ws.duty.assign(n_, 0.0);
    ws.ticks.assign(n_, 0);
    const StateTracker& tracker = session_.tracker();
    if (tracker.valid() && tracker.counts().size() == n_)
      ws.ticks.assign(tracker.counts().begin(), tracker.counts().end());
    ws.status.assign(n_, mrt_msgs::WheelState::STATUS_OK);
    wheel_pub_.publish(ws);
    publish_status(ws.header.stamp, nullptr);
  }

  // ------------------------------------------------------------ diagnostics
  void on_diag(const ros::TimerEvent&) {
    const std::lock_guard<std::mutex> lock(mutex_);
    diag_.update();
    if (!session_.link_up()) publish_status(ros::Time::now(), nullptr);
  }

  void diag_link(diagnostic_updater::DiagnosticStatusWrapper& d) {
    if (!session_.link_up())
      d.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "no link to the board");
    else if (!session_.info_ok())
      d.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "board does not match the base configuration");
    else
      d.summary(diagnostic_msgs::DiagnosticStatus::OK, "link up");
    const FrameDecoder::Stats& f = session_.frame_stats();
    const SessionStats& c = session_.stats();
    d.add("port", o_.port);
    d.add("frames good", f.frames_ok);
    d.add("frames bad (CRC)", f.crc_errors);
    d.add("frames bad (length)", f.length_errors);
    d.add("bytes skipped", f.bytes_skipped);
    d.add("frames rejected by the board (NACK)", c.nacks);
    d.add("unexpected frames", c.unexpected_frames);
    d.add("board frames bad", session_.have_state() ? session_.last_state().frames_bad : 0);
    d.add("reconnects", c.reconnects);
    d.add("port opens", c.port_opens);
    d.add("next reconnect delay (s)", session_.next_reconnect_delay());
    d.add("commands sent", c.commands_sent);
    d.add("commands clamped (speed limit)", c.commands_saturated);
    d.add("inputs dropped", c.dropped_inputs);
    const BoardInfo& info = session_.info();
    if (info.motors) {
      d.add("firmware", std::to_string(info.fw_major) + "." + std::to_string(info.fw_minor));
      d.add("PWM frequency (Hz)", info.pwm_hz);
    }
  }

  void diag_motors(diagnostic_updater::DiagnosticStatusWrapper& d) {
    if (!session_.link_up() || !session_.have_state()) {
      d.summary(diagnostic_msgs::DiagnosticStatus::STALE, "motors considered stopped (no link)");
      return;
    }
    const BoardState& s = session_.last_state();
    if (s.status & (proto::kStatusOvercurrent | proto::kStatusEncoderFault))
      d.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "over-current or encoder fault");
    else if (s.status & proto::kStatusWatchdog)
      d.summary(diagnostic_msgs::DiagnosticStatus::WARN, "watchdog tripped: motors stopped by the board");
    else if (s.status & (proto::kStatusSaturated | proto::kStatusClamped))
      d.summary(diagnostic_msgs::DiagnosticStatus::WARN, "saturated or clamped");
    else
      d.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
    d.add("watchdog trips", s.watchdog_trips);
    d.add("board time (s)", s.time_ms * 1e-3);
    for (std::size_t i = 0; i < s.motors.size(); ++i) {
      const MotorState& m = s.motors[i];
      char buf[160];
      std::snprintf(buf, sizeof(buf), "setpoint %.3f rad/s, speed %.3f rad/s, duty %.3f, status 0x%02x", m.setpoint,
                    m.speed, m.duty, m.status);
      d.add("motor " + std::to_string(i), buf);
    }
  }

  std::mutex mutex_;  // every callback's: the session is not thread-safe
  NodeOptions o_;
  BoardSession session_;
  std::size_t n_;
  std::map<std::string, double> last_log_;  // throttle key -> wall time of the last message

  ros::Publisher wheel_pub_, odom_pub_, status_pub_, joint_pub_;
  ros::Subscriber cmd_sub_, brian_sub_, wheel_sub_;
  ros::Timer control_timer_, read_timer_, diag_timer_;
  diagnostic_updater::Updater diag_;
  tf2_ros::TransformBroadcaster tf_;
  ros::Time last_tf_stamp_;  // of the last odom -> base_link sent
  boost::recursive_mutex reconfigure_mutex_;  // the server's own, held around on_reconfigure
  std::unique_ptr<dynamic_reconfigure::Server<mrt_airboard::AirboardConfig>> reconfigure_;
};

}  // namespace mrt::airboard::node

int main(int argc, char** argv) {
  ros::init(argc, argv, "airboard_node");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::airboard::node::AirboardNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
