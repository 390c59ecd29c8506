#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "mrt_airboard/protocol.h"

using namespace mrt::airboard;
using Bytes = std::vector<uint8_t>;

namespace {
std::vector<Frame> decode_all(FrameDecoder& d, const Bytes& b) {
  std::vector<Frame> out;
  d.feed(b.data(), b.size(), [&](const Frame& f) { out.push_back(f); });
  return out;
}
}  // namespace

TEST(Crc16, CheckValue) {
  const std::string s = "123456789";
  EXPECT_EQ(crc16_ccitt(reinterpret_cast<const uint8_t*>(s.data()), s.size()), 0x29B1);
  EXPECT_EQ(crc16_ccitt(nullptr, 0), 0xFFFF);
}

// Golden frames, written by hand from doc/protocol.md's byte tables (CRC computed
// with doc/protocol.md's bit-by-bit algorithm, independently of this code).
TEST(Golden, Heartbeat) {
  EXPECT_EQ(encode_frame(make_simple(proto::kHeartbeat, 0)), (Bytes{0xA5, 0x00, 0x05, 0x00, 0x69, 0x33}));
  EXPECT_EQ(encode_frame(make_simple(proto::kGetInfo, 1)), (Bytes{0xA5, 0x00, 0x07, 0x01, 0x2A, 0x45}));
}

TEST(Golden, SetSpeed) {
  const Bytes want{0xA5, 0x09, 0x01, 0x07, 0x02, 0xDC, 0x05, 0x00, 0x00, 0x30, 0xF8, 0xFF, 0xFF, 0x10, 0xBB};
  EXPECT_EQ(encode_frame(make_set_speed(7, {1.5, -2.0})), want);
  FrameDecoder d;
  auto f = decode_all(d, want);
  ASSERT_EQ(f.size(), 1u);
  std::vector<double> sp;
  ASSERT_TRUE(parse_set_speed(f[0], &sp));
  EXPECT_EQ(sp, (std::vector<double>{1.5, -2.0}));
  EXPECT_EQ(f[0].seq, 7);
}

TEST(Golden, SetPwmAndStream) {
  EXPECT_EQ(encode_frame(make_set_pwm(9, {0.5, -0.25})),
            (Bytes{0xA5, 0x05, 0x02, 0x09, 0x02, 0x88, 0x13, 0x3C, 0xF6, 0xEB, 0x98}));
  EXPECT_EQ(encode_frame(make_set_stream(2, 10)), (Bytes{0xA5, 0x02, 0x06, 0x02, 0x0A, 0x00, 0xBD, 0xF3}));
  EXPECT_EQ(encode_frame(make_nack(3, 0x09, proto::kNackUnknownType)),
            (Bytes{0xA5, 0x02, 0x8F, 0x03, 0x09, 0x01, 0xB0, 0xAF}));
}

TEST(Golden, State) {
  const Bytes want{0xA5, 0x1C, 0x81, 0x07, 0xE8, 0x03, 0x00, 0x00, 0x01, 0x07, 0x64, 0x00, 0x03, 0x00,
                   0x01, 0x00, 0x01, 0xFB, 0xFF, 0xFF, 0xFF, 0xFA, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                   0x00, 0x18, 0xFC, 0x05, 0xD2, 0x88};
  BoardState s;
  s.time_ms = 1000;
  s.status = proto::kStatusWatchdog;
  s.last_seq = 7;
  s.since_cmd_ms = 100;
  s.frames_bad = 3;
  s.watchdog_trips = 1;
  MotorState m;
  m.ticks = -5;
  m.speed = 0.25;
  m.setpoint = 0.0;
  m.duty = -0.1;
  m.status = proto::kStatusWatchdog | proto::kStatusSaturated;
  s.motors = {m};
  EXPECT_EQ(encode_frame(make_state(7, s)), want);
  FrameDecoder d;
  auto f = decode_all(d, want);
  ASSERT_EQ(f.size(), 1u);
  BoardState r;
  ASSERT_TRUE(parse_state(f[0], &r));
  EXPECT_EQ(r.time_ms, 1000u);
  EXPECT_EQ(r.since_cmd_ms, 100);
  EXPECT_EQ(r.frames_bad, 3);
  ASSERT_EQ(r.motors.size(), 1u);
  EXPECT_EQ(r.motors[0].ticks, -5);
  EXPECT_DOUBLE_EQ(r.motors[0].speed, 0.25);
  EXPECT_DOUBLE_EQ(r.motors[0].duty, -0.1);
  EXPECT_EQ(r.motors[0].status, 0x05);
}

// The compact format for noisy lines (doc/protocol.md: SHORT_STATE, COUNTERS).
TEST(Golden, CompactFormat) {
  const Bytes stream{0xA5, 0x03, 0x06, 0x02, 0x03, 0x00, 0x01, 0x6C, 0xA9};
  EXPECT_EQ(encode_frame(make_set_stream(2, 3, proto::kFormatCompact)), stream);
  FrameDecoder d;
  auto f = decode_all(d, stream);
  ASSERT_EQ(f.size(), 1u);
  uint16_t period = 0;
  uint8_t format = 0;
  ASSERT_TRUE(parse_set_stream(f[0], &period, &format));
  EXPECT_EQ(period, 3);
  EXPECT_EQ(format, proto::kFormatCompact);
  // The 2-byte form is format 0 (STATE).
  ASSERT_TRUE(parse_set_stream(make_set_stream(2, 10), &period, &format));
  EXPECT_EQ(format, proto::kFormatState);

  // Board time 70000 ms, WATCHDOG + SATURATED, counts 70000 and -5 (low 16
  // bits), set-points 2.48 and -5.52 rad/s.
  const Bytes short_state{0xA5, 0x0B, 0x83, 0x07, 0x70, 0x11, 0x05, 0x70, 0x11,
                          0xB0, 0x09, 0xFB, 0xFF, 0x70, 0xEA, 0xAB, 0xFC};
  BoardState s;
  s.time_ms = 70000;
  s.status = proto::kStatusWatchdog | proto::kStatusSaturated;
  s.since_cmd_ms = 100;
  s.frames_bad = 3;
  s.watchdog_trips = 1;
  MotorState m0, m1;
  m0.ticks = 70000;
  m0.setpoint = 2.48;
  m0.speed = 1.0;  // not carried
  m1.ticks = -5;
  m1.setpoint = -5.52;
  s.motors = {m0, m1};
  EXPECT_EQ(encode_frame(make_short_state(7, s)), short_state);
  f = decode_all(d, short_state);
  ASSERT_EQ(f.size(), 1u);
  ShortState r;
  ASSERT_TRUE(parse_short_state(f[0], &r));
  EXPECT_EQ(f[0].seq, 7);
  EXPECT_EQ(r.time_ms, 70000 - 65536);
  EXPECT_EQ(r.status, 0x05);
  EXPECT_EQ(r.ticks, (std::vector<int16_t>{70000 - 65536, -5}));
  EXPECT_EQ(r.setpoints, (std::vector<double>{2.48, -5.52}));

  const Bytes counters{0xA5, 0x06, 0x84, 0x07, 0x64, 0x00, 0x03, 0x00, 0x01, 0x00, 0x06, 0x58};
  EXPECT_EQ(encode_frame(make_counters(7, s)), counters);
  f = decode_all(d, counters);
  ASSERT_EQ(f.size(), 1u);
  BoardCounters c;
  ASSERT_TRUE(parse_counters(f[0], &c));
  EXPECT_EQ(c.since_cmd_ms, 100);
  EXPECT_EQ(c.frames_bad, 3);
  EXPECT_EQ(c.watchdog_trips, 1);

  // Wrong lengths are refused; set-points saturate at the i16 range.
  Frame bad = make_short_state(7, s);
  bad.payload.pop_back();
  EXPECT_FALSE(parse_short_state(bad, &r));
  bad.payload.resize(3);
  EXPECT_FALSE(parse_short_state(bad, &r));
  s.motors[0].setpoint = 40.0;
  ASSERT_TRUE(parse_short_state(make_short_state(7, s), &r));
  EXPECT_DOUBLE_EQ(r.setpoints[0], 32.767);
  Frame long_stream = make_set_stream(2, 3, 1);
  long_stream.payload.push_back(0);
  EXPECT_FALSE(parse_set_stream(long_stream, &period, &format));
}

// At 10 % of the bytes corrupted, the fraction of frames that survive is
// 0.9^length: 16.7 % of 17-byte SHORT_STATEs against 0.6 % of 49-byte STATEs
// (two motors).
TEST(Decoder, ShortFramesSurviveTenPercentCorruption) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  BoardState s;
  s.motors.resize(2);
  int ok[2] = {0, 0};
  const int frames = 20000;
  for (int kind = 0; kind < 2; ++kind) {
    FrameDecoder d;
    for (int i = 0; i < frames; ++i) {
      s.time_ms = static_cast<uint32_t>(i);
      s.motors[0].ticks = i * 7;
      Bytes b = encode_frame(kind ? make_short_state(static_cast<uint8_t>(i), s) : make_state(static_cast<uint8_t>(i), s));
      for (auto& x : b)
        if (u(rng) < 0.1) x ^= static_cast<uint8_t>(1u << (rng() % 8));
      for (const Frame& f : decode_all(d, b)) {
        BoardState st;
        ShortState ss;
        if (kind ? parse_short_state(f, &ss) : parse_state(f, &st)) ++ok[kind];
      }
    }
  }
  const double full = double(ok[0]) / frames, compact = double(ok[1]) / frames;
  std::printf("10 %% byte corruption: %.2f %% of STATE, %.2f %% of SHORT_STATE frames decoded\n", 100 * full,
              100 * compact);
  EXPECT_NEAR(full, std::pow(0.9, 49), 0.003);
  EXPECT_NEAR(compact, std::pow(0.9, 17), 0.01);
}

TEST(RoundTrip, EveryMessage) {
  FrameDecoder d;
  Bytes b;
  Gains g{1, 0.05, 1.25};
  BoardInfo info;
  info.motors = 3;
  info.counts_per_rev = 8192;
  info.control_hz = 1000;
  info.pwm_hz = 20000;
  info.max_speed = 30.0;
  info.watchdog_ms = 100;
  append_frame(b, make_set_gains(1, g));
  append_frame(b, make_info(2, info));
  append_frame(b, make_set_speed(3, {0.001, -32.5, 7.0, 0.0}));
  append_frame(b, make_simple(proto::kGetState, 4));
  auto f = decode_all(d, b);
  ASSERT_EQ(f.size(), 4u);
  Gains g2;
  ASSERT_TRUE(parse_set_gains(f[0], &g2));
  EXPECT_EQ(g2.motor, 1);
  EXPECT_DOUBLE_EQ(g2.kp, std::round(0.05 * 65536) / 65536);
  EXPECT_DOUBLE_EQ(g2.ki, 1.25);
  BoardInfo i2;
  ASSERT_TRUE(parse_info(f[1], &i2));
  EXPECT_EQ(i2.motors, 3);
  EXPECT_EQ(i2.counts_per_rev, 8192u);
  EXPECT_EQ(i2.pwm_hz, 20000u);
  EXPECT_DOUBLE_EQ(i2.max_speed, 30.0);
  std::vector<double> sp;
  ASSERT_TRUE(parse_set_speed(f[2], &sp));
  EXPECT_EQ(sp, (std::vector<double>{0.001, -32.5, 7.0, 0.0}));
  EXPECT_EQ(f[3].type, proto::kGetState);
  EXPECT_TRUE(f[3].payload.empty());
  EXPECT_EQ(d.stats().frames_ok, 4u);
  EXPECT_EQ(d.stats().frames_bad(), 0u);
  // Wrong type or length is refused by the typed parsers.
  EXPECT_FALSE(parse_set_pwm(f[2], nullptr));
  Frame bad = f[2];
  bad.payload.pop_back();
  EXPECT_FALSE(parse_set_speed(bad, &sp));
  EXPECT_THROW(make_set_speed(0, {}), std::invalid_argument);
  EXPECT_THROW(make_set_speed(0, std::vector<double>(5, 0.0)), std::invalid_argument);
}

TEST(FixedPoint, Saturates) {
  EXPECT_EQ(to_duty(2.0), 20000);
  EXPECT_EQ(to_duty(-4.0), -32768);
  EXPECT_EQ(to_mrad(1e12), 2147483647);
  EXPECT_EQ(to_mrad(NAN), 0);
}

TEST(Decoder, ByteByByteAndGarbage) {
  Bytes b{0x00, 0x13, 0xA5};  // garbage including a false start byte
  append_frame(b, make_set_speed(1, {1.0, 2.0}));
  b.push_back(0xFF);
  append_frame(b, make_simple(proto::kHeartbeat, 2));
  FrameDecoder d;
  std::vector<Frame> got;
  for (uint8_t x : b) d.feed(&x, 1, [&](const Frame& f) { got.push_back(f); });
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].seq, 1);
  EXPECT_EQ(got[1].seq, 2);
  EXPECT_GE(d.stats().frames_bad(), 1u);
}

TEST(Decoder, TruncatedFrameThenGoodFrame) {
  Bytes good = encode_frame(make_set_speed(5, {3.0, -3.0}));
  Bytes b(good.begin(), good.begin() + 7);  // truncated
  b.insert(b.end(), good.begin(), good.end());
  FrameDecoder d;
  auto f = decode_all(d, b);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].seq, 5);
  EXPECT_EQ(d.stats().crc_errors, 1u);
}

TEST(Decoder, BadCrcAndOversizeAreDiscarded) {
  Bytes b = encode_frame(make_set_speed(5, {3.0, -3.0}));
  b[6] ^= 0x10;  // payload bit flip
  const Bytes over{0xA5, 0xFF, 0x01, 0x00};
  b.insert(b.end(), over.begin(), over.end());
  append_frame(b, make_simple(proto::kGetState, 9));
  FrameDecoder d;
  auto f = decode_all(d, b);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].seq, 9);
  EXPECT_EQ(d.stats().crc_errors, 1u);
  EXPECT_EQ(d.stats().length_errors, 1u);
}

TEST(Decoder, EveryDecodedFrameUnderRandomCorruptionIsAnOriginal) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  Bytes b;
  std::vector<Bytes> originals;
  for (int i = 0; i < 5000; ++i) {
    Frame f = make_set_speed(static_cast<uint8_t>(i), {i * 0.001, -i * 0.002});
    originals.push_back(f.payload);
    append_frame(b, f);
    if (i % 7 == 0) b.push_back(static_cast<uint8_t>(rng()));  // garbage between frames
  }
  int flipped = 0;
  for (auto& x : b)
    if (u(rng) < 0.1) {
      x ^= static_cast<uint8_t>(1u << (rng() % 8));
      ++flipped;
    }
  FrameDecoder d;
  int good = 0;
  d.feed(b.data(), b.size(), [&](const Frame& f) {
    ASSERT_EQ(f.type, proto::kSetSpeed);
    // The payload must be one of the originals with this sequence number.
    bool found = false;
    for (std::size_t i = f.seq; i < originals.size(); i += 256) found = found || originals[i] == f.payload;
    EXPECT_TRUE(found);
    ++good;
  });
  EXPECT_GT(flipped, 0);
  EXPECT_GT(good, 800);  // ~ 0.9^15 = 21 % of the frames survive
  EXPECT_GT(d.stats().frames_bad(), 1000u);
}
