// The PC <-> AIRBoard serial protocol (specified byte by byte in the
// package's doc/protocol.md). ROS-free.
//
// Frame:  0xA5 | LEN | TYPE | SEQ | PAYLOAD (LEN bytes) | CRC_L | CRC_H
// LEN is the payload length (0..kMaxPayload). The CRC is CRC-16/CCITT-FALSE
// (poly 0x1021, init 0xFFFF, no reflection, no final xor) over LEN, TYPE,
// SEQ and the payload, sent low byte first. Every multi-byte field is
// little-endian (the PIC18's order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace mrt::airboard {

namespace proto {
constexpr uint8_t kStart = 0xA5;
constexpr std::size_t kMaxPayload = 96;
constexpr std::size_t kOverhead = 6;  // start, len, type, seq, crc x2
constexpr std::size_t kMaxFrame = kMaxPayload + kOverhead;
constexpr std::size_t kMaxMotors = 4;

// PC -> board.
constexpr uint8_t kSetSpeed = 0x01;   // u8 n, n x i32 set-point [mrad/s]
constexpr uint8_t kSetPwm = 0x02;     // u8 n, n x i16 duty [1e-4]
constexpr uint8_t kSetGains = 0x03;   // u8 motor (0xFF all), i32 kp, i32 ki [Q16.16]
constexpr uint8_t kGetState = 0x04;   // empty
constexpr uint8_t kHeartbeat = 0x05;  // empty
constexpr uint8_t kSetStream = 0x06;  // u16 period [ms], 0 = off [, u8 format]
constexpr uint8_t kGetInfo = 0x07;    // empty
// Board -> PC.
constexpr uint8_t kState = 0x81;
constexpr uint8_t kInfo = 0x82;
constexpr uint8_t kNack = 0x8F;       // u8 rejected type, u8 reason
constexpr uint8_t kShortState = 0x83; // u16 time, u8 status, n x (i16 count, i16 set-point)
constexpr uint8_t kCounters = 0x84;   // u16 since_cmd, u16 frames_bad, u16 watchdog_trips

// SET_STREAM formats (optional third payload byte).
constexpr uint8_t kFormatState = 0;    // stream STATE, answer set commands with STATE
constexpr uint8_t kFormatCompact = 1;  // stream SHORT_STATE (+ COUNTERS), answer set commands with SHORT_STATE
constexpr int kCountersEvery = 10;     // compact format: COUNTERS after every 10th streamed SHORT_STATE

// Status bits, per motor and (OR of the motors plus the board's own) global.
// The low four match mrt_msgs/WheelState's STATUS_* constants.
constexpr uint8_t kStatusWatchdog = 0x01;     // watchdog tripped (latched until a set command)
constexpr uint8_t kStatusOvercurrent = 0x02;  // current limit active
constexpr uint8_t kStatusSaturated = 0x04;    // PWM at +-100 %
constexpr uint8_t kStatusEncoderFault = 0x08;
constexpr uint8_t kStatusClamped = 0x10;      // last command exceeded limits and was clamped
constexpr uint8_t kStatusPwmMode = 0x20;      // global: open-loop PWM mode

// NACK reasons.
constexpr uint8_t kNackUnknownType = 1;
constexpr uint8_t kNackBadLength = 2;
constexpr uint8_t kNackBadMotorCount = 3;
constexpr uint8_t kNackBadArgument = 4;
constexpr uint8_t kNackBadCheck = 5;      // a checked set command whose CRC-32 does not match
constexpr uint8_t kNackUnchecked = 6;     // a plain set command after checked ones (strict mode)

// Checked set commands: SET_SPEED / SET_PWM may end with a u32 CRC-32
// (ISO-HDLC, Boost's crc_32_type) of TYPE, SEQ and the payload before it:
// LEN 5 + 4 n (SET_SPEED) or 5 + 2 n (SET_PWM). Damage must then pass both
// the frame's CRC-16 and this CRC-32 to be applied.
constexpr std::size_t kCheckSize = 4;
}  // namespace proto

/// CRC-16/CCITT-FALSE; crc16_ccitt("123456789") == 0x29B1.
uint16_t crc16_ccitt(const uint8_t* data, std::size_t n, uint16_t crc = 0xFFFF);

struct Frame {
  uint8_t type = 0;
  uint8_t seq = 0;
  std::vector<uint8_t> payload;
};

/// Appends the encoded frame; throws std::invalid_argument when the payload
/// exceeds proto::kMaxPayload.
void append_frame(std::vector<uint8_t>& out, const Frame& f);
std::vector<uint8_t> encode_frame(const Frame& f);

/// Incremental frame decoder with resynchronisation. Bytes before a start
/// byte are skipped; a header announcing more than kMaxPayload bytes or a
/// CRC mismatch discards only the start byte and the search restarts at the
/// next byte, so a good frame hidden in a bad one (truncated frame, garbage
/// with 0xA5) is still found. Memory is bounded by kMaxFrame.
class FrameDecoder {
 public:
  struct Stats {
    uint64_t frames_ok = 0;
    uint64_t crc_errors = 0;
    uint64_t length_errors = 0;
    uint64_t bytes_skipped = 0;
    uint64_t frames_bad() const { return crc_errors + length_errors; }
  };

  /// Feeds bytes; calls `on_frame` for every valid frame, in order.
  void feed(const uint8_t* data, std::size_t n, const std::function<void(const Frame&)>& on_frame);
  /// Drops a partial frame (e.g. after reopening the port).
  void clear() { len_ = 0; }
  const Stats& stats() const { return stats_; }

 private:
  void parse(const std::function<void(const Frame&)>& on_frame);
  void drop(std::size_t k);
  uint8_t buf_[proto::kMaxFrame];
  std::size_t len_ = 0;
  Frame scratch_;
  Stats stats_;
};

// ---------------------------------------------------------------- messages

/// Status of one motor as reported by STATE.
struct MotorState {
  int32_t ticks = 0;        // encoder counts, wrapping int32
  double speed = 0.0;       // measured, rad/s (mrad/s on the wire)
  double setpoint = 0.0;    // rad/s
  double duty = 0.0;        // [-1, 1] (1e-4 on the wire)
  uint8_t status = 0;       // proto::kStatus*
};

/// STATE payload: u32 time_ms, u8 status, u8 last_seq, u16 since_cmd_ms,
/// u16 frames_bad, u16 watchdog_trips, u8 n, then n x (i32 ticks,
/// i32 speed, i32 setpoint, i16 duty, u8 status): 13 + 15 n bytes.
struct BoardState {
  uint32_t time_ms = 0;          // board clock (1 ms control ticks)
  uint8_t status = 0;            // OR of motor bits plus board bits
  uint8_t last_seq = 0;          // SEQ of the last applied set command
  uint16_t since_cmd_ms = 0;     // ms since the last valid command (saturates)
  uint16_t frames_bad = 0;       // frames the board discarded (wraps)
  uint16_t watchdog_trips = 0;   // wraps
  std::vector<MotorState> motors;
};

/// SHORT_STATE payload (compact format, for noisy lines): u16 board time
/// (low 16 bits of the ms clock), u8 status (global, as STATE), then
/// n x (i16 encoder count, low 16 bits; i16 set-point in force, mrad/s,
/// saturated to +-32767): 3 + 4 n bytes, n = (LEN - 3) / 4. The frame's SEQ
/// is STATE's (request or last applied set command).
struct ShortState {
  uint16_t time_ms = 0;
  uint8_t status = 0;
  std::vector<int16_t> ticks;     // low 16 bits of the encoder counts
  std::vector<double> setpoints;  // rad/s
};

/// COUNTERS payload: u16 since_cmd_ms, u16 frames_bad, u16 watchdog_trips
/// (as in STATE): 6 bytes.
struct BoardCounters {
  uint16_t since_cmd_ms = 0;
  uint16_t frames_bad = 0;
  uint16_t watchdog_trips = 0;
};

/// INFO payload: u8 fw_major, u8 fw_minor, u8 motors, u32 counts_per_rev,
/// u16 control_hz, u32 pwm_hz, i32 max_speed [mrad/s], u16 watchdog_ms: 19 bytes.
struct BoardInfo {
  uint8_t fw_major = 1;
  uint8_t fw_minor = 0;
  uint8_t motors = 0;
  uint32_t counts_per_rev = 0;
  uint16_t control_hz = 0;
  uint32_t pwm_hz = 0;
  double max_speed = 0.0;  // rad/s
  uint16_t watchdog_ms = 0;
};

struct Gains {
  uint8_t motor = 0xFF;  // 0xFF = all motors
  double kp = 0.0;       // duty per rad/s
  double ki = 0.0;       // duty per rad
};

/// Rounds to the wire's fixed point, saturating at the field's range.
int32_t to_mrad(double rad_per_s);
int16_t to_duty(double duty);
int32_t to_q16(double v);

/// `checked`: append the CRC-32 trailer (see proto::kCheckSize).
Frame make_set_speed(uint8_t seq, const std::vector<double>& speeds, bool checked = false);
Frame make_set_pwm(uint8_t seq, const std::vector<double>& duties, bool checked = false);
/// CRC-32 of TYPE, SEQ and the first `n` payload bytes.
uint32_t command_check(const Frame& f, std::size_t n);
Frame make_set_gains(uint8_t seq, const Gains& g);
Frame make_simple(uint8_t type, uint8_t seq);  // GET_STATE, HEARTBEAT, GET_INFO
Frame make_set_stream(uint8_t seq, uint16_t period_ms);  // 2-byte payload (format STATE)
Frame make_set_stream(uint8_t seq, uint16_t period_ms, uint8_t format);  // 3-byte payload
Frame make_short_state(uint8_t seq, const BoardState& s);  // the compact view of a STATE
Frame make_counters(uint8_t seq, const BoardState& s);
Frame make_state(uint8_t seq, const BoardState& s);
Frame make_info(uint8_t seq, const BoardInfo& i);
Frame make_nack(uint8_t seq, uint8_t type, uint8_t reason);

/// Decoders: false when the type or the exact payload length is wrong, or
/// when the motor count is 0 or above kMaxMotors. Values as on the wire
/// (not clamped: the firmware clamps and reports).
/// Set commands, plain or checked (`checked`, when given, says which); false
/// also when a checked command's CRC-32 does not match (then
/// set_check_failed() is true).
bool parse_set_speed(const Frame& f, std::vector<double>* speeds, bool* checked = nullptr);
bool parse_set_pwm(const Frame& f, std::vector<double>* duties, bool* checked = nullptr);
/// True for a SET_SPEED / SET_PWM of the checked length whose CRC-32 fails.
bool set_check_failed(const Frame& f);
bool parse_set_gains(const Frame& f, Gains* g);
bool parse_set_stream(const Frame& f, uint16_t* period_ms, uint8_t* format = nullptr);  // format 0 when absent
bool parse_short_state(const Frame& f, ShortState* s);
bool parse_counters(const Frame& f, BoardCounters* c);
bool parse_state(const Frame& f, BoardState* s);
bool parse_info(const Frame& f, BoardInfo* i);
bool parse_nack(const Frame& f, uint8_t* type, uint8_t* reason);

}  // namespace mrt::airboard
