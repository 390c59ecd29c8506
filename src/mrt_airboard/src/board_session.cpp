#include "mrt_airboard/board_session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mrt::airboard {

using Level = SessionListener::Level;

namespace {

void require(bool ok, const std::string& name, const std::string& expected) {
  if (!ok) throw std::invalid_argument("~" + name + ": expected " + expected);
}

std::string format(const char* fmt, double a, double b = 0.0) {
  char buf[200];
  std::snprintf(buf, sizeof(buf), fmt, a, b);
  return buf;
}

}  // namespace

// ---------------------------------------------------------------- options

SessionOptions::StateFormat SessionOptions::parse_state_format(const std::string& s) {
  if (s == "auto") return StateFormat::kAuto;
  if (s == "state") return StateFormat::kState;
  if (s == "compact") return StateFormat::kCompact;
  throw std::invalid_argument("~state_format: expected 'auto', 'state' or 'compact', got '" + s + "'");
}

void SessionOptions::validate() const {
  require(rate > 0.0 && rate <= 1000.0, "rate", "a number in (0, 1000] Hz");
  require(cmd_timeout > 0.0, "cmd_timeout", "a number > 0 s");
  require(link_timeout > 0.0, "link_timeout", "a number > 0 s");
  require(stream_period_ms >= 0 && stream_period_ms <= 65535, "stream_period_ms", "an integer in 0..65535");
  require(compact_period_ms >= 1 && compact_period_ms <= 65535, "compact_period_ms", "an integer in 1..65535");
  require(reconnect_min > 0.0, "reconnect_min", "a number > 0 s");
  require(reconnect_max >= reconnect_min, "reconnect_max", "a number >= ~reconnect_min");
  require(kp >= 0.0, "gains/kp", "a number >= 0");
  require(ki >= 0.0, "gains/ki", "a number >= 0");
  base.validate();
  brian.validate();
}

// ---------------------------------------------------------------- session

BoardSession::BoardSession(const SessionOptions& o, std::unique_ptr<BoardLink> link, SessionListener* listener)
    : o_((o.validate(), o)),
      link_(std::move(link)),
      listener_(listener ? listener : &null_listener_),
      n_(o_.base.wheel_count()),
      limiter_(o_.base),
      brian_(o_.brian),
      odom_(o_.base, o_.base.counts_per_rev),
      backoff_(o_.reconnect_min, o_.reconnect_max) {}

void BoardSession::set_limits(double max_wheel_speed, double max_wheel_accel) {
  limiter_.set_limits(max_wheel_speed, max_wheel_accel);  // validates first
  o_.base.max_wheel_speed = max_wheel_speed;
  o_.base.max_wheel_accel = max_wheel_accel;
}

void BoardSession::log(Level level, const std::string& key, const std::string& text) {
  listener_->log(level, key, text);
}

bool BoardSession::command_twist(const Twist2D& t, double now) {
  if (!std::isfinite(t.vx) || !std::isfinite(t.vy) || !std::isfinite(t.omega)) {
    ++stats_.dropped_inputs;
    log(Level::kWarn, "cmd_vel",
        "dropped a cmd_vel with a non-finite component (" + std::to_string(t.vx) + ", " + std::to_string(t.vy) +
            ", " + std::to_string(t.omega) + ")");
    return false;
  }
  twist_ = t;
  source_ = Source::kTwist;
  last_cmd_ = now;
  return true;
}

bool BoardSession::command_brian(const std::vector<std::pair<std::string, double>>& commands, double now) {
  const auto t = brian_.to_twist(commands);
  if (!t) {
    ++stats_.dropped_inputs;
    log(Level::kWarn, "brian",
        "dropped a brian_commands array with a non-finite " + o_.brian.speed_name + ", " + o_.brian.angle_name +
            " or " + o_.brian.rotation_name);
    return false;
  }
  twist_ = *t;
  source_ = Source::kTwist;
  last_cmd_ = now;
  return true;
}

bool BoardSession::command_wheels(WheelMode mode, const std::vector<double>& values, double now) {
  bool ok = values.size() == n_;
  for (double x : values) ok = ok && std::isfinite(x);
  if (!ok) {
    ++stats_.dropped_inputs;
    log(Level::kWarn, "wheel_cmd",
        "dropped a wheel_cmd (" + std::to_string(values.size()) + " values for " + std::to_string(n_) +
            " wheels, or a non-finite one)");
    return false;
  }
  wheel_cmd_ = values;
  source_ = mode == WheelMode::kPwm ? Source::kWheelPwm : Source::kWheelSpeed;
  last_cmd_ = now;
  return true;
}

void BoardSession::drop_input(const std::string& why) {
  ++stats_.dropped_inputs;
  log(Level::kWarn, "drop", "dropped " + why);
}

// ---------------------------------------------------------------- link

void BoardSession::connect(double now) {
  try {
    link_->open();
  } catch (const SerialError& e) {
    backoff_.failed(now);
    log(Level::kWarn, "open",
        std::string(e.what()) + format(" (retrying, next delay %.1f s)", backoff_.current_delay()));
    return;
  }
  // The back-off is reset by the board's first valid frame (on_frame), not
  // here: a port that opens but stays silent keeps backing off.
  ++stats_.port_opens;
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
  compact_ = o_.state_format == SessionOptions::StateFormat::kCompact;
  window_start_ = now;
  window_good_ = dec_.stats().frames_ok;
  window_bad_ = dec_.stats().frames_bad();
  request_stream();
  send(make_simple(proto::kGetInfo, seq_++));
  if (o_.set_gains) send(make_set_gains(seq_++, Gains{0xFF, o_.kp, o_.ki}));
  log(Level::kInfo, "", "opened " + link_->name());
}

void BoardSession::disconnect(const std::string& why) {
  if (!link_->is_open() && !link_up_) return;
  link_->close();
  link_up_ = false;
  log(Level::kWarn, "", "link lost (" + why + "); motors considered stopped, reconnecting");
  have_state_ = false;
  listener_->on_link_lost();
  tracker_.reset();
  odom_.reset();
  limiter_.reset();
}

// Asks the board for the stream in the format in use; until a frame of that
// format confirms it, control() repeats the request.
void BoardSession::request_stream() {
  stream_confirmed_ = false;
  stream_seq_ = seq_;
  if (compact_)
    send(make_set_stream(seq_++, static_cast<uint16_t>(o_.compact_period_ms), proto::kFormatCompact));
  else
    send(make_set_stream(seq_++, static_cast<uint16_t>(o_.stream_period_ms)));
}

// ~state_format auto: the full STATE (49 bytes for two motors) is the
// default; when the decoder discards more frames than it accepts, the line
// is too noisy for it (at 10 % of the bytes corrupted, 0.6 % of STATEs
// survive) and the board is asked for SHORT_STATE frames (17 bytes, 16.7 %
// survive) at a shorter period; back to STATE when fewer than one frame in
// six is discarded over 2 s.
void BoardSession::adapt_format(double now) {
  if (compact_ && !compact_allowed()) {
    compact_ = false;
    log(Level::kWarn, "",
        format("the board's max set-point %.3f rad/s does not fit SHORT_STATE: full STATE frames", info_.max_speed));
    request_stream();
    return;
  }
  if (o_.state_format != SessionOptions::StateFormat::kAuto || !compact_allowed()) return;
  const uint64_t good = dec_.stats().frames_ok - window_good_;
  const uint64_t bad = dec_.stats().frames_bad() - window_bad_;
  bool change = false;
  if (!compact_)
    change = bad >= 8 && bad > good;
  else
    change = now - window_start_ >= 2.0 && bad * 5 < good;
  if (change) {
    compact_ = !compact_;
    log(Level::kWarn, "",
        std::to_string(bad) + " of " + std::to_string(bad + good) + " frames bad: switching to " +
            (compact_ ? "compact SHORT_STATE" : "full STATE") + " frames");
    request_stream();
  }
  if (change || now - window_start_ >= (compact_ ? 2.0 : 1.0)) {
    window_start_ = now;
    window_good_ = dec_.stats().frames_ok;
    window_bad_ = dec_.stats().frames_bad();
  }
}

// SHORT_STATE carries set-points as i16 mrad/s: only for boards whose speed
// limit fits.
bool BoardSession::compact_allowed() const { return info_.motors == 0 || info_.max_speed <= 32.767; }

// Longest gap between SHORT_STATEs over which the 16-bit count difference is
// unambiguous: half the i16 range at 1.5 x the fastest wheel speed.
uint32_t BoardSession::short_max_gap_ms() const {
  const double w = 1.5 * std::max(o_.base.max_wheel_speed, info_.max_speed);
  const double counts_per_s = w * o_.base.counts_per_rev / (2.0 * M_PI);
  return static_cast<uint32_t>(std::max(1.0, 32767.0 / counts_per_s * 1000.0));
}

void BoardSession::send(const Frame& f) {
  if (!link_->is_open()) return;
  try {
    tx_.clear();
    append_frame(tx_, f);
    link_->write(tx_.data(), tx_.size());
  } catch (const SerialError& e) {
    disconnect(e.what());
  }
}

// ---------------------------------------------------------------- control

void BoardSession::control(double now) {
  // Time this session did not run (a starved process, a simulated clock's
  // jump) is not the board's silence: after a gap of half the link timeout
  // the board gets a whole timeout again.
  if (last_judged_ >= 0.0 && now - last_judged_ > 0.5 * o_.link_timeout) resumed_ = now;
  last_judged_ = now;
  if (!link_->is_open()) {
    if (backoff_.due(now)) connect(now);
    if (!link_->is_open()) return;
  }
  // What waits in the line first: a node starved longer than link_timeout
  // may run this before its read callback, with the board's frames unread.
  read(now);
  if (!link_->is_open()) return;
  const double last = std::max(last_frame_ >= 0.0 ? last_frame_ : opened_at_, resumed_);
  if (now - last > o_.link_timeout) {
    disconnect("no valid frame for " + std::to_string(o_.link_timeout) + " s");
    backoff_.failed(now);
    return;
  }
  adapt_format(now);
  // Re-send the stream request every second: idempotent, and it survives a
  // lost request or a board reset.
  ++control_cycles_;
  if (control_cycles_ % static_cast<uint64_t>(std::max(1.0, o_.rate)) == 0 ||
      (!stream_confirmed_ && control_cycles_ % 2 == 0))
    request_stream();
  if (!info_ok_) return poll_info();
  const bool fresh = source_ != Source::kNone && now - last_cmd_ <= o_.cmd_timeout;
  // While the board reports it stopped, each command is the first step of
  // the ramp at the nominal period, so repeated ones are identical.
  const double dt = last_control_ > 0.0 && !limiter_.board_stopped() ? now - last_control_ : 1.0 / o_.rate;
  last_control_ = now;
  if (fresh && source_ == Source::kWheelPwm) return send_pwm();
  send_speed(fresh, dt);
}

// Until the board identified itself as matching the base, keep asking and
// drive nothing: every period until a first INFO arrives (25 bytes: 7 % get
// through a line with 10 % of its bytes corrupted), then every 10th.
void BoardSession::poll_info() {
  if (info_.motors == 0 || ++info_polls_ % 10 == 0) send(make_simple(proto::kGetInfo, seq_++));
  send(make_simple(proto::kHeartbeat, seq_++));
}

void BoardSession::send_pwm() {
  std::vector<double> d = wheel_cmd_;
  bool clamped = false;
  for (double& x : d) {
    clamped = clamped || std::fabs(x) > 1.0;
    x = std::max(-1.0, std::min(1.0, x));
  }
  if (clamped) {
    ++stats_.commands_saturated;
    log(Level::kWarn, "duty", "wheel_cmd duty beyond +-1 clamped");
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
  send(make_set_pwm(seq_++, d, o_.checked_commands));
  ++stats_.commands_sent;
}

void BoardSession::send_speed(bool fresh, double dt) {
  std::vector<double> w;
  if (fresh && source_ == Source::kWheelSpeed) {
    w = wheel_cmd_;
    if (saturate_preserving_direction(w, o_.base.max_wheel_speed) < 1.0) ++stats_.commands_saturated;
    limiter_.hold(w);
  } else {
    const auto r = limiter_.update(fresh ? twist_ : Twist2D{}, dt);
    if (r.saturated) {
      ++stats_.commands_saturated;
      log(Level::kWarn, "saturated",
          format("command exceeds max_wheel_speed %.2f rad/s, scaled down", o_.base.max_wheel_speed));
    }
    w = r.wheels;
  }
  send(make_set_speed(seq_++, w, o_.checked_commands));
  ++stats_.commands_sent;
}

// ---------------------------------------------------------------- frames

void BoardSession::read(double now) {
  if (!link_->is_open()) return;
  uint8_t buf[1024];
  try {
    for (int i = 0; i < 16; ++i) {
      const std::size_t n = link_->read(buf, sizeof(buf));
      if (n == 0) break;
      dec_.feed(buf, n, [this, now](const Frame& f) { on_frame(f, now); });
    }
  } catch (const SerialError& e) {
    disconnect(e.what());
    backoff_.failed(now);
  }
}

void BoardSession::on_frame(const Frame& f, double now) {
  last_frame_ = now;
  link_up_ = true;
  if (!answered_) {
    answered_ = true;
    backoff_.succeeded();
    if (ever_answered_) ++stats_.reconnects;
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
    ++stats_.nacks;
    log(Level::kWarn, "nack",
        "board rejected a frame of type " + std::to_string(t) + " (reason " + std::to_string(reason) + ")");
    return;
  }
  ++stats_.unexpected_frames;
}

void BoardSession::on_info(const BoardInfo& i) {
  info_ = i;
  const bool ok = i.motors == n_ && static_cast<int>(i.counts_per_rev) == o_.base.counts_per_rev;
  if (!ok) {
    log(Level::kError, "info",
        "the board reports " + std::to_string(i.motors) + " motors and " + std::to_string(i.counts_per_rev) +
            " counts/rev; base '" + o_.base.name + "' needs " + std::to_string(n_) + " and " +
            std::to_string(o_.base.counts_per_rev) + " (parameter '~base/counts_per_rev'): not driving");
  } else if (!info_ok_) {
    log(Level::kInfo, "",
        "board firmware " + std::to_string(i.fw_major) + "." + std::to_string(i.fw_minor) + ", " +
            std::to_string(i.motors) + " motors, " + std::to_string(i.counts_per_rev) + " counts/rev, PI at " +
            std::to_string(i.control_hz) + " Hz, PWM " + std::to_string(i.pwm_hz) + " Hz, watchdog " +
            std::to_string(i.watchdog_ms) + " ms");
  }
  info_ok_ = ok;
}

void BoardSession::on_state(const BoardState& s, double now) {
  if (s.motors.size() != n_) {
    ++stats_.unexpected_frames;
    return;
  }
  note_board_status(s.status);
  counters_ = BoardCounters{s.since_cmd_ms, s.frames_bad, s.watchdog_trips};
  have_counters_ = true;
  if (!tracker_.update(s, now)) {
    last_state_ = s;  // same board instant (a reply and a streamed frame): nothing new to integrate
    return;
  }
  speed_ref_time_ = -1.0;  // STATE carries the board's own measured speeds
  publish_state(s);
}

// A state with the WATCHDOG bit: the board zeroed its set-points and applied
// none of the commands sent since (the bit is latched until one is): the
// acceleration ramp restarts from rest, not from the old target. The first
// state without the bit releases it.
void BoardSession::note_board_status(uint8_t status) {
  limiter_.set_board_stopped((status & proto::kStatusWatchdog) != 0);
}

// SHORT_STATE: clock and counts unwrapped by the tracker, set-points and
// status from the board; the measured speed is computed here from the counts
// (over >= 10 ms), the duty is not carried (NaN), the counters are the last
// COUNTERS' (or STATE's).
void BoardSession::on_short_state(const ShortState& ss, uint8_t seq, double now) {
  if (ss.ticks.size() != n_) {
    ++stats_.unexpected_frames;
    return;
  }
  note_board_status(ss.status);
  if (!tracker_.update_short(ss, now, short_max_gap_ms())) return;
  if (tracker_.rebased()) {
    odom_.reset();
    speed_ref_time_ = -1.0;
  }
  const std::vector<int64_t>& counts = tracker_.counts();
  const double t = tracker_.board_time();
  estimate_short_speed(counts, t);
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

// Wheel speeds of the compact stream: count differences over at least 10 ms
// of board time; the first SHORT_STATE after a STATE (or a re-base) keeps
// the last STATE's measured speeds.
void BoardSession::estimate_short_speed(const std::vector<int64_t>& counts, double t) {
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
}

void BoardSession::publish_state(const BoardState& s) {
  last_state_ = s;
  have_state_ = true;
  odom_.update(tracker_.counts(), tracker_.board_time());
  listener_->on_state(s);
}

}  // namespace mrt::airboard
