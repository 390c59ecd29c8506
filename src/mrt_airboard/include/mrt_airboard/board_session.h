// The PC side of the AIRBoard link, ROS-free: the link session (connection,
// back-off, link timeout, board identification), stream switching between
// full STATE and compact SHORT_STATE frames, arbitration between the command
// sources (twist, Mr. BRIAN, wheel speeds, PWM duties) with the velocity
// limits, and the wheel-speed estimate of the compact stream. airboard_node
// is the ROS wiring around it.
//
// The session owns no thread and reads no clock: every call takes the host
// time `now` (s), so the tests drive it in simulated time against the
// firmware model (test/test_board_session.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mrt_airboard/kinematics.h"
#include "mrt_airboard/protocol.h"
#include "mrt_airboard/serial_port.h"
#include "mrt_airboard/state_tracker.h"
#include "mrt_common/brian_mapping.h"
#include "mrt_common/wheel_odometry.h"

namespace mrt::airboard {

/// Mr. BRIAN's commands as a twist, and the encoders' odometry: mrt_common's
/// (shared with the applications' in-process loops).
using mrt::common::BrianMapping;
using mrt::common::BrianMappingParams;
using mrt::common::WheelOdometry;

/// The byte link to the board. open(), read() and write() throw SerialError
/// when the device is missing or has gone (read and write close the link
/// first).
class BoardLink {
 public:
  virtual ~BoardLink() = default;
  virtual void open() = 0;
  virtual void close() = 0;
  virtual bool is_open() const = 0;
  /// What is available (0 when nothing), at most `cap` bytes.
  virtual std::size_t read(uint8_t* buf, std::size_t cap) = 0;
  virtual void write(const uint8_t* data, std::size_t n) = 0;
  /// Names the link in messages (the port path).
  virtual std::string name() const = 0;
};

/// A serial port (or a pty) as the board link.
class SerialLink : public BoardLink {
 public:
  SerialLink(std::string path, int baud) : path_(std::move(path)), baud_(baud) {}
  void open() override { port_.open(path_, baud_); }
  void close() override { port_.close(); }
  bool is_open() const override { return port_.is_open(); }
  std::size_t read(uint8_t* buf, std::size_t cap) override { return port_.read(buf, cap); }
  void write(const uint8_t* data, std::size_t n) override { port_.write(data, n); }
  std::string name() const override { return path_; }

 private:
  std::string path_;
  int baud_;
  SerialPort port_;
};

/// The node's options that shape the session (ROS parameters of the same
/// names, see the README).
struct SessionOptions {
  enum class StateFormat { kAuto, kState, kCompact };
  double rate = 50.0;              // Hz, control() is called at this rate
  double cmd_timeout = 0.5;        // s: an older command counts as none (stop)
  double link_timeout = 0.5;       // s without a valid frame: link lost
  int stream_period_ms = 10;       // full STATE stream period
  StateFormat state_format = StateFormat::kAuto;
  int compact_period_ms = 3;       // SHORT_STATE stream period
  double reconnect_min = 0.1;      // s, first back-off delay
  double reconnect_max = 2.0;      // s, longest back-off delay
  bool set_gains = false;          // send SET_GAINS(kp, ki) on connection
  double kp = 0.05, ki = 1.0;
  bool checked_commands = true;    // SET_SPEED / SET_PWM with the CRC-32 trailer (the board then refuses plain ones)
  BaseParams base;
  BrianMappingParams brian;

  /// Parses "auto" / "state" / "compact"; throws std::invalid_argument.
  static StateFormat parse_state_format(const std::string& s);
  /// Throws std::invalid_argument naming the first bad option (as its
  /// parameter, e.g. "~rate"); the base and the mapping validate themselves.
  void validate() const;
};

/// What the session tells its owner. Called from within the session's
/// calls; the default implementations do nothing.
class SessionListener {
 public:
  enum class Level { kInfo, kWarn, kError };
  virtual ~SessionListener() = default;
  /// A new board state (STATE, or a SHORT_STATE completed with the
  /// estimated speeds and the last counters); the session's tracker() and
  /// odometry() are up to date.
  virtual void on_state(const BoardState& /*s*/) {}
  /// The link was lost: the motors are considered stopped. Called before
  /// the tracker is reset (tracker().counts() are the last ones).
  virtual void on_link_lost() {}
  /// A message for the log. `throttle_key` non-empty: a recurring message,
  /// to be rate-limited per key.
  virtual void log(Level /*level*/, const std::string& /*throttle_key*/, const std::string& /*text*/) {}
};

/// Counters of the session (the node's diagnostics and AirboardStatus).
struct SessionStats {
  uint64_t commands_sent = 0;
  uint64_t commands_saturated = 0;  // clamped or scaled to the limits
  uint64_t dropped_inputs = 0;      // non-finite or malformed commands
  uint64_t nacks = 0;               // frames the board rejected
  uint64_t unexpected_frames = 0;
  uint64_t port_opens = 0;
  uint32_t reconnects = 0;          // links re-established after a first one
};

class BoardSession {
 public:
  /// Throws std::invalid_argument when the options are invalid.
  BoardSession(const SessionOptions& o, std::unique_ptr<BoardLink> link, SessionListener* listener);

  // ------------------------------------------------------------ commands
  /// Each returns false (and counts the input as dropped, keeping the
  /// previous command) when the input is non-finite or malformed.
  bool command_twist(const Twist2D& t, double now);
  bool command_brian(const std::vector<std::pair<std::string, double>>& commands, double now);
  enum class WheelMode { kSpeed, kPwm };
  /// Wheel speeds (rad/s) or PWM duties (-1..1, clamped), one per wheel.
  bool command_wheels(WheelMode mode, const std::vector<double>& values, double now);
  /// Counts (and logs) an input the caller could not even translate (e.g.
  /// an unknown wheel-command mode).
  void drop_input(const std::string& why);
  /// New wheel speed and acceleration limits (rad/s, rad/s^2; 0 = none) at
  /// run time (airboard_node's dynamic_reconfigure), applied from the next
  /// control period to twists, Mr. BRIAN's commands and wheel speeds alike.
  /// Throws std::invalid_argument naming the parameter, with nothing changed.
  void set_limits(double max_wheel_speed, double max_wheel_accel);

  // ------------------------------------------------------------ periodic
  /// The control period (at options.rate): (re)connects when due, checks
  /// the link timeout, adapts the stream format, and sends the command in
  /// force (a stop when none is fresh).
  void control(double now);
  /// Reads what the board sent (call every few ms) and handles its frames.
  void read(double now);

  // ------------------------------------------------------------ state
  bool link_up() const { return link_up_; }
  bool link_open() const { return link_->is_open(); }
  /// The board identified itself (INFO) as matching the base.
  bool info_ok() const { return info_ok_; }
  const BoardInfo& info() const { return info_; }
  /// SHORT_STATE frames requested.
  bool compact() const { return compact_; }
  bool have_state() const { return have_state_; }
  const BoardState& last_state() const { return last_state_; }
  const StateTracker& tracker() const { return tracker_; }
  const WheelOdometry& odometry() const { return odom_; }
  const FrameDecoder::Stats& frame_stats() const { return dec_.stats(); }
  const SessionStats& stats() const { return stats_; }
  double next_reconnect_delay() const { return backoff_.current_delay(); }
  const SessionOptions& options() const { return o_; }
  std::size_t wheel_count() const { return n_; }
  const BoardLink& link() const { return *link_; }

 private:
  enum class Source { kNone, kTwist, kWheelSpeed, kWheelPwm };

  void log(SessionListener::Level level, const std::string& key, const std::string& text);
  void connect(double now);
  void disconnect(const std::string& why);
  void request_stream();
  void adapt_format(double now);
  bool compact_allowed() const;
  uint32_t short_max_gap_ms() const;
  void send(const Frame& f);
  void send_pwm();
  void send_speed(bool fresh, double dt);
  void poll_info();
  void on_frame(const Frame& f, double now);
  void on_info(const BoardInfo& i);
  void on_state(const BoardState& s, double now);
  void on_short_state(const ShortState& ss, uint8_t seq, double now);
  void estimate_short_speed(const std::vector<int64_t>& counts, double t);
  void publish_state(const BoardState& s);
  void note_board_status(uint8_t status);

  SessionOptions o_;
  std::unique_ptr<BoardLink> link_;
  SessionListener* listener_;
  SessionListener null_listener_;
  std::size_t n_ = 0;
  VelocityLimiter limiter_;
  BrianMapping brian_;
  WheelOdometry odom_;
  Backoff backoff_;
  FrameDecoder dec_;
  std::vector<uint8_t> tx_;
  uint8_t seq_ = 0;
  SessionStats stats_;

  Source source_ = Source::kNone;
  Twist2D twist_;
  std::vector<double> wheel_cmd_;
  double last_cmd_ = 0.0;
  double last_control_ = 0.0;

  bool link_up_ = false;
  bool answered_ = false;  // a valid frame arrived since the link was opened
  bool ever_answered_ = false;
  double opened_at_ = 0.0;
  double last_frame_ = -1.0;
  double last_judged_ = -1.0;  // the previous control() call, for the link's silence
  double resumed_ = -1.0;       // the last control() after a gap (silence counts from here)
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
};

}  // namespace mrt::airboard
