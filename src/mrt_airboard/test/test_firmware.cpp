#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mrt_airboard/firmware.h"

using namespace mrt::airboard;

namespace {
struct Link {
  Firmware fw;
  FrameDecoder dec;
  std::vector<BoardState> states;
  std::vector<Frame> others;
  explicit Link(FirmwareConfig c = {}) : fw(c) {}
  void send(const Frame& f) {
    auto b = encode_frame(f);
    fw.receive(b.data(), b.size());
    pump();
  }
  void pump() {
    auto out = fw.take_output();
    dec.feed(out.data(), out.size(), [&](const Frame& f) {
      BoardState s;
      if (parse_state(f, &s)) states.push_back(s);
      else others.push_back(f);
    });
  }
  void run_ms(int ms) {
    for (int i = 0; i < ms; ++i) {
      fw.step();
      pump();
    }
  }
};
}  // namespace

TEST(Firmware, PiLoopTracksTheSetPoint) {
  Link l;
  l.send(make_set_speed(1, {10.0, -5.0}));
  ASSERT_EQ(l.states.size(), 1u);
  EXPECT_EQ(l.states[0].last_seq, 1);
  for (int i = 0; i < 10; ++i) {  // refresh within the watchdog delay
    l.run_ms(50);
    l.send(make_set_speed(static_cast<uint8_t>(2 + i), {10.0, -5.0}));
  }
  EXPECT_NEAR(l.fw.speed(0), 10.0, 0.1);
  EXPECT_NEAR(l.fw.speed(1), -5.0, 0.1);
  // Encoder: 0.5 s at 10 rad/s after the transient is ~ 8192 * 5 / 2 pi counts.
  const int64_t t0 = l.fw.ticks(0);
  l.run_ms(50);
  EXPECT_NEAR(static_cast<double>(l.fw.ticks(0) - t0), 10.0 * 0.05 * 8192 / (2 * M_PI), 15.0);
  EXPECT_EQ(l.fw.time_ms(), 550u);
}

TEST(Firmware, WatchdogStopsTheMotors100msAfterTheLastCommand) {
  Link l;
  l.send(make_set_speed(1, {10.0, 10.0}));
  l.run_ms(99);
  EXPECT_FALSE(l.fw.watchdog_tripped());
  EXPECT_NE(l.fw.duty(0), 0.0);
  l.run_ms(1);  // 100 ms of simulated time since the command
  EXPECT_TRUE(l.fw.watchdog_tripped());
  EXPECT_EQ(l.fw.setpoint(0), 0.0);
  EXPECT_EQ(l.fw.duty(0), 0.0);
  EXPECT_EQ(l.fw.watchdog_trips(), 1u);
  const double w0 = l.fw.speed(0);
  l.run_ms(100);  // short-circuit brake: the wheel decays with tau = 20 ms
  EXPECT_LT(std::fabs(l.fw.speed(0)), 0.01 * w0);
  // The trip is latched and reported until the next set command.
  l.send(make_simple(proto::kGetState, 9));
  EXPECT_TRUE(l.states.back().status & proto::kStatusWatchdog);
  EXPECT_EQ(l.states.back().since_cmd_ms, 200);
  l.send(make_simple(proto::kHeartbeat, 10));  // does not re-arm
  EXPECT_TRUE(l.fw.watchdog_tripped());
  l.send(make_set_speed(11, {1.0, 1.0}));
  EXPECT_FALSE(l.fw.watchdog_tripped());
  EXPECT_FALSE(l.states.back().status & proto::kStatusWatchdog);
}

TEST(Firmware, HeartbeatKeepsTheWatchdogQuiet) {
  Link l;
  l.send(make_set_speed(1, {3.0, 3.0}));
  for (int i = 0; i < 10; ++i) {
    l.run_ms(60);
    l.send(make_simple(proto::kHeartbeat, 2));
  }
  EXPECT_FALSE(l.fw.watchdog_tripped());
  EXPECT_NEAR(l.fw.speed(0), 3.0, 0.1);
}

TEST(Firmware, ClampsAndReports) {
  Link l;
  l.send(make_set_speed(1, {100.0, -0.5}));
  EXPECT_EQ(l.fw.setpoint(0), 30.0);
  EXPECT_EQ(l.fw.setpoint(1), -0.5);
  EXPECT_TRUE(l.states.back().motors[0].status & proto::kStatusClamped);
  EXPECT_FALSE(l.states.back().motors[1].status & proto::kStatusClamped);
  l.send(make_set_pwm(2, {1.5, -0.2}));
  EXPECT_TRUE(l.states.back().motors[0].status & proto::kStatusClamped);
  l.run_ms(5);
  EXPECT_LE(l.fw.duty(0), 1.0);  // clamped to 100 %, then the current limit
  EXPECT_GT(l.fw.duty(0), 0.8);
  EXPECT_NEAR(l.fw.duty(1), -0.2, 1.0 / 500);
}

TEST(Firmware, SaturationAndCurrentLimitAreReported) {
  Link l;
  l.send(make_set_speed(1, {30.0, -30.0}));
  l.run_ms(1);
  l.send(make_simple(proto::kGetState, 2));
  // A step from rest asks for more current than the limit allows.
  EXPECT_TRUE(l.states.back().motors[0].status & proto::kStatusOvercurrent);
  EXPECT_LE(l.fw.duty(0), 0.8 + 1e-9);
  l.run_ms(60);
  l.send(make_set_speed(3, {30.0, -30.0}));
  l.run_ms(60);
  l.send(make_simple(proto::kGetState, 4));
  // 30 rad/s needs 30 / 38 = 79 % duty: in range, so no saturation at steady state.
  EXPECT_FALSE(l.states.back().motors[0].status & proto::kStatusSaturated);
}

TEST(Firmware, RejectsMalformedCommands) {
  Link l;
  l.send(make_set_speed(1, {1.0, 1.0, 1.0}));  // the board has 2 motors
  ASSERT_EQ(l.others.size(), 1u);
  uint8_t type, reason;
  ASSERT_TRUE(parse_nack(l.others[0], &type, &reason));
  EXPECT_EQ(type, proto::kSetSpeed);
  EXPECT_EQ(reason, proto::kNackBadMotorCount);
  Frame unknown;
  unknown.type = 0x42;
  l.send(unknown);
  ASSERT_TRUE(parse_nack(l.others.back(), &type, &reason));
  EXPECT_EQ(reason, proto::kNackUnknownType);
  EXPECT_EQ(l.fw.setpoint(0), 0.0);
  EXPECT_EQ(l.fw.commands_rejected(), 2u);
  l.send(make_simple(proto::kGetInfo, 5));
  BoardInfo info;
  ASSERT_TRUE(parse_info(l.others.back(), &info));
  EXPECT_EQ(info.motors, 2);
  EXPECT_EQ(info.pwm_hz, 20000u);
  EXPECT_EQ(info.watchdog_ms, 100);
}

TEST(Firmware, StreamsState) {
  Link l;
  l.send(make_set_stream(1, 10));
  l.states.clear();
  l.run_ms(100);
  ASSERT_EQ(l.states.size(), 10u);
  EXPECT_EQ(l.states.back().time_ms, 100u);
}

// 10 % of the command bytes get one bit flipped: no set-point other than the
// commanded ones (or 0 after a watchdog trip) ever reaches a motor.
TEST(Firmware, NoCorruptedCommandIsApplied) {
  Link l;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const std::vector<double> a{4.0, -2.5}, b{-1.0, 7.25};
  for (int i = 0; i < 5000; ++i) {
    auto bytes = encode_frame(make_set_speed(static_cast<uint8_t>(i), i % 2 ? a : b));
    for (auto& x : bytes)
      if (u(rng) < 0.1) x ^= static_cast<uint8_t>(1u << (rng() % 8));
    // Split arbitrarily, as a serial driver would.
    const std::size_t cut = rng() % bytes.size();
    l.fw.receive(bytes.data(), cut);
    l.fw.receive(bytes.data() + cut, bytes.size() - cut);
    for (int m = 0; m < 2; ++m) {
      const double sp = l.fw.setpoint(m);
      EXPECT_TRUE(sp == a[m] || sp == b[m] || sp == 0.0) << sp;
    }
    l.run_ms(10);
    l.fw.take_output();
  }
  EXPECT_GT(l.fw.rx_stats().frames_bad(), 500u);
  EXPECT_GT(l.fw.commands_applied(), 500u);
}

// The compact format: SHORT_STATE streamed (with COUNTERS after every 10th)
// and as the reply to set commands and heartbeats; GET_STATE still answers STATE.
TEST(Firmware, StreamsCompactState) {
  Link l;
  l.send(make_set_stream(1, 3, proto::kFormatCompact));
  EXPECT_EQ(l.fw.stream_format(), proto::kFormatCompact);
  l.states.clear();
  l.others.clear();
  l.run_ms(300);
  int shorts = 0, counters = 0;
  for (const Frame& f : l.others) {
    ShortState s;
    BoardCounters c;
    if (parse_short_state(f, &s)) {
      ++shorts;
      EXPECT_EQ(s.ticks.size(), 2u);
    } else if (parse_counters(f, &c)) {
      ++counters;
    }
  }
  EXPECT_EQ(shorts, 100);
  EXPECT_EQ(counters, 10);
  EXPECT_TRUE(l.states.empty());
  l.others.clear();
  l.send(make_set_speed(9, {3.25, -1.5}));
  ASSERT_EQ(l.others.size(), 1u);
  ShortState s;
  ASSERT_TRUE(parse_short_state(l.others[0], &s));
  EXPECT_EQ(l.others[0].seq, 9);
  EXPECT_EQ(s.setpoints, (std::vector<double>{3.25, -1.5}));
  l.send(make_simple(proto::kGetState, 10));
  ASSERT_EQ(l.states.size(), 1u);
  // Unknown formats are refused; the 2-byte request goes back to STATE.
  l.others.clear();
  l.send(make_set_stream(11, 3, 7));
  ASSERT_EQ(l.others.size(), 1u);
  EXPECT_EQ(l.others[0].type, proto::kNack);
  l.send(make_set_stream(12, 10));
  EXPECT_EQ(l.fw.stream_format(), proto::kFormatState);
}
