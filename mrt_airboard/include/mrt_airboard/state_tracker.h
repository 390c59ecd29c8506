// Turns the board's STATE frames into wrap-free encoder counts and a
// continuous board clock mapped onto the host clock. ROS-free.
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_airboard/protocol.h"

namespace mrt::airboard {

class StateTracker {
 public:
  /// `drift_ppm`: how fast the host-board clock offset may grow (the offset
  /// follows the smallest observed transport delay; it can always shrink).
  explicit StateTracker(double drift_ppm = 1000.0) : drift_(drift_ppm * 1e-6) {}

  /// Feeds a STATE received at host time `host_time` (s). Returns false when
  /// it brings nothing new (same or older board time, e.g. a reply and a
  /// streamed frame of the same millisecond) or has a different motor count
  /// than the first one; the tracker is then unchanged.
  bool update(const BoardState& s, double host_time);
  /// Forgets everything (after a reconnection the board may have restarted).
  void reset() { have_ = false; }

  bool valid() const { return have_; }
  /// Cumulative counts since the first STATE after reset(), 64 bit.
  const std::vector<int64_t>& counts() const { return counts_; }
  /// Board time (s), continuous across the u32 ms wrap.
  double board_time() const { return board_time_; }
  /// Host time (s) of the last STATE's board instant.
  double host_stamp() const { return board_time_ + offset_; }

 private:
  double drift_;
  bool have_ = false;
  std::vector<int64_t> counts_;
  std::vector<uint32_t> raw_;
  uint32_t last_ms_ = 0;
  double board_time_ = 0.0;
  double offset_ = 0.0;
};

}  // namespace mrt::airboard
