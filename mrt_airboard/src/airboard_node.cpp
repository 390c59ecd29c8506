// airboard_node: the AIRBoard driver. Wiring only: parameters -> core
// options, messages <-> core types; the protocol, kinematics, limits and
// odometry live in the ROS-free core (include/mrt_airboard/).
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/AirboardStatus.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/WheelCommand.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mrt_airboard/brian_mapping.h"
#include "mrt_airboard/kinematics.h"
#include "mrt_airboard/odometry.h"
#include "mrt_airboard/protocol.h"
#include "mrt_airboard/serial_port.h"
#include "mrt_airboard/state_tracker.h"
#include "mrt_common/angle.h"

namespace mrt::airboard {

namespace {

struct NodeOptions {
  std::string port = "/tmp/airboard";
  int baud = 115200;
  double rate = 50.0;
  double cmd_timeout = 0.5;
  double link_timeout = 0.5;
  int stream_period_ms = 10;
  std::string state_format = "auto";  // auto | state | compact
  int compact_period_ms = 3;
  double reconnect_min = 0.1;
  double reconnect_max = 2.0;
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  bool publish_tf = true;
  bool mirror_to_sim = false;
  bool set_gains = false;
  double kp = 0.0, ki = 0.0;
  BaseParams base;
  BrianMappingParams brian;
};

[[noreturn]] void fail(const std::string& msg) { throw std::invalid_argument(msg); }

NodeOptions load_options(ros::NodeHandle& pnh) {
  NodeOptions o;
  pnh.param("port", o.port, o.port);
  pnh.param("baud", o.baud, o.baud);
  pnh.param("rate", o.rate, o.rate);
  pnh.param("cmd_timeout", o.cmd_timeout, o.cmd_timeout);
  pnh.param("link_timeout", o.link_timeout, o.link_timeout);
  pnh.param("stream_period_ms", o.stream_period_ms, o.stream_period_ms);
  pnh.param("state_format", o.state_format, o.state_format);
  pnh.param("compact_period_ms", o.compact_period_ms, o.compact_period_ms);
  pnh.param("reconnect_min", o.reconnect_min, o.reconnect_min);
  pnh.param("reconnect_max", o.reconnect_max, o.reconnect_max);
  pnh.param("odom_frame", o.odom_frame, o.odom_frame);
  pnh.param("base_frame", o.base_frame, o.base_frame);
  pnh.param("publish_tf", o.publish_tf, o.publish_tf);
  pnh.param("mirror_to_sim", o.mirror_to_sim, o.mirror_to_sim);
  o.set_gains = pnh.hasParam("gains/kp") || pnh.hasParam("gains/ki");
  pnh.param("gains/kp", o.kp, 0.05);
  pnh.param("gains/ki", o.ki, 1.0);
  if (o.port.empty()) fail("parameter '~port' must not be empty");
  if (!(o.rate > 0.0 && o.rate <= 1000.0)) fail("parameter '~rate' must be in (0, 1000] Hz");
  if (!(o.cmd_timeout > 0.0)) fail("parameter '~cmd_timeout' must be > 0 s");
  if (!(o.link_timeout > 0.0)) fail("parameter '~link_timeout' must be > 0 s");
  if (o.stream_period_ms < 0 || o.stream_period_ms > 65535) fail("parameter '~stream_period_ms' must be 0..65535");
  if (o.state_format != "auto" && o.state_format != "state" && o.state_format != "compact")
    fail("parameter '~state_format' must be 'auto', 'state' or 'compact'");
  if (o.compact_period_ms < 1 || o.compact_period_ms > 65535) fail("parameter '~compact_period_ms' must be 1..65535");
  if (!(o.reconnect_min > 0.0 && o.reconnect_max >= o.reconnect_min))
    fail("parameters '~reconnect_min' and '~reconnect_max' must satisfy 0 < min <= max");
  if (!(o.kp >= 0.0 && o.ki >= 0.0)) fail("parameters '~gains/kp' and '~gains/ki' must be >= 0");

  // Base: start from the preset, then override what is given.
  std::string preset = "ianus3";
  pnh.param("base/preset", preset, preset);
  o.base = base_preset(preset);
  std::string type;
  if (pnh.getParam("base/type", type)) o.base.type = parse_base_type(type);
  pnh.param("base/name", o.base.name, o.base.name);
  pnh.param("base/wheel_radius", o.base.wheel_radius, o.base.wheel_radius);
  pnh.param("base/track", o.base.track, o.base.track);
  pnh.param("base/wheel_distance", o.base.wheel_distance, o.base.wheel_distance);
  std::vector<double> deg;
  if (pnh.getParam("base/wheel_angles", deg)) {
    o.base.wheel_angles.clear();
    for (double d : deg) o.base.wheel_angles.push_back(mrt::common::deg_to_rad(d));
  }
  pnh.param("base/max_wheel_speed", o.base.max_wheel_speed, o.base.max_wheel_speed);
  pnh.param("base/max_wheel_accel", o.base.max_wheel_accel, o.base.max_wheel_accel);
  pnh.param("base/deadband_linear", o.base.deadband_linear, o.base.deadband_linear);
  pnh.param("base/deadband_angular", o.base.deadband_angular, o.base.deadband_angular);
  pnh.param("base/counts_per_rev", o.base.counts_per_rev, o.base.counts_per_rev);
  o.base.validate();

  o.brian = BrianMappingParams::for_base(o.base.type);
  std::string mode;
  if (pnh.getParam("brian/mode", mode)) o.brian.mode = BrianMappingParams::parse_mode(mode);
  pnh.param("brian/speed", o.brian.speed_name, o.brian.speed_name);
  pnh.param("brian/angle", o.brian.angle_name, o.brian.angle_name);
  pnh.param("brian/rotation", o.brian.rotation_name, o.brian.rotation_name);
  pnh.param("brian/speed_scale", o.brian.speed_scale, o.brian.speed_scale);
  pnh.param("brian/angle_scale", o.brian.angle_scale, o.brian.angle_scale);
  pnh.param("brian/rotation_scale", o.brian.rotation_scale, o.brian.rotation_scale);
  o.brian.validate();
  return o;
}

}  // namespace

class AirboardNode {
 public:
  AirboardNode(ros::NodeHandle& nh, ros::NodeHandle& pnh)
      : o_(load_options(pnh)),
        limiter_(o_.base),
        brian_(o_.brian),
        odom_(o_.base),
        backoff_(o_.reconnect_min, o_.reconnect_max) {
    n_ = o_.base.wheel_count();
    wheel_pub_ = nh.advertise<mrt_msgs::WheelState>("wheel_state", 10);
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    status_pub_ = nh.advertise<mrt_msgs::AirboardStatus>("airboard_status", 10);
    if (o_.mirror_to_sim) sim_pub_ = nh.advertise<mrt_msgs::WheelCommand>("sim_wheel_cmd", 10);
    cmd_sub_ = nh.subscribe("cmd_vel", 10, &AirboardNode::on_cmd_vel, this);
    brian_sub_ = nh.subscribe("brian_commands", 10, &AirboardNode::on_brian, this);
    wheel_sub_ = nh.subscribe("wheel_cmd", 10, &AirboardNode::on_wheel_cmd, this);
    diag_.setHardwareID("AIRBoard on " + o_.port);
    diag_.add("AIRBoard link", this, &AirboardNode::diag_link);
    diag_.add("AIRBoard motors", this, &AirboardNode::diag_motors);
    control_timer_ = nh.createTimer(ros::Duration(1.0 / o_.rate), &AirboardNode::on_control, this);
    read_timer_ = nh.createTimer(ros::Duration(0.002), &AirboardNode::on_read, this);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), &AirboardNode::on_diag, this);
    ROS_INFO("airboard_node: base '%s' (%zu wheels), port %s at %d baud", o_.base.name.c_str(), n_,
             o_.port.c_str(), o_.baud);
  }

 private:
  enum class Source { kNone, kTwist, kWheelSpeed, kWheelPwm };

  // ------------------------------------------------------------ inputs
  void on_cmd_vel(const geometry_msgs::Twist& m) {
    if (!std::isfinite(m.linear.x) || !std::isfinite(m.linear.y) || !std::isfinite(m.angular.z)) {
      ++dropped_inputs_;
      ROS_WARN_THROTTLE(5.0, "airboard_node: dropped a cmd_vel with a non-finite component (%g, %g, %g)",
                        m.linear.x, m.linear.y, m.angular.z);
      return;
    }
    twist_ = Twist2D{m.linear.x, m.linear.y, m.angular.z};
    source_ = Source::kTwist;
    last_cmd_ = ros::Time::now();
  }

  void on_brian(const mrt_msgs::CommandArray& m) {
    std::vector<std::pair<std::string, double>> c;
    for (const auto& x : m.commands) c.emplace_back(x.name, x.value);
    const auto t = brian_.to_twist(c);
    if (!t) {
      ++dropped_inputs_;
      ROS_WARN_THROTTLE(5.0, "airboard_node: dropped a brian_commands array with a non-finite %s, %s or %s",
                        o_.brian.speed_name.c_str(), o_.brian.angle_name.c_str(), o_.brian.rotation_name.c_str());
      return;
    }
    twist_ = *t;
    source_ = Source::kTwist;
    last_cmd_ = ros::Time::now();
  }

  void on_wheel_cmd(const mrt_msgs::WheelCommand& m) {
    const auto& v = m.mode == mrt_msgs::WheelCommand::MODE_PWM ? m.duty : m.speed;
    bool ok = v.size() == n_ && (m.mode == mrt_msgs::WheelCommand::MODE_SPEED ||
                                 m.mode == mrt_msgs::WheelCommand::MODE_PWM);
    for (double x : v) ok = ok && std::isfinite(x);
    if (!ok) {
      ++dropped_inputs_;
      ROS_WARN_THROTTLE(5.0, "airboard_node: dropped a wheel_cmd (mode %d, %zu values for %zu wheels)",
                        int(m.mode), v.size(), n_);
      return;
    }
    wheel_cmd_ = v;
    source_ = m.mode == mrt_msgs::WheelCommand::MODE_PWM ? Source::kWheelPwm : Source::kWheelSpeed;
    last_cmd_ = ros::Time::now();
  }

  // ------------------------------------------------------------ link
  void connect(double now) {
    try {
      port_.open(o_.port, o_.baud);
    } catch (const SerialError& e) {
      backoff_.failed(now);
      ROS_WARN_THROTTLE(5.0, "airboard_node: %s (retrying, next delay %.1f s)", e.what(), backoff_.current_delay());
      return;
    }
    // The back-off is reset by the board's first valid frame (on_frame), not
    // here: a port that opens but stays silent keeps backing off.
    ++port_opens_;
    answered_ = false;
    dec_.clear();
    opened_at_ = now;
    last_frame_ = -1.0;
    tracker_.reset();
    odom_.reset();
    limiter_.reset();
    info_ok_ = false;
    info_ = BoardInfo{};
    info_.motors = 0;
    have_counters_ = false;
    speed_ref_time_ = -1.0;
    compact_ = o_.state_format == "compact";
    window_start_ = now;
    window_good_ = dec_.stats().frames_ok;
    window_bad_ = dec_.stats().frames_bad();
    request_stream();
    send(make_simple(proto::kGetInfo, seq_++));
    if (o_.set_gains) send(make_set_gains(seq_++, Gains{0xFF, o_.kp, o_.ki}));
    ROS_INFO("airboard_node: opened %s", o_.port.c_str());
  }

  void disconnect(const std::string& why) {
    if (!port_.is_open() && !link_up_) return;
    port_.close();
    link_up_ = false;
    ROS_WARN("airboard_node: link lost (%s); motors considered stopped, reconnecting", why.c_str());
    publish_stopped();
    tracker_.reset();
    odom_.reset();
    limiter_.reset();
  }

  // Asks the board for the stream in the format in use; until a frame of that
  // format confirms it, on_control repeats the request.
  void request_stream() {
    stream_confirmed_ = false;
    stream_seq_ = seq_;
    if (compact_)
      send(make_set_stream(seq_++, static_cast<uint16_t>(o_.compact_period_ms), proto::kFormatCompact));
    else
      send(make_set_stream(seq_++, static_cast<uint16_t>(o_.stream_period_ms)));
  }

  // ~state_format auto: the full STATE (49 bytes for two motors) is the
  // default; when the node's decoder discards more frames than it accepts,
  // the line is too noisy for it (at 10 % of the bytes corrupted, 0.6 % of
  // STATEs survive) and the board is asked for SHORT_STATE frames (17 bytes,
  // 16.7 % survive) at a shorter period; back to STATE when fewer than one
  // frame in six is discarded over 2 s.
  void adapt_format(double now) {
    if (compact_ && !compact_allowed()) {
      compact_ = false;
      ROS_WARN("airboard_node: the board's max set-point %.3f rad/s does not fit SHORT_STATE: full STATE frames",
               info_.max_speed);
      request_stream();
      return;
    }
    if (o_.state_format != "auto" || !compact_allowed()) return;
    const uint64_t good = dec_.stats().frames_ok - window_good_;
    const uint64_t bad = dec_.stats().frames_bad() - window_bad_;
    bool change = false;
    if (!compact_) change = bad >= 8 && bad > good;
    else change = now - window_start_ >= 2.0 && bad * 5 < good;
    if (change) {
      compact_ = !compact_;
      ROS_WARN("airboard_node: %lu of %lu frames bad: switching to %s frames", static_cast<unsigned long>(bad),
               static_cast<unsigned long>(bad + good), compact_ ? "compact SHORT_STATE" : "full STATE");
      request_stream();
    }
    if (change || now - window_start_ >= (compact_ ? 2.0 : 1.0)) {
      window_start_ = now;
      window_good_ = dec_.stats().frames_ok;
      window_bad_ = dec_.stats().frames_bad();
    }
  }

  // SHORT_STATE carries set-points as i16 mrad/s: only for boards whose
  // speed limit fits.
  bool compact_allowed() const { return info_.motors == 0 || info_.max_speed <= 32.767; }

  // Longest gap between SHORT_STATEs over which the 16-bit count difference
  // is unambiguous: half the i16 range at 1.5 x the fastest wheel speed.
  uint32_t short_max_gap_ms() const {
    const double w = 1.5 * std::max(o_.base.max_wheel_speed, info_.max_speed);
    const double counts_per_s = w * o_.base.counts_per_rev / (2.0 * M_PI);
    return static_cast<uint32_t>(std::max(1.0, 32767.0 / counts_per_s * 1000.0));
  }

  void send(const Frame& f) {
    if (!port_.is_open()) return;
    try {
      tx_.clear();
      append_frame(tx_, f);
      port_.write(tx_.data(), tx_.size());
    } catch (const SerialError& e) {
      disconnect(e.what());
    }
  }

  // ------------------------------------------------------------ timers
  void on_control(const ros::TimerEvent&) {
    const ros::Time now_t = ros::Time::now();
    const double now = now_t.toSec();
    if (!port_.is_open()) {
      if (backoff_.due(now)) connect(now);
      if (!port_.is_open()) return;
    }
    const double last = last_frame_ >= 0.0 ? last_frame_ : opened_at_;
    if (now - last > o_.link_timeout) {
      disconnect("no valid frame for " + std::to_string(o_.link_timeout) + " s");
      backoff_.failed(now);
      return;
    }
    // Re-send the stream request every second: idempotent, and it survives a
    // lost request or a board reset.
    adapt_format(now);
    ++control_cycles_;
    if (control_cycles_ % static_cast<uint64_t>(std::max(1.0, o_.rate)) == 0 ||
        (!stream_confirmed_ && control_cycles_ % 2 == 0))
      request_stream();
    if (!info_ok_) {
      // Until the board identified itself as matching the base, keep asking
      // and drive nothing.
      // Every period until a first INFO arrives (25 bytes: 7 % get through
      // a line with 10 % of its bytes corrupted), then every 10th.
      if (info_.motors == 0 || ++info_polls_ % 10 == 0) send(make_simple(proto::kGetInfo, seq_++));
      send(make_simple(proto::kHeartbeat, seq_++));
      return;
    }
    const bool fresh = source_ != Source::kNone && (now_t - last_cmd_).toSec() <= o_.cmd_timeout;
    // While the board reports it stopped, each command is the first step of
    // the ramp at the nominal period, so repeated ones are identical.
    const double dt = last_control_ > 0.0 && !limiter_.board_stopped() ? now - last_control_ : 1.0 / o_.rate;
    last_control_ = now;
    if (fresh && source_ == Source::kWheelPwm) {
      std::vector<double> d = wheel_cmd_;
      bool clamped = false;
      for (double& x : d) {
        clamped = clamped || std::fabs(x) > 1.0;
        x = std::max(-1.0, std::min(1.0, x));
      }
      if (clamped) {
        ++commands_saturated_;
        ROS_WARN_THROTTLE(5.0, "airboard_node: wheel_cmd duty beyond +-1 clamped");
      }
      // A later twist ramps from the wheels' measured speeds (open loop: no
      // set-point is in force).
      if (have_state_ && last_state_.motors.size() == n_) {
        std::vector<double> measured(n_);
        for (std::size_t i = 0; i < n_; ++i) measured[i] = last_state_.motors[i].speed;
        limiter_.hold(measured);
      } else {
        limiter_.reset();
      }
      send(make_set_pwm(seq_++, d));
      ++commands_sent_;
      return;
    }
    std::vector<double> w;
    if (fresh && source_ == Source::kWheelSpeed) {
      w = wheel_cmd_;
      if (saturate_preserving_direction(w, o_.base.max_wheel_speed) < 1.0) ++commands_saturated_;
      limiter_.hold(w);
    } else {
      const auto r = limiter_.update(fresh ? twist_ : Twist2D{}, dt);
      if (r.saturated) {
        ++commands_saturated_;
        ROS_WARN_THROTTLE(5.0, "airboard_node: command exceeds max_wheel_speed %.2f rad/s, scaled down",
                          o_.base.max_wheel_speed);
      }
      w = r.wheels;
    }
    send(make_set_speed(seq_++, w));
    ++commands_sent_;
  }

  void on_read(const ros::TimerEvent&) {
    if (!port_.is_open()) return;
    uint8_t buf[1024];
    try {
      for (int i = 0; i < 16; ++i) {
        const std::size_t n = port_.read(buf, sizeof(buf));
        if (n == 0) break;
        dec_.feed(buf, n, [this](const Frame& f) { on_frame(f); });
      }
    } catch (const SerialError& e) {
      disconnect(e.what());
      backoff_.failed(ros::Time::now().toSec());
    }
  }

  void on_diag(const ros::TimerEvent&) {
    diag_.update();
    if (!link_up_) publish_status(ros::Time::now(), nullptr);
  }

  // ------------------------------------------------------------ frames
  void on_frame(const Frame& f) {
    const ros::Time now = ros::Time::now();
    last_frame_ = now.toSec();
    link_up_ = true;
    if (!answered_) {
      answered_ = true;
      backoff_.succeeded();
      if (ever_answered_) ++reconnects_;
      ever_answered_ = true;
    }
    BoardState s;
    ShortState ss;
    BoardCounters c;
    BoardInfo info;
    uint8_t t, reason;
    if (parse_state(f, &s)) {
      if (!compact_ && f.seq == stream_seq_) stream_confirmed_ = true;
      return on_state(s, now);
    }
    if (parse_short_state(f, &ss)) {
      if (compact_) stream_confirmed_ = true;
      return on_short_state(ss, f.seq, now);
    }
    if (parse_counters(f, &c)) {
      if (compact_) stream_confirmed_ = true;
      counters_ = c;
      have_counters_ = true;
      return;
    }
    if (parse_info(f, &info)) return on_info(info);
    if (parse_nack(f, &t, &reason)) {
      ++nacks_;
      ROS_WARN_THROTTLE(5.0, "airboard_node: board rejected a frame of type 0x%02x (reason %d)", t, reason);
      return;
    }
    ++unexpected_frames_;
  }

  void on_info(const BoardInfo& i) {
    info_ = i;
    const bool ok = i.motors == n_ && static_cast<int>(i.counts_per_rev) == o_.base.counts_per_rev;
    if (!ok) {
      ROS_ERROR_THROTTLE(5.0,
                         "airboard_node: the board reports %d motors and %u counts/rev; base '%s' needs %zu "
                         "and %d (parameter '~base/counts_per_rev'): not driving",
                         int(i.motors), i.counts_per_rev, o_.base.name.c_str(), n_, o_.base.counts_per_rev);
    } else if (!info_ok_) {
      ROS_INFO("airboard_node: board firmware %d.%d, %d motors, %u counts/rev, PI at %d Hz, PWM %u Hz, watchdog %d ms",
               int(i.fw_major), int(i.fw_minor), int(i.motors), i.counts_per_rev, int(i.control_hz), i.pwm_hz,
               int(i.watchdog_ms));
    }
    info_ok_ = ok;
  }

  void on_state(const BoardState& s, const ros::Time& now) {
    if (s.motors.size() != n_) {
      ++unexpected_frames_;
      return;
    }
    note_board_status(s.status);
    counters_ = BoardCounters{s.since_cmd_ms, s.frames_bad, s.watchdog_trips};
    have_counters_ = true;
    if (!tracker_.update(s, now.toSec())) {
      last_state_ = s;  // same board instant (a reply and a streamed frame): nothing new to integrate
      return;
    }
    speed_ref_time_ = -1.0;  // STATE carries the board's own measured speeds
    publish_state(s);
  }

  // A state with the WATCHDOG bit: the board zeroed its set-points and
  // applied none of the commands sent since (the bit is latched until one
  // is): the acceleration ramp restarts from rest, not from the old target.
  // The first state without the bit releases it.
  void note_board_status(uint8_t status) { limiter_.set_board_stopped((status & proto::kStatusWatchdog) != 0); }

  // SHORT_STATE: clock and counts unwrapped by the tracker, set-points and
  // status from the board; the measured speed is computed here from the
  // counts (over >= 10 ms), the duty is not carried (NaN), the counters are
  // the last COUNTERS' (or STATE's).
  void on_short_state(const ShortState& ss, uint8_t seq, const ros::Time& now) {
    if (ss.ticks.size() != n_) {
      ++unexpected_frames_;
      return;
    }
    note_board_status(ss.status);
    if (!tracker_.update_short(ss, now.toSec(), short_max_gap_ms())) return;
    if (tracker_.rebased()) {
      odom_.reset();
      speed_ref_time_ = -1.0;
    }
    const std::vector<int64_t>& counts = tracker_.counts();
    const double t = tracker_.board_time();
    if (speed_ref_time_ < 0.0) {
      speed_ref_time_ = t;
      speed_ref_counts_ = counts;
      short_speed_.assign(n_, 0.0);
      for (std::size_t i = 0; i < n_ && have_state_ && i < last_state_.motors.size(); ++i)
        short_speed_[i] = last_state_.motors[i].speed;
    } else if (t - speed_ref_time_ >= 0.010 - 1e-9) {
      const double k = 2.0 * M_PI / o_.base.counts_per_rev / (t - speed_ref_time_);
      for (std::size_t i = 0; i < n_; ++i) short_speed_[i] = (counts[i] - speed_ref_counts_[i]) * k;
      speed_ref_time_ = t;
      speed_ref_counts_ = counts;
    }
    BoardState s;
    s.time_ms = static_cast<uint32_t>(static_cast<uint64_t>(std::llround(t * 1000.0)));
    s.status = ss.status;
    s.last_seq = seq;
    if (have_counters_) {
      s.since_cmd_ms = counters_.since_cmd_ms;
      s.frames_bad = counters_.frames_bad;
      s.watchdog_trips = counters_.watchdog_trips;
    }
    s.motors.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      MotorState& m = s.motors[i];
      m.ticks = static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(counts[i])));
      m.speed = short_speed_[i];
      m.setpoint = ss.setpoints[i];
      m.duty = std::numeric_limits<double>::quiet_NaN();
      m.status = ss.status & static_cast<uint8_t>(~proto::kStatusPwmMode);
    }
    publish_state(s);
  }

  void publish_state(const BoardState& s) {
    last_state_ = s;
    have_state_ = true;
    const std::vector<int64_t>& counts = tracker_.counts();
    const ros::Time stamp(tracker_.host_stamp());
    odom_.update(counts, tracker_.board_time());

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
    if (o_.mirror_to_sim) {
      // Coupling to mrt_sim: the emulated wheels' measured speeds drive the
      // simulated base (remap sim_wheel_cmd to /<robot>/wheel_cmd).
      mrt_msgs::WheelCommand wc;
      wc.header = ws.header;
      wc.mode = mrt_msgs::WheelCommand::MODE_SPEED;
      wc.speed = ws.speed;
      sim_pub_.publish(wc);
    }

    nav_msgs::Odometry od;
    od.header.stamp = stamp;
    od.header.frame_id = o_.odom_frame;
    od.child_frame_id = o_.base_frame;
    const auto& p = odom_.pose();
    od.pose.pose.position.x = p.x;
    od.pose.pose.position.y = p.y;
    od.pose.pose.orientation.z = std::sin(p.theta / 2.0);
    od.pose.pose.orientation.w = std::cos(p.theta / 2.0);
    od.twist.twist.linear.x = odom_.twist().vx;
    od.twist.twist.linear.y = odom_.twist().vy;
    od.twist.twist.angular.z = odom_.twist().omega;
    // Encoder odometry: small, growing-free diagonal covariances (x, y, yaw).
    for (int i : {0, 7}) od.pose.covariance[i] = 1e-3;
    od.pose.covariance[35] = 1e-2;
    for (int i : {14, 21, 28}) od.pose.covariance[i] = 1e6;  // z, roll, pitch: not measured
    for (int i : {0, 7}) od.twist.covariance[i] = 1e-4;
    od.twist.covariance[35] = 1e-3;
    for (int i : {14, 21, 28}) od.twist.covariance[i] = 1e6;
    odom_pub_.publish(od);

    if (o_.publish_tf) {
      geometry_msgs::TransformStamped tf;
      tf.header = od.header;
      tf.child_frame_id = o_.base_frame;
      tf.transform.translation.x = p.x;
      tf.transform.translation.y = p.y;
      tf.transform.rotation = od.pose.pose.orientation;
      tf_.sendTransform(tf);
    }
    publish_status(stamp, &s);
  }

  void publish_status(const ros::Time& stamp, const BoardState* s) {
    mrt_msgs::AirboardStatus st;
    st.header.stamp = stamp;
    st.header.frame_id = o_.base_frame;
    st.connected = link_up_;
    if (s) {
      st.board_time = tracker_.valid() ? tracker_.board_time() : s->time_ms * 1e-3;
      st.since_command = s->since_cmd_ms * 1e-3;
      st.status = s->status;
      st.watchdog_trips = s->watchdog_trips;
      st.board_frames_bad = s->frames_bad;
    }
    st.frames_good = dec_.stats().frames_ok;
    st.frames_bad = dec_.stats().frames_bad();
    st.reconnects = reconnects_;
    st.commands_sent = commands_sent_;
    st.commands_saturated = commands_saturated_;
    status_pub_.publish(st);
  }

  void publish_stopped() {
    mrt_msgs::WheelState ws;
    ws.header.stamp = ros::Time::now();
    ws.header.frame_id = o_.base_frame;
    ws.setpoint.assign(n_, 0.0);
    ws.speed.assign(n_, 0.0);
    ws.duty.assign(n_, 0.0);
    ws.ticks.assign(n_, 0);
    if (tracker_.valid() && tracker_.counts().size() == n_)
      ws.ticks.assign(tracker_.counts().begin(), tracker_.counts().end());
    ws.status.assign(n_, mrt_msgs::WheelState::STATUS_OK);
    wheel_pub_.publish(ws);
    have_state_ = false;
    publish_status(ws.header.stamp, nullptr);
  }

  // ------------------------------------------------------------ diagnostics
  void diag_link(diagnostic_updater::DiagnosticStatusWrapper& d) {
    if (!link_up_)
      d.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "no link to the board");
    else if (!info_ok_)
      d.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "board does not match the base configuration");
    else
      d.summary(diagnostic_msgs::DiagnosticStatus::OK, "link up");
    d.add("port", o_.port);
    d.add("frames good", dec_.stats().frames_ok);
    d.add("frames bad (CRC)", dec_.stats().crc_errors);
    d.add("frames bad (length)", dec_.stats().length_errors);
    d.add("bytes skipped", dec_.stats().bytes_skipped);
    d.add("frames rejected by the board (NACK)", nacks_);
    d.add("unexpected frames", unexpected_frames_);
    d.add("board frames bad", have_state_ ? last_state_.frames_bad : 0);
    d.add("reconnects", reconnects_);
    d.add("port opens", port_opens_);
    d.add("next reconnect delay (s)", backoff_.current_delay());
    d.add("commands sent", commands_sent_);
    d.add("commands clamped (speed limit)", commands_saturated_);
    d.add("inputs dropped", dropped_inputs_);
    if (info_.motors) {
      d.add("firmware", std::to_string(info_.fw_major) + "." + std::to_string(info_.fw_minor));
      d.add("PWM frequency (Hz)", info_.pwm_hz);
    }
  }

  void diag_motors(diagnostic_updater::DiagnosticStatusWrapper& d) {
    if (!link_up_ || !have_state_) {
      d.summary(diagnostic_msgs::DiagnosticStatus::STALE, "motors considered stopped (no link)");
      return;
    }
    const uint8_t st = last_state_.status;
    if (st & (proto::kStatusOvercurrent | proto::kStatusEncoderFault))
      d.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "over-current or encoder fault");
    else if (st & proto::kStatusWatchdog)
      d.summary(diagnostic_msgs::DiagnosticStatus::WARN, "watchdog tripped: motors stopped by the board");
    else if (st & (proto::kStatusSaturated | proto::kStatusClamped))
      d.summary(diagnostic_msgs::DiagnosticStatus::WARN, "saturated or clamped");
    else
      d.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
    d.add("watchdog trips", last_state_.watchdog_trips);
    d.add("board time (s)", last_state_.time_ms * 1e-3);
    for (std::size_t i = 0; i < last_state_.motors.size(); ++i) {
      const MotorState& m = last_state_.motors[i];
      char buf[160];
      std::snprintf(buf, sizeof(buf), "setpoint %.3f rad/s, speed %.3f rad/s, duty %.3f, status 0x%02x", m.setpoint,
                    m.speed, m.duty, m.status);
      d.add("motor " + std::to_string(i), buf);
    }
  }

  NodeOptions o_;
  std::size_t n_ = 0;
  VelocityLimiter limiter_;
  BrianMapping brian_;
  EncoderOdometry odom_;
  Backoff backoff_;
  SerialPort port_;
  FrameDecoder dec_;
  std::vector<uint8_t> tx_;
  uint8_t seq_ = 0;

  Source source_ = Source::kNone;
  Twist2D twist_;
  std::vector<double> wheel_cmd_;
  ros::Time last_cmd_;
  double last_control_ = 0.0;

  bool link_up_ = false;
  bool answered_ = false;       // a valid frame arrived since the port was opened
  bool ever_answered_ = false;
  uint64_t port_opens_ = 0;
  double opened_at_ = 0.0;
  double last_frame_ = -1.0;
  bool info_ok_ = false;
  BoardInfo info_;
  uint64_t info_polls_ = 0;
  uint64_t control_cycles_ = 0;

  bool compact_ = false;  // SHORT_STATE format requested
  bool stream_confirmed_ = false;
  uint8_t stream_seq_ = 0;
  double window_start_ = 0.0;
  uint64_t window_good_ = 0, window_bad_ = 0;
  BoardCounters counters_;
  bool have_counters_ = false;
  double speed_ref_time_ = -1.0;
  std::vector<int64_t> speed_ref_counts_;
  std::vector<double> short_speed_;

  bool have_state_ = false;
  BoardState last_state_;
  StateTracker tracker_;

  uint64_t commands_sent_ = 0, commands_saturated_ = 0, dropped_inputs_ = 0, nacks_ = 0, unexpected_frames_ = 0;
  uint32_t reconnects_ = 0;

  ros::Publisher wheel_pub_, odom_pub_, status_pub_, sim_pub_;
  ros::Subscriber cmd_sub_, brian_sub_, wheel_sub_;
  ros::Timer control_timer_, read_timer_, diag_timer_;
  diagnostic_updater::Updater diag_;
  tf2_ros::TransformBroadcaster tf_;
};

}  // namespace mrt::airboard

int main(int argc, char** argv) {
  ros::init(argc, argv, "airboard_node");
  ros::NodeHandle nh, pnh("~");
  try {
    mrt::airboard::AirboardNode node(nh, pnh);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("airboard_node: %s", e.what());
    return 1;
  }
  return 0;
}
