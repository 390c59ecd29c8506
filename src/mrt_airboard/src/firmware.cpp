#include "mrt_airboard/firmware.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::airboard {

namespace {
constexpr double kTwoPi = 2.0 * mrt::common::kPi;
}

Firmware::Firmware(const FirmwareConfig& c) : c_(c) {
  if (c_.motors < 1 || c_.motors > static_cast<int>(proto::kMaxMotors))
    throw std::invalid_argument("Firmware: motors must be 1.." + std::to_string(proto::kMaxMotors));
  if (c_.control_hz <= 0 || c_.counts_per_rev == 0 || c_.tau <= 0.0 || c_.no_load_speed <= 0.0 ||
      c_.pwm_steps <= 0 || c_.speed_window_ms <= 0 || c_.max_speed <= 0.0)
    throw std::invalid_argument("Firmware: invalid configuration");
  dt_ = 1.0 / c_.control_hz;
  m_.resize(c_.motors);
  for (Motor& m : m_) {
    m.hist.assign(c_.speed_window_ms, 0);
    m.kp = c_.kp;
    m.ki = c_.ki;
  }
}

std::vector<uint8_t> Firmware::take_output() {
  std::vector<uint8_t> o;
  o.swap(out_);
  return o;
}

void Firmware::receive(const uint8_t* data, std::size_t n) {
  dec_.feed(data, n, [this](const Frame& f) { handle(f); });
}

void Firmware::command_received(uint8_t seq) {
  since_cmd_ = 0;
  armed_ = true;
  tripped_ = false;
  last_seq_ = seq;
  ++applied_;
}

// Strict mode: once a checked set command was applied (or from power-up with
// FirmwareConfig::require_checked), plain ones are refused, so damage that
// turns a checked frame into a plain one (it must also pass the CRC-16) is
// not applied either.
bool Firmware::accept_check(bool checked) {
  if (checked) {
    strict_ = true;
    return true;
  }
  return !strict_ && !c_.require_checked;
}

template <class Nack>
void Firmware::refuse_set(const Frame& f, const Nack& nack) {
  if (set_check_failed(f)) {
    ++check_failures_;
    return nack(proto::kNackBadCheck);
  }
  return nack(proto::kNackBadLength);
}

void Firmware::handle(const Frame& f) {
  auto nack = [&](uint8_t reason) {
    ++rejected_;
    append_frame(out_, make_nack(f.seq, f.type, reason));
  };
  switch (f.type) {
    case proto::kSetSpeed: {
      std::vector<double> sp;
      bool checked = false;
      if (!parse_set_speed(f, &sp, &checked)) return refuse_set(f, nack);
      if (static_cast<int>(sp.size()) != c_.motors) return nack(proto::kNackBadMotorCount);
      if (!accept_check(checked)) return nack(proto::kNackUnchecked);
      for (std::size_t i = 0; i < sp.size(); ++i) {
        Motor& m = m_[i];
        m.clamped = std::fabs(sp[i]) > c_.max_speed;
        const double v = std::clamp(sp[i], -c_.max_speed, c_.max_speed);
        if (mode_ != Mode::kSpeed) m.integ = 0.0;
        m.setpoint = v;
      }
      mode_ = Mode::kSpeed;
      command_received(f.seq);
      return reply_set(f.seq);
    }
    case proto::kSetPwm: {
      std::vector<double> d;
      bool checked = false;
      if (!parse_set_pwm(f, &d, &checked)) return refuse_set(f, nack);
      if (static_cast<int>(d.size()) != c_.motors) return nack(proto::kNackBadMotorCount);
      if (!accept_check(checked)) return nack(proto::kNackUnchecked);
      for (std::size_t i = 0; i < d.size(); ++i) {
        m_[i].clamped = std::fabs(d[i]) > 1.0;
        m_[i].duty_cmd = std::clamp(d[i], -1.0, 1.0);
        m_[i].setpoint = 0.0;
      }
      mode_ = Mode::kPwm;
      command_received(f.seq);
      return reply_set(f.seq);
    }
    case proto::kSetGains: {
      Gains g;
      if (!parse_set_gains(f, &g)) return nack(proto::kNackBadLength);
      if (g.kp < 0.0 || g.ki < 0.0 || (g.motor != 0xFF && g.motor >= m_.size()))
        return nack(proto::kNackBadArgument);
      for (std::size_t i = 0; i < m_.size(); ++i)
        if (g.motor == 0xFF || g.motor == i) {
          m_[i].kp = g.kp;
          m_[i].ki = g.ki;
          m_[i].integ = 0.0;
        }
      return reply_state(f.seq);
    }
    case proto::kGetState:
      if (!f.payload.empty()) return nack(proto::kNackBadLength);
      return reply_state(f.seq);
    case proto::kHeartbeat:
      if (!f.payload.empty()) return nack(proto::kNackBadLength);
      since_cmd_ = 0;  // keeps the watchdog quiet, does not re-arm a tripped one
      return reply_set(f.seq);
    case proto::kSetStream: {
      uint16_t p;
      uint8_t format;
      if (!parse_set_stream(f, &p, &format)) return nack(proto::kNackBadLength);
      if (format != proto::kFormatState && format != proto::kFormatCompact) return nack(proto::kNackBadArgument);
      stream_ms_ = p;
      format_ = format;
      return reply_state(f.seq);
    }
    case proto::kGetInfo:
      if (!f.payload.empty()) return nack(proto::kNackBadLength);
      append_frame(out_, make_info(f.seq, info()));
      return;
    default:
      return nack(proto::kNackUnknownType);
  }
}

void Firmware::reply_state(uint8_t seq) { append_frame(out_, make_state(seq, state())); }

void Firmware::reply_set(uint8_t seq) {
  if (format_ == proto::kFormatCompact)
    append_frame(out_, make_short_state(seq, state()));
  else
    reply_state(seq);
}

BoardState Firmware::state() const {
  BoardState s;
  s.time_ms = time_ms_;
  s.last_seq = last_seq_;
  s.since_cmd_ms = static_cast<uint16_t>(std::min<uint32_t>(since_cmd_, 0xFFFF));
  s.frames_bad = static_cast<uint16_t>(dec_.stats().frames_bad());
  s.watchdog_trips = static_cast<uint16_t>(trips_);
  for (const Motor& m : m_) {
    MotorState ms;
    ms.ticks = static_cast<int32_t>(static_cast<uint32_t>(m.ticks));  // wraps like the board's counter
    ms.speed = m.meas;
    ms.setpoint = m.setpoint;
    ms.duty = m.duty;
    ms.status = m.status | (m.clamped ? proto::kStatusClamped : 0) | (tripped_ ? proto::kStatusWatchdog : 0);
    s.status |= ms.status;
    s.motors.push_back(ms);
  }
  if (mode_ == Mode::kPwm) s.status |= proto::kStatusPwmMode;
  return s;
}

BoardInfo Firmware::info() const {
  BoardInfo i;
  i.fw_major = 1;
  i.fw_minor = 0;
  i.motors = static_cast<uint8_t>(c_.motors);
  i.counts_per_rev = c_.counts_per_rev;
  i.control_hz = static_cast<uint16_t>(c_.control_hz);
  i.pwm_hz = c_.pwm_hz;
  i.max_speed = c_.max_speed;
  i.watchdog_ms = c_.watchdog_ms;
  return i;
}

void Firmware::control(Motor& m) {
  m.status = 0;
  double u = 0.0;
  switch (mode_) {
    case Mode::kSpeed: {
      const double e = m.setpoint - m.meas;
      const double u_unsat = c_.kff * m.setpoint + m.kp * e + m.ki * (m.integ + e * dt_);
      // Anti-windup: integrate only when that does not push further into saturation.
      if (std::fabs(u_unsat) < 1.0 || (u_unsat > 0) != (e > 0)) m.integ += e * dt_;
      u = c_.kff * m.setpoint + m.kp * e + m.ki * m.integ;
      break;
    }
    case Mode::kPwm:
      u = m.duty_cmd;
      break;
    case Mode::kBrake:
      u = 0.0;  // H-bridge low sides on: short-circuit brake
      m.integ = 0.0;
      break;
  }
  // Current limit (the board measures the motor current): i = I_stall (u - w / w0).
  const double back = m.w / c_.no_load_speed;
  const double lim = c_.current_limit / c_.stall_current;
  if (u - back > lim) {
    u = back + lim;
    m.status |= proto::kStatusOvercurrent;
  } else if (u - back < -lim) {
    u = back - lim;
    m.status |= proto::kStatusOvercurrent;
  }
  if (u > 1.0 || u < -1.0) {
    u = std::clamp(u, -1.0, 1.0);
    m.status |= proto::kStatusSaturated;
  }
  // The CCP module has pwm_steps discrete duty levels.
  m.duty = std::round(u * c_.pwm_steps) / c_.pwm_steps;
}

void Firmware::step() {
  ++time_ms_;
  if (since_cmd_ < 0xFFFFFFFFu) ++since_cmd_;
  if (armed_ && since_cmd_ >= c_.watchdog_ms) {
    armed_ = false;
    tripped_ = true;
    ++trips_;
    mode_ = Mode::kBrake;
    for (Motor& m : m_) {
      m.setpoint = 0.0;
      m.duty_cmd = 0.0;
      m.integ = 0.0;
    }
  }
  const double a = 1.0 - std::exp(-dt_ / c_.tau);
  const double counts_per_rad = c_.counts_per_rev / kTwoPi;
  for (Motor& m : m_) {
    control(m);
    // Plant: exact discretisation of the first-order motor over one period.
    const double w_ss = m.duty * c_.no_load_speed;
    const double w0 = m.w;
    m.w = w_ss + (w0 - w_ss) * (1.0 - a);
    // Angle: integral of the exponential approach over the period.
    m.angle += w_ss * dt_ + (w0 - w_ss) * c_.tau * a;
    // Quadrature decoder count (x4), exact: floor of the angle in counts.
    m.ticks = static_cast<int64_t>(std::floor(m.angle * counts_per_rad));
    // Measured speed over the sliding window.
    const int64_t old = m.hist[hist_at_];
    m.hist[hist_at_] = m.ticks;
    const double window = std::min<double>(time_ms_, c_.speed_window_ms) * dt_;
    m.meas = static_cast<double>(m.ticks - old) / counts_per_rad / window;
  }
  hist_at_ = (hist_at_ + 1) % static_cast<std::size_t>(c_.speed_window_ms);
  if (stream_ms_ > 0 && time_ms_ % stream_ms_ == 0) {
    if (format_ == proto::kFormatCompact) {
      const BoardState s = state();
      append_frame(out_, make_short_state(last_seq_, s));
      if (++streamed_ % proto::kCountersEvery == 0) append_frame(out_, make_counters(last_seq_, s));
    } else {
      reply_state(last_seq_);
    }
  }
}

}  // namespace mrt::airboard
