#include "mrt_airboard/protocol.h"

#include <cmath>
#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <boost/crc.hpp>

namespace mrt::airboard {

uint16_t crc16_ccitt(const uint8_t* data, std::size_t n, uint16_t crc) {
  // CRC-16/CCITT-FALSE: polynomial 0x1021, MSB first, no final XOR, so the
  // running value is also the remainder a chained call starts from.
  boost::crc_optimal<16, 0x1021, 0xFFFF, 0, false, false> c(crc);
  c.process_bytes(data, n);
  return c.checksum();
}

void append_frame(std::vector<uint8_t>& out, const Frame& f) {
  if (f.payload.size() > proto::kMaxPayload)
    throw std::invalid_argument("append_frame: payload of " + std::to_string(f.payload.size()) +
                                " bytes exceeds " + std::to_string(proto::kMaxPayload));
  const std::size_t at = out.size();
  out.push_back(proto::kStart);
  out.push_back(static_cast<uint8_t>(f.payload.size()));
  out.push_back(f.type);
  out.push_back(f.seq);
  out.insert(out.end(), f.payload.begin(), f.payload.end());
  const uint16_t crc = crc16_ccitt(out.data() + at + 1, f.payload.size() + 3);
  out.push_back(static_cast<uint8_t>(crc & 0xFF));
  out.push_back(static_cast<uint8_t>(crc >> 8));
}

std::vector<uint8_t> encode_frame(const Frame& f) {
  std::vector<uint8_t> out;
  out.reserve(f.payload.size() + proto::kOverhead);
  append_frame(out, f);
  return out;
}

// ---------------------------------------------------------------- decoder

void FrameDecoder::drop(std::size_t k) {
  if (k >= len_) {
    len_ = 0;
    return;
  }
  std::memmove(buf_, buf_ + k, len_ - k);
  len_ -= k;
}

void FrameDecoder::feed(const uint8_t* data, std::size_t n,
                        const std::function<void(const Frame&)>& on_frame) {
  std::size_t i = 0;
  while (i < n) {
    if (len_ == 0) {
      // Fast skip of garbage between frames.
      const void* p = std::memchr(data + i, proto::kStart, n - i);
      if (!p) {
        stats_.bytes_skipped += n - i;
        return;
      }
      const std::size_t j = static_cast<std::size_t>(static_cast<const uint8_t*>(p) - data);
      stats_.bytes_skipped += j - i;
      i = j;
    }
    // Copy as much as the pending frame still needs (its header first), in one go.
    const std::size_t want = len_ < 2 ? 2 : (buf_[1] > proto::kMaxPayload ? 2 : buf_[1] + proto::kOverhead);
    const std::size_t k = std::min(want > len_ ? want - len_ : 1, n - i);
    std::memcpy(buf_ + len_, data + i, k);
    len_ += k;
    i += k;
    parse(on_frame);
  }
}

void FrameDecoder::parse(const std::function<void(const Frame&)>& on_frame) {
  while (len_ > 0) {
    if (buf_[0] != proto::kStart) {
      std::size_t k = 1;
      while (k < len_ && buf_[k] != proto::kStart) ++k;
      stats_.bytes_skipped += k;
      drop(k);
      continue;
    }
    if (len_ < 2) return;
    const std::size_t plen = buf_[1];
    if (plen > proto::kMaxPayload) {
      ++stats_.length_errors;
      drop(1);
      continue;
    }
    const std::size_t total = plen + proto::kOverhead;
    if (len_ < total) return;
    const uint16_t want = crc16_ccitt(buf_ + 1, plen + 3);
    const uint16_t got = static_cast<uint16_t>(buf_[total - 2] | (buf_[total - 1] << 8));
    if (want != got) {
      ++stats_.crc_errors;
      drop(1);
      continue;
    }
    ++stats_.frames_ok;
    scratch_.type = buf_[2];
    scratch_.seq = buf_[3];
    scratch_.payload.assign(buf_ + 4, buf_ + 4 + plen);
    drop(total);
    on_frame(scratch_);
  }
}

// ---------------------------------------------------------------- fixed point

namespace {

template <typename T>
T round_sat(double v) {
  if (std::isnan(v)) return 0;
  const double r = std::round(v);
  if (r >= static_cast<double>(std::numeric_limits<T>::max())) return std::numeric_limits<T>::max();
  if (r <= static_cast<double>(std::numeric_limits<T>::min())) return std::numeric_limits<T>::min();
  return static_cast<T>(r);
}

struct Writer {
  std::vector<uint8_t>& b;
  void u8(uint8_t v) { b.push_back(v); }
  void u16(uint16_t v) {
    b.push_back(static_cast<uint8_t>(v));
    b.push_back(static_cast<uint8_t>(v >> 8));
  }
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<uint8_t>(v >> (8 * i)));
  }
  void i16(int16_t v) { u16(static_cast<uint16_t>(v)); }
  void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
};

struct Reader {
  const std::vector<uint8_t>& b;
  std::size_t at = 0;
  uint8_t u8() { return b[at++]; }
  uint16_t u16() {
    const uint16_t v = static_cast<uint16_t>(b[at] | (b[at + 1] << 8));
    at += 2;
    return v;
  }
  uint32_t u32() {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(b[at + i]) << (8 * i);
    at += 4;
    return v;
  }
  int16_t i16() { return static_cast<int16_t>(u16()); }
  int32_t i32() { return static_cast<int32_t>(u32()); }
};

Frame frame(uint8_t type, uint8_t seq) {
  Frame f;
  f.type = type;
  f.seq = seq;
  return f;
}

void check_motors(std::size_t n) {
  if (n == 0 || n > proto::kMaxMotors)
    throw std::invalid_argument("AIRBoard frames carry 1.." + std::to_string(proto::kMaxMotors) +
                                " motors, got " + std::to_string(n));
}

}  // namespace

int32_t to_mrad(double v) { return round_sat<int32_t>(v * 1000.0); }
int16_t to_duty(double v) { return round_sat<int16_t>(v * 10000.0); }
int32_t to_q16(double v) { return round_sat<int32_t>(v * 65536.0); }

uint32_t command_check(const Frame& f, std::size_t n) {
  boost::crc_32_type c;
  const uint8_t head[2] = {f.type, f.seq};
  c.process_bytes(head, 2);
  c.process_bytes(f.payload.data(), std::min(n, f.payload.size()));
  return c.checksum();
}

namespace {
void append_check(Frame& f) {
  const uint32_t c = command_check(f, f.payload.size());
  for (int i = 0; i < 4; ++i) f.payload.push_back(static_cast<uint8_t>(c >> (8 * i)));
}

// The set command's body length for its motor count n and element size;
// 0 when the length is neither the plain nor the checked one.
std::size_t set_body(const Frame& f, std::size_t elem, bool* checked) {
  if (f.payload.empty()) return 0;
  const std::size_t n = f.payload[0];
  if (n == 0 || n > proto::kMaxMotors) return 0;
  const std::size_t body = 1 + elem * n;
  *checked = f.payload.size() == body + proto::kCheckSize;
  return (f.payload.size() == body || *checked) ? body : 0;
}

bool check_ok(const Frame& f, std::size_t body) {
  const uint8_t* p = f.payload.data() + body;
  const uint32_t c = p[0] | (p[1] << 8) | (p[2] << 16) | (static_cast<uint32_t>(p[3]) << 24);
  return c == command_check(f, body);
}
}  // namespace

Frame make_set_speed(uint8_t seq, const std::vector<double>& speeds, bool checked) {
  check_motors(speeds.size());
  Frame f = frame(proto::kSetSpeed, seq);
  Writer w{f.payload};
  w.u8(static_cast<uint8_t>(speeds.size()));
  for (double s : speeds) w.i32(to_mrad(s));
  if (checked) append_check(f);
  return f;
}

Frame make_set_pwm(uint8_t seq, const std::vector<double>& duties, bool checked) {
  check_motors(duties.size());
  Frame f = frame(proto::kSetPwm, seq);
  Writer w{f.payload};
  w.u8(static_cast<uint8_t>(duties.size()));
  for (double d : duties) w.i16(to_duty(d));
  if (checked) append_check(f);
  return f;
}

bool set_check_failed(const Frame& f) {
  bool checked = false;
  std::size_t body = 0;
  if (f.type == proto::kSetSpeed) body = set_body(f, 4, &checked);
  else if (f.type == proto::kSetPwm) body = set_body(f, 2, &checked);
  return body > 0 && checked && !check_ok(f, body);
}

Frame make_set_gains(uint8_t seq, const Gains& g) {
  Frame f = frame(proto::kSetGains, seq);
  Writer w{f.payload};
  w.u8(g.motor);
  w.i32(to_q16(g.kp));
  w.i32(to_q16(g.ki));
  return f;
}

Frame make_simple(uint8_t type, uint8_t seq) { return frame(type, seq); }

Frame make_set_stream(uint8_t seq, uint16_t period_ms) {
  Frame f = frame(proto::kSetStream, seq);
  Writer w{f.payload};
  w.u16(period_ms);
  return f;
}

Frame make_set_stream(uint8_t seq, uint16_t period_ms, uint8_t format) {
  Frame f = make_set_stream(seq, period_ms);
  f.payload.push_back(format);
  return f;
}

Frame make_short_state(uint8_t seq, const BoardState& s) {
  check_motors(s.motors.size());
  Frame f = frame(proto::kShortState, seq);
  Writer w{f.payload};
  w.u16(static_cast<uint16_t>(s.time_ms));
  w.u8(s.status);
  for (const MotorState& m : s.motors) {
    w.i16(static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(m.ticks))));
    w.i16(round_sat<int16_t>(m.setpoint * 1000.0));
  }
  return f;
}

Frame make_counters(uint8_t seq, const BoardState& s) {
  Frame f = frame(proto::kCounters, seq);
  Writer w{f.payload};
  w.u16(s.since_cmd_ms);
  w.u16(s.frames_bad);
  w.u16(s.watchdog_trips);
  return f;
}

Frame make_state(uint8_t seq, const BoardState& s) {
  check_motors(s.motors.size());
  Frame f = frame(proto::kState, seq);
  Writer w{f.payload};
  w.u32(s.time_ms);
  w.u8(s.status);
  w.u8(s.last_seq);
  w.u16(s.since_cmd_ms);
  w.u16(s.frames_bad);
  w.u16(s.watchdog_trips);
  w.u8(static_cast<uint8_t>(s.motors.size()));
  for (const MotorState& m : s.motors) {
    w.i32(m.ticks);
    w.i32(to_mrad(m.speed));
    w.i32(to_mrad(m.setpoint));
    w.i16(to_duty(m.duty));
    w.u8(m.status);
  }
  return f;
}

Frame make_info(uint8_t seq, const BoardInfo& i) {
  Frame f = frame(proto::kInfo, seq);
  Writer w{f.payload};
  w.u8(i.fw_major);
  w.u8(i.fw_minor);
  w.u8(i.motors);
  w.u32(i.counts_per_rev);
  w.u16(i.control_hz);
  w.u32(i.pwm_hz);
  w.i32(to_mrad(i.max_speed));
  w.u16(i.watchdog_ms);
  return f;
}

Frame make_nack(uint8_t seq, uint8_t type, uint8_t reason) {
  Frame f = frame(proto::kNack, seq);
  f.payload = {type, reason};
  return f;
}

bool parse_set_speed(const Frame& f, std::vector<double>* speeds, bool* checked) {
  bool chk = false;
  if (f.type != proto::kSetSpeed) return false;
  const std::size_t body = set_body(f, 4, &chk);
  if (body == 0 || (chk && !check_ok(f, body))) return false;
  if (checked) *checked = chk;
  const std::size_t n = f.payload[0];
  Reader r{f.payload, 1};
  speeds->resize(n);
  for (std::size_t i = 0; i < n; ++i) (*speeds)[i] = r.i32() / 1000.0;
  return true;
}

bool parse_set_pwm(const Frame& f, std::vector<double>* duties, bool* checked) {
  bool chk = false;
  if (f.type != proto::kSetPwm) return false;
  const std::size_t body = set_body(f, 2, &chk);
  if (body == 0 || (chk && !check_ok(f, body))) return false;
  if (checked) *checked = chk;
  const std::size_t n = f.payload[0];
  Reader r{f.payload, 1};
  duties->resize(n);
  for (std::size_t i = 0; i < n; ++i) (*duties)[i] = r.i16() / 10000.0;
  return true;
}

bool parse_set_gains(const Frame& f, Gains* g) {
  if (f.type != proto::kSetGains || f.payload.size() != 9) return false;
  Reader r{f.payload};
  g->motor = r.u8();
  g->kp = r.i32() / 65536.0;
  g->ki = r.i32() / 65536.0;
  return true;
}

bool parse_set_stream(const Frame& f, uint16_t* period_ms, uint8_t* format) {
  if (f.type != proto::kSetStream || (f.payload.size() != 2 && f.payload.size() != 3)) return false;
  Reader r{f.payload};
  *period_ms = r.u16();
  if (format) *format = f.payload.size() == 3 ? r.u8() : proto::kFormatState;
  return true;
}

bool parse_short_state(const Frame& f, ShortState* s) {
  if (f.type != proto::kShortState || f.payload.size() < 3 || (f.payload.size() - 3) % 4 != 0) return false;
  const std::size_t n = (f.payload.size() - 3) / 4;
  if (n == 0 || n > proto::kMaxMotors) return false;
  Reader r{f.payload};
  s->time_ms = r.u16();
  s->status = r.u8();
  s->ticks.resize(n);
  s->setpoints.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s->ticks[i] = r.i16();
    s->setpoints[i] = r.i16() / 1000.0;
  }
  return true;
}

bool parse_counters(const Frame& f, BoardCounters* c) {
  if (f.type != proto::kCounters || f.payload.size() != 6) return false;
  Reader r{f.payload};
  c->since_cmd_ms = r.u16();
  c->frames_bad = r.u16();
  c->watchdog_trips = r.u16();
  return true;
}

bool parse_state(const Frame& f, BoardState* s) {
  if (f.type != proto::kState || f.payload.size() < 13) return false;
  const std::size_t n = f.payload[12];
  if (n == 0 || n > proto::kMaxMotors || f.payload.size() != 13 + 15 * n) return false;
  Reader r{f.payload};
  s->time_ms = r.u32();
  s->status = r.u8();
  s->last_seq = r.u8();
  s->since_cmd_ms = r.u16();
  s->frames_bad = r.u16();
  s->watchdog_trips = r.u16();
  r.u8();
  s->motors.resize(n);
  for (MotorState& m : s->motors) {
    m.ticks = r.i32();
    m.speed = r.i32() / 1000.0;
    m.setpoint = r.i32() / 1000.0;
    m.duty = r.i16() / 10000.0;
    m.status = r.u8();
  }
  return true;
}

bool parse_info(const Frame& f, BoardInfo* i) {
  if (f.type != proto::kInfo || f.payload.size() != 19) return false;
  Reader r{f.payload};
  i->fw_major = r.u8();
  i->fw_minor = r.u8();
  i->motors = r.u8();
  i->counts_per_rev = r.u32();
  i->control_hz = r.u16();
  i->pwm_hz = r.u32();
  i->max_speed = r.i32() / 1000.0;
  i->watchdog_ms = r.u16();
  return true;
}

bool parse_nack(const Frame& f, uint8_t* type, uint8_t* reason) {
  if (f.type != proto::kNack || f.payload.size() != 2) return false;
  *type = f.payload[0];
  *reason = f.payload[1];
  return true;
}

}  // namespace mrt::airboard
