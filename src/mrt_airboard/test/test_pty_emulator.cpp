#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <thread>
#include <vector>
#include <unistd.h>

#include "mrt_airboard/pty_emulator.h"
#include "mrt_airboard/serial_port.h"

using namespace mrt::airboard;

namespace {
// Reads frames for up to `ms` until `pred` accepts one.
template <typename Pred>
bool read_until(SerialPort& port, FrameDecoder& dec, int ms, Pred pred) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  uint8_t buf[512];
  bool ok = false;
  while (!ok && std::chrono::steady_clock::now() < end) {
    port.wait_readable(10);
    const std::size_t n = port.read(buf, sizeof(buf));
    dec.feed(buf, n, [&](const Frame& f) { ok = ok || pred(f); });
  }
  return ok;
}
}  // namespace

TEST(PtyEmulator, ServesTheProtocolOnAPseudoTerminal) {
  const std::string link = "/tmp/mrt_airboard_gtest_" + std::to_string(::getpid());
  std::atomic<bool> stop{false};
  FirmwareConfig c;
  c.motors = 3;
  auto emu = std::make_unique<PtyEmulator>(c, LineFaults{}, link);
  std::thread t([&] { emu->run(stop); });

  SerialPort port;
  port.open(link, 115200);
  FrameDecoder dec;
  auto f = encode_frame(make_simple(proto::kGetInfo, 1));
  port.write(f.data(), f.size());
  BoardInfo info;
  EXPECT_TRUE(read_until(port, dec, 1000, [&](const Frame& fr) { return parse_info(fr, &info); }));
  EXPECT_EQ(info.motors, 3);

  f = encode_frame(make_set_speed(2, {5.0, 0.0, -5.0}));
  port.write(f.data(), f.size());
  BoardState s;
  EXPECT_TRUE(read_until(port, dec, 1000, [&](const Frame& fr) {
    return parse_state(fr, &s) && fr.seq == 2;
  }));
  ASSERT_EQ(s.motors.size(), 3u);
  EXPECT_DOUBLE_EQ(s.motors[0].setpoint, 5.0);
  EXPECT_DOUBLE_EQ(s.motors[2].setpoint, -5.0);

  stop = true;
  t.join();
  EXPECT_GE(emu->firmware().commands_applied(), 1u);
  emu.reset();
  EXPECT_NE(::access(link.c_str(), F_OK), 0);  // the symlink is gone
}

TEST(PtyEmulator, BoardTimeFollowsItsTimeSource) {
  // The board on a simulator's clock running at twice the wall clock (a
  // real-time factor of 2): a wheel commanded at 5 rad/s turns, over 2 s of
  // that clock (1 s of wall time), 5 * 2 * 8192 / (2 pi) = 13038 counts; on
  // the wall clock it would turn half of that (6519).
  const std::string link = "/tmp/mrt_airboard_gtest_clock_" + std::to_string(::getpid());
  std::atomic<bool> stop{false};
  FirmwareConfig c;
  c.motors = 2;
  PtyEmulator emu(c, LineFaults{}, link);
  const auto t0 = std::chrono::steady_clock::now();
  auto sim_time = [t0] {
    return 1.0 + 2.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  emu.set_time_source(sim_time);
  const double board_start = sim_time();
  std::thread t([&] { emu.run(stop); });
  SerialPort port;
  port.open(link, 115200);
  FrameDecoder dec;
  uint8_t seq = 0;
  // Commands every 10 ms of wall time (20 ms of board time, within the
  // watchdog's 100 ms); returns the reply's ticks of motor 0 and the source
  // time at its reception. `max_gap`: the longest source time between two
  // commands sent (a starved test thread, e.g. under ASan at nice 19 beside
  // the team rostests, can exceed the watchdog: seen once in CI).
  double last_sent = -1.0, max_gap = 0.0;
  auto command = [&](double* when) {
    const double sent = sim_time();
    if (last_sent >= 0.0) max_gap = std::max(max_gap, sent - last_sent);
    last_sent = sent;
    const auto f = encode_frame(make_set_speed(++seq, {5.0, 5.0}));
    port.write(f.data(), f.size());
    BoardState st;
    EXPECT_TRUE(read_until(port, dec, 1000, [&](const Frame& fr) { return parse_state(fr, &st) && fr.seq == seq; }));
    *when = sim_time();
    return st.motors.empty() ? 0 : st.motors[0].ticks;
  };
  // One measurement: the wheel brought to speed (0.3 s of wall time, tau
  // 20 ms), then its ticks over 2 s of source time; max_gap over both.
  // Repeated (3 times at most) while the test thread was starved beyond
  // 80 % of the watchdog, or the watchdog tripped: the wheel then stopped
  // in between, and the count says nothing. A firmware whose watchdog
  // trips on time-kept commands trips in all 3 and fails.
  const double starved = 0.8 * c.watchdog_ms / 1000.0;
  double start = 0.0, end = 0.0;
  int32_t first = 0, last = 0;
  uint32_t trips = 0;
  last_sent = board_start;  // the board's watchdog runs from its start
  for (int attempt = 0; attempt < 3; ++attempt) {
    const uint32_t trips0 = emu.firmware().watchdog_trips();
    max_gap = 0.0;
    for (int i = 0; i < 30; ++i) {
      command(&start);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    first = last = command(&start);
    end = start;
    while (end - start < 2.0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      last = command(&end);
    }
    trips = emu.firmware().watchdog_trips() - trips0;
    // A trip with the sender on time is the emulator's thread starved (it
    // read the commands late: seen once under ASan beside the other lane,
    // 73 ms between sends, one trip): measured again too.
    if (max_gap < starved && trips == 0) break;
    std::printf("test thread starved: %.3f s of board time between two commands (watchdog %u ms), %u trips\n",
                max_gap, c.watchdog_ms, trips);
  }
  stop = true;
  t.join();
  ASSERT_LT(max_gap, starved) << "the test thread was starved in all 3 attempts";
  const double expected = 5.0 * (end - start) * 8192.0 / (2.0 * M_PI);  // about 13038
  EXPECT_NEAR(last - first, expected, 0.01 * expected) << "over " << end - start << " s of source time";
  EXPECT_EQ(trips, 0u) << "longest gap between commands " << max_gap << " s";
}

TEST(PtyEmulator, CarriesBytesAtTheBaudRate) {
  const std::string link = "/tmp/mrt_airboard_gtest_baud_" + std::to_string(::getpid());
  std::atomic<bool> stop{false};
  FirmwareConfig c;
  c.motors = 3;
  LineFaults faults;
  faults.baud = 115200;
  PtyEmulator emu(c, faults, link);
  std::thread t([&] { emu.run(stop); });
  SerialPort port;
  port.open(link, 115200);
  FrameDecoder dec;
  const auto f = encode_frame(make_set_speed(4, {1.0, 2.0, 3.0}));  // 19 bytes
  const auto t0 = std::chrono::steady_clock::now();
  port.write(f.data(), f.size());
  EXPECT_TRUE(read_until(port, dec, 1000, [&](const Frame& fr) { return fr.type == proto::kState && fr.seq == 4; }));
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  // 19 + 58 + 6 = 83 bytes of 10 bits at 115200 baud: at least 7.2 ms.
  EXPECT_GE(ms, 7.2);
  stop = true;
  t.join();
}

// The emulator reports every state frame it sends (what airboard_emulator
// --sim-wheel-cmd publishes for the simulator): each STATE the PC decodes is
// among the reports, same board time, the same speeds to the bit, and a
// reply beside the streamed frame of the same millisecond is reported once.
// Commanded 5 and -5 rad/s for 0.3 s (tau 20 ms), the wheels measure 5 and
// -5 rad/s within 2 %.
TEST(PtyEmulator, ReportsTheStatesItSends) {
  const std::string link = "/tmp/mrt_airboard_gtest_observer_" + std::to_string(::getpid());
  std::atomic<bool> stop{false};
  PtyEmulator emu(FirmwareConfig{}, LineFaults{}, link);
  std::mutex m;
  std::map<uint32_t, std::vector<double>> reported;
  int repeats = 0;
  emu.set_state_observer([&](uint32_t ms, const std::vector<double>& speeds) {
    std::lock_guard<std::mutex> lock(m);
    repeats += reported.count(ms) ? 1 : 0;
    reported[ms] = speeds;
  });
  std::thread t([&] { emu.run(stop); });
  SerialPort port;
  port.open(link, 115200);
  FrameDecoder dec;
  auto f = encode_frame(make_set_stream(1, 10));
  port.write(f.data(), f.size());
  std::vector<BoardState> received;
  for (uint8_t seq = 2; seq < 32; ++seq) {
    f = encode_frame(make_set_speed(seq, {5.0, -5.0}));
    port.write(f.data(), f.size());
    read_until(port, dec, 1000, [&](const Frame& fr) {
      BoardState st;
      if (parse_state(fr, &st)) received.push_back(st);
      return st.last_seq == seq;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  stop = true;
  t.join();
  ASSERT_GE(received.size(), 30u);
  std::lock_guard<std::mutex> lock(m);
  EXPECT_EQ(repeats, 0);
  for (const BoardState& st : received) {
    const auto it = reported.find(st.time_ms);
    ASSERT_NE(it, reported.end()) << "board time " << st.time_ms;
    ASSERT_EQ(it->second.size(), 2u);
    EXPECT_EQ(it->second[0], st.motors[0].speed);
    EXPECT_EQ(it->second[1], st.motors[1].speed);
  }
  EXPECT_NEAR(received.back().motors[0].speed, 5.0, 0.1);
  EXPECT_NEAR(received.back().motors[1].speed, -5.0, 0.1);
}

TEST(SerialPort, ReportsTheDeviceGoingAway) {
  const std::string link = "/tmp/mrt_airboard_gtest_hup_" + std::to_string(::getpid());
  auto emu = std::make_unique<PtyEmulator>(FirmwareConfig{}, LineFaults{}, link);
  SerialPort port;
  port.open(link, 115200);
  uint8_t buf[64];
  EXPECT_EQ(port.read(buf, sizeof(buf)), 0u);
  emu.reset();  // the emulator exits: the pty master closes
  EXPECT_THROW(
      {
        for (int i = 0; i < 100; ++i) {
          port.wait_readable(10);
          port.read(buf, sizeof(buf));
        }
      },
      SerialError);
  EXPECT_FALSE(port.is_open());
  EXPECT_THROW(port.open(link, 115200), SerialError);  // the link is gone too
  EXPECT_THROW(port.open("/dev/null", 115200), SerialError);  // not a tty
  EXPECT_THROW(port.open(link, 12345), SerialError);          // bad baud rate
}

TEST(Backoff, DoublesUpToTheMaximumAndResets) {
  Backoff b(0.1, 1.0);
  EXPECT_TRUE(b.due(0.0));
  b.failed(0.0);
  EXPECT_FALSE(b.due(0.05));
  EXPECT_TRUE(b.due(0.1));
  b.failed(0.1);  // next after 0.2
  EXPECT_FALSE(b.due(0.25));
  EXPECT_TRUE(b.due(0.31));
  for (int i = 0; i < 10; ++i) b.failed(1.0);
  EXPECT_DOUBLE_EQ(b.current_delay(), 1.0);
  b.succeeded();
  EXPECT_DOUBLE_EQ(b.current_delay(), 0.1);
  EXPECT_TRUE(b.due(0.0));
}
