// The firmware model served on a pseudo-terminal in real time: what the
// airboard_emulator program and the latency benchmark run. ROS-free.
#pragma once

#include <atomic>
#include <chrono>
#include <deque>
#include <functional>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "mrt_airboard/firmware.h"

namespace mrt::airboard {

/// Line faults, applied to bytes crossing the emulated cable.
struct LineFaults {
  double corrupt_rx = 0.0;    // probability that a PC -> board byte gets one bit flipped
  double corrupt_tx = 0.0;    // same, board -> PC
  double cut_rx_after = -1.0; // s of board time after which PC -> board bytes are lost (< 0: never)
  uint32_t seed = 1;
  int baud = 0;               // > 0: bytes cross the line at baud / 10 per second (8N1); 0: instantly
};

struct EmulatorStats {
  uint64_t bytes_in = 0, bytes_out = 0, bytes_dropped_out = 0;
  uint64_t bytes_corrupted_in = 0, bytes_corrupted_out = 0, bytes_cut_in = 0;
  uint64_t late_ticks = 0;    // control periods run late (caught up)
  uint64_t paused_ticks = 0;  // periods skipped: the process was starved, board time paused
};

class PtyEmulator {
 public:
  /// Opens a pty pair in raw mode; when `link_path` is not empty, makes it a
  /// symlink to the slave (replacing a stale symlink). Throws
  /// std::runtime_error on failure.
  PtyEmulator(const FirmwareConfig& fw, const LineFaults& faults, std::string link_path);
  ~PtyEmulator();  // closes the pty and removes the symlink
  PtyEmulator(const PtyEmulator&) = delete;
  PtyEmulator& operator=(const PtyEmulator&) = delete;

  const std::string& slave_path() const { return slave_path_; }
  /// Serves the board until `stop` becomes true: input is handled as soon as
  /// it arrives, step() runs every 1 ms of wall time (up to 20 late periods
  /// are caught up; after a longer stall of this process board time pauses),
  /// or, with a time source, every 1 ms of that source's time.
  void run(const std::atomic<bool>& stop);

  /// Board time follows `seconds` (e.g. ROS time on a simulator's /clock)
  /// instead of the wall clock: the firmware steps as many 1 ms periods as
  /// the source advanced (up to 1000 at once; a larger jump, or the source
  /// going back, restarts the count without stepping: board time pauses).
  /// Board time starts at the first positive reading (a /clock not yet
  /// published reads 0). The line's baud-rate throttling follows the
  /// source too (a byte takes 10 / baud s of source time, converted to wall
  /// time by the source's rate over the last 100 ms). Only between runs.
  void set_time_source(std::function<double()> seconds) { time_source_ = std::move(seconds); }

  /// The wheel speeds the board reports, as the PC decodes them: called at
  /// every state frame the board sends, the moment it sends it (before any
  /// line fault), with its board time (ms) and one speed per motor (rad/s):
  /// a STATE's measured speeds; for a SHORT_STATE, which carries none, the
  /// firmware's measured speeds rounded to the wire's mrad/s. A frame of the
  /// same board time as the previous one (a reply beside the streamed
  /// frame) is not reported again. What a simulator takes as the robot's
  /// wheel commands (airboard_emulator --sim-wheel-cmd). Only between runs.
  using StateObserver = std::function<void(uint32_t board_ms, const std::vector<double>& speeds)>;
  void set_state_observer(StateObserver f) { observer_ = std::move(f); }

  /// Only between runs.
  const Firmware& firmware() const { return fw_; }
  const EmulatorStats& stats() const { return stats_; }

 private:
  using Clock = std::chrono::steady_clock;
  void run_on_source(const std::atomic<bool>& stop);
  void flush();
  bool handle_input();  // one non-blocking read; false when nothing was read
  void deliver(uint8_t* d, std::size_t n);
  void write_out(const uint8_t* d, std::size_t n);
  void service_line(Clock::time_point now);  // moves throttled bytes whose time has come
  void corrupt(uint8_t* d, std::size_t n, double p, uint64_t* count);
  void observe(const std::vector<uint8_t>& out);  // the state frames of the board's output

  Firmware fw_;
  LineFaults faults_;
  std::string link_path_;
  std::string slave_path_;
  int master_ = -1;
  int slave_ = -1;
  std::mt19937 rng_;
  EmulatorStats stats_;
  Clock::duration byte_time_{0};
  std::deque<std::pair<uint8_t, Clock::time_point>> rx_q_, tx_q_;
  Clock::time_point rx_free_{}, tx_free_{};
  std::function<double()> time_source_;
  StateObserver observer_;
  FrameDecoder out_dec_;  // the board's own output, for the observer
  bool observed_ = false;
  uint32_t observed_ms_ = 0;
};

}  // namespace mrt::airboard
