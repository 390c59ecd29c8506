#include <gtest/gtest.h>

#include <limits>

#include "mrt_airboard/state_tracker.h"

using namespace mrt::airboard;

namespace {
BoardState state(uint32_t ms, std::vector<int32_t> ticks) {
  BoardState s;
  s.time_ms = ms;
  for (int32_t t : ticks) {
    MotorState m;
    m.ticks = t;
    s.motors.push_back(m);
  }
  return s;
}
}  // namespace

TEST(StateTracker, UnwrapsCountsAndBoardClock) {
  StateTracker t;
  const int32_t max = std::numeric_limits<int32_t>::max();
  const uint32_t near_wrap = 0xFFFFFFFFu - 5;  // board clock 6 ms before its wrap
  ASSERT_TRUE(t.update(state(near_wrap, {max - 10, -7}), 100.0));
  EXPECT_EQ(t.counts()[0], max - 10);
  // 10 ms later both the clock and counter 0 have wrapped.
  ASSERT_TRUE(t.update(state(near_wrap + 10, {std::numeric_limits<int32_t>::min() + 9, -27}), 100.010));
  EXPECT_EQ(t.counts()[0], static_cast<int64_t>(max) + 10);
  EXPECT_EQ(t.counts()[1], -27);
  EXPECT_NEAR(t.board_time(), near_wrap * 1e-3 + 0.010, 1e-9);
  // Same millisecond again (a reply after a streamed frame): nothing new.
  EXPECT_FALSE(t.update(state(near_wrap + 10, {0, 0}), 100.011));
  EXPECT_EQ(t.counts()[1], -27);
  // A different motor count is refused.
  EXPECT_FALSE(t.update(state(near_wrap + 20, {1, 2, 3}), 100.02));
  t.reset();
  EXPECT_TRUE(t.update(state(3, {5, 6, 7}), 200.0));
  EXPECT_EQ(t.counts().size(), 3u);
}

TEST(StateTracker, MapsBoardTimeOnTheLeastDelayedSample) {
  StateTracker t(0.0);
  t.update(state(1000, {0}), 50.004);  // 4 ms transport delay
  EXPECT_NEAR(t.host_stamp(), 50.004, 1e-12);
  t.update(state(1010, {0}), 50.011);  // 1 ms: the offset shrinks
  EXPECT_NEAR(t.host_stamp(), 50.011, 1e-12);
  t.update(state(1020, {0}), 50.029);  // 9 ms of jitter does not move the stamp
  EXPECT_NEAR(t.host_stamp(), 50.021, 1e-12);
}

TEST(StateTracker, FollowsAFasterHostClockWithinTheDriftBound) {
  StateTracker t(1000.0);  // up to 1000 ppm
  for (int i = 0; i <= 1000; ++i)  // host clock 500 ppm faster, 10 s
    t.update(state(static_cast<uint32_t>(i * 10), {0}), i * 0.010 * 1.0005);
  EXPECT_NEAR(t.host_stamp(), 10.005, 1e-4);
}

// mrt_sim's /clock against the emulator's wall clock: the simulator stalls
// (its clock stops while the board runs on), then races to catch up (it does
// so for stalls under 0.2 s, sim_node.cpp). Frames every 10 ms of board
// time, 2 ms transport delay; every 2 s the host clock stops for 15 frames
// (150 ms) and then runs twice as fast for 15 frames. The minimum offset
// alone keeps the stall's -150 ms for good: 1.2 s after the catch-up the
// stamps lag the reception by 0.150 - 1000 ppm x 1.35 s = 0.1487 s (the
// plot_run lag). With the 1 s window they lag by 0.
TEST(StateTracker, SimulatedClockStallsDoNotLeaveTheStampsBehind) {
  StateTracker t;  // 1000 ppm, 1 s window
  double host = 100.002;
  double last_stamp = 0.0;
  for (int cycle = 0; cycle < 10; ++cycle) {
    for (int k = 0; k < 200; ++k) {
      const uint32_t ms = static_cast<uint32_t>((cycle * 200 + k) * 10);
      if (cycle + k > 0) host += (k >= 50 && k < 65) ? 0.0 : (k >= 65 && k < 80) ? 0.020 : 0.010;
      ASSERT_TRUE(t.update(state(ms, {0}), host));
      EXPECT_LE(t.host_stamp(), host + 1e-12);         // never later than the reception
      EXPECT_GE(t.host_stamp(), last_stamp - 1e-9);     // never backwards
      last_stamp = t.host_stamp();
    }
    // 1.2 s after the catch-up: the stamp is the reception time again.
    EXPECT_NEAR(t.host_stamp(), host, 1e-9) << "cycle " << cycle;
  }
  // The old behaviour, window off: the 0.1487 s lag.
  StateTracker old(1000.0, 0.0);
  host = 100.002;
  for (int k = 0; k < 200; ++k) {
    if (k > 0) host += (k >= 50 && k < 65) ? 0.0 : (k >= 65 && k < 80) ? 0.020 : 0.010;
    old.update(state(static_cast<uint32_t>(k * 10), {0}), host);
  }
  EXPECT_NEAR(host - old.host_stamp(), 0.150 - 1e-3 * 1.35, 1e-6);
}

namespace {
ShortState short_state(uint32_t ms, std::vector<int32_t> ticks) {
  ShortState s;
  s.time_ms = static_cast<uint16_t>(ms);
  for (int32_t t : ticks) {
    s.ticks.push_back(static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(t))));
    s.setpoints.push_back(0.0);
  }
  return s;
}
}  // namespace

// SHORT_STATEs (16-bit clock and counts) continue a STATE's 32-bit ones and
// are continued by them; a gap beyond the horizon re-bases the counts.
TEST(StateTracker, UnwrapsShortStates) {
  StateTracker t(0.0);
  ASSERT_TRUE(t.update(state(65530, {32760, -100000}), 10.0));
  ASSERT_TRUE(t.update_short(short_state(65540, {32790, -130000}), 10.010, 500));
  EXPECT_FALSE(t.rebased());
  EXPECT_EQ(t.counts()[0], 32790);
  EXPECT_EQ(t.counts()[1], -130000);
  EXPECT_NEAR(t.board_time(), 65.540, 1e-9);
  EXPECT_FALSE(t.update_short(short_state(65540, {0, 0}), 10.011, 500));  // same instant
  ASSERT_TRUE(t.update_short(short_state(65550, {32800, -160000}), 10.020, 500));
  EXPECT_EQ(t.counts()[1], -160000);
  // A STATE after SHORT_STATEs continues from their low bits.
  ASSERT_TRUE(t.update(state(65560, {32810, -190000}), 10.030));
  EXPECT_EQ(t.counts()[0], 32810);
  EXPECT_EQ(t.counts()[1], -190000);
  EXPECT_NEAR(t.board_time(), 65.560, 1e-9);
  // 600 ms without a frame: beyond a 500 ms horizon, the counts restart.
  ASSERT_TRUE(t.update_short(short_state(66160, {40000, -1}), 10.630, 500));
  EXPECT_TRUE(t.rebased());
  EXPECT_EQ(t.counts()[1], -1);
  EXPECT_NEAR(t.board_time(), 66.160, 1e-9);
  ASSERT_TRUE(t.update_short(short_state(66170, {40010, -11}), 10.640, 500));
  EXPECT_FALSE(t.rebased());
  EXPECT_EQ(t.counts()[1], -11);
  EXPECT_NEAR(t.host_stamp(), 10.640, 1e-9);
}
