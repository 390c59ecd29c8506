// Turns the board's STATE frames into wrap-free encoder counts and a
// continuous board clock mapped onto the host clock. ROS-free.
#pragma once

#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "mrt_airboard/protocol.h"

namespace mrt::airboard {

class StateTracker {
 public:
  /// `drift_ppm`: how fast the host-board clock offset may grow (the offset
  /// follows the smallest observed transport delay; it can always shrink).
  /// `window_s`: the offset is never below the smallest (host - board) of
  /// the frames received in the last `window_s` of host time, so the stamps
  /// lag the reception of the latest frame by at most the delay spread of
  /// that window. Without it (window_s <= 0) a host clock that stalls while
  /// the board runs on (mrt_sim's /clock under load against the emulator's
  /// wall clock) lowers the offset for good and the stamps fall behind by
  /// the sum of the stalls, recovered only at `drift_ppm`.
  explicit StateTracker(double drift_ppm = 1000.0, double window_s = 1.0)
      : drift_(drift_ppm * 1e-6), window_(window_s) {}

  /// Feeds a STATE received at host time `host_time` (s). Returns false when
  /// it brings nothing new (same or older board time, e.g. a reply and a
  /// streamed frame of the same millisecond) or has a different motor count
  /// than the first one; the tracker is then unchanged.
  bool update(const BoardState& s, double host_time);
  /// Feeds a SHORT_STATE (16-bit clock and counts, unwrapped by modular
  /// differences against the last update). When more than `max_gap_ms` of
  /// board time passed since the last update, a 16-bit count difference is
  /// ambiguous: the counts are re-based on this frame (as after reset(), but
  /// the board clock stays continuous) and rebased() is true until the next
  /// update. Returns false as update() does.
  bool update_short(const ShortState& s, double host_time, uint32_t max_gap_ms);
  /// True when the last successful update restarted the counts (first update
  /// after reset(), or a SHORT_STATE after too long a gap): the caller's
  /// odometry must take a new reference.
  bool rebased() const { return rebased_; }
  /// Forgets everything (after a reconnection the board may have restarted).
  void reset() {
    have_ = false;
    recent_.clear();
  }

  bool valid() const { return have_; }
  /// Cumulative counts since the first STATE after reset(), 64 bit.
  const std::vector<int64_t>& counts() const { return counts_; }
  /// Board time (s), continuous across the u32 ms wrap.
  double board_time() const { return board_time_; }
  /// Host time (s) of the last STATE's board instant.
  double host_stamp() const { return board_time_ + offset_; }

 private:
  double drift_;
  double window_;
  // (host time, host - board) of the recent frames, offsets increasing
  // front to back: the front is the window's minimum.
  std::deque<std::pair<double, double>> recent_;
  void remember(double host_time);
  bool advance(uint32_t dms, double host_time);
  bool have_ = false;
  bool rebased_ = false;
  bool full_ = false;  // raw_ and last_ms_ hold all 32 bits (a STATE was seen since the last re-base)
  std::vector<int64_t> counts_;
  std::vector<uint32_t> raw_;
  uint32_t last_ms_ = 0;
  double board_time_ = 0.0;
  double offset_ = 0.0;
};

}  // namespace mrt::airboard
