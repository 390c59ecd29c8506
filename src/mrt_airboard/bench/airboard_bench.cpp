// AIRBoard benchmark: frames decoded per second (clean and with 1 % of the
// bytes corrupted: 10 % would leave almost no intact 64-byte frame) against a memchr scan of the same bytes as the in-run
// baseline, and the command-to-set-point latency through a real pty served
// by the emulator (p50, p99).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <thread>
#include <unistd.h>
#include <vector>

#include "mrt_airboard/pty_emulator.h"
#include "mrt_airboard/serial_port.h"

using namespace mrt::airboard;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::vector<uint8_t> state_stream(int frames) {
  std::vector<uint8_t> b;
  BoardState s;
  s.motors.resize(3);
  for (int i = 0; i < frames; ++i) {
    s.time_ms = static_cast<uint32_t>(i);
    for (auto& m : s.motors) {
      m.ticks = i * 37;
      m.speed = i * 0.001;
    }
    append_frame(b, make_state(static_cast<uint8_t>(i), s));
  }
  return b;
}

void decode_rate(const char* name, const std::vector<uint8_t>& bytes, double baseline_bps) {
  FrameDecoder dec;
  uint64_t n = 0;
  const auto t0 = Clock::now();
  int reps = 0;
  do {
    dec.feed(bytes.data(), bytes.size(), [&](const Frame&) { ++n; });
    ++reps;
  } while (seconds_since(t0) < 0.5);
  const double dt = seconds_since(t0);
  std::printf("decode_%s_frames_per_s: %.0f frames/s\n", name, n / dt);
  std::printf("decode_%s_bytes_per_s: %.0f B/s\n", name, reps * bytes.size() / dt);
  std::printf("decode_%s_vs_memchr_scan: %.4f ratio\n", name, (reps * bytes.size() / dt) / baseline_bps);
}

// Writes SET_SPEED, waits for the board's STATE echoing its sequence number
// (the set-point is in force from then on; the PI loop acts on it at the
// next 1 ms tick).
void latency(const char* name, int baud) {
  const std::string link = "/tmp/mrt_airboard_bench_" + std::to_string(::getpid());
  FirmwareConfig c;
  c.motors = 3;
  LineFaults faults;
  faults.baud = baud;
  PtyEmulator emu(c, faults, link);
  std::atomic<bool> stop{false};
  std::thread t([&] { emu.run(stop); });
  SerialPort port;
  port.open(link, 115200);
  FrameDecoder dec;
  std::vector<double> lat_us;
  uint8_t buf[1024];
  const int n = baud ? 300 : 2000;
  for (int i = 0; i < n; ++i) {
    const auto seq = static_cast<uint8_t>(i);
    const auto f = encode_frame(make_set_speed(seq, {1.0 + i % 5, 2.0, 3.0}));
    const auto ts = Clock::now();
    port.write(f.data(), f.size());
    bool got = false;
    while (!got && seconds_since(ts) < 0.5) {
      port.wait_readable(5);
      const std::size_t k = port.read(buf, sizeof(buf));
      dec.feed(buf, k, [&](const Frame& fr) { got = got || (fr.type == proto::kState && fr.seq == seq); });
    }
    if (got) lat_us.push_back(seconds_since(ts) * 1e6);
  }
  stop = true;
  t.join();
  std::sort(lat_us.begin(), lat_us.end());
  auto pct = [&](double p) { return lat_us.empty() ? -1.0 : lat_us[static_cast<std::size_t>(p * (lat_us.size() - 1))]; };
  std::printf("%s_command_to_setpoint_p50: %.1f us\n", name, pct(0.5));
  std::printf("%s_command_to_setpoint_p99: %.1f us\n", name, pct(0.99));
  std::printf("%s_replies_lost: %zu frames\n", name, static_cast<std::size_t>(n) - lat_us.size());
}

}  // namespace

int main() {
  // 1. Decoder throughput on 64-byte STATE frames (3 motors: 6 + 13 + 3 x 15 bytes).
  const std::vector<uint8_t> clean = state_stream(20000);
  std::vector<uint8_t> dirty = clean;
  std::mt19937 rng(5);
  for (auto& x : dirty)
    if (rng() % 100 == 0) x ^= static_cast<uint8_t>(1u << (rng() % 8));
  // Baseline: scanning the same bytes for the start byte with memchr.
  volatile std::size_t sink = 0;
  const auto t0 = Clock::now();
  int reps = 0;
  do {
    const uint8_t* p = clean.data();
    const uint8_t* end = p + clean.size();
    while ((p = static_cast<const uint8_t*>(std::memchr(p, 0xA5, static_cast<std::size_t>(end - p))))) {
      sink = sink + 1;
      ++p;
    }
    ++reps;
  } while (seconds_since(t0) < 0.3);
  const double baseline = reps * clean.size() / seconds_since(t0);
  std::printf("memchr_scan_bytes_per_s: %.0f B/s\n", baseline);
  decode_rate("clean", clean, baseline);
  decode_rate("corrupt1pct", dirty, baseline);

  // 2. Latency through the pty, instantaneous and at the rate of a real
  // 115200-baud line.
  latency("pty", 0);
  latency("pty_115200baud", 115200);
  return 0;
}
