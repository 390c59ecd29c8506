#include "mrt_airboard/state_tracker.h"

#include <algorithm>

namespace mrt::airboard {

bool StateTracker::update(const BoardState& s, double host_time) {
  const std::size_t n = s.motors.size();
  if (!have_) {
    counts_.assign(n, 0);
    raw_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      raw_[i] = static_cast<uint32_t>(s.motors[i].ticks);
      counts_[i] = s.motors[i].ticks;
    }
    last_ms_ = s.time_ms;
    board_time_ = s.time_ms * 1e-3;
    offset_ = host_time - board_time_;
    have_ = true;
    return true;
  }
  if (n != counts_.size()) return false;
  // Modular differences: correct across the u32 / i32 wraps as long as
  // updates are less than 2^31 ms and 2^31 counts apart.
  const int32_t dms = static_cast<int32_t>(s.time_ms - last_ms_);
  if (dms <= 0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const uint32_t r = static_cast<uint32_t>(s.motors[i].ticks);
    counts_[i] += static_cast<int32_t>(r - raw_[i]);
    raw_[i] = r;
  }
  last_ms_ = s.time_ms;
  const double dt = dms * 1e-3;
  board_time_ += dt;
  offset_ = std::min(offset_ + drift_ * dt, host_time - board_time_);
  return true;
}

}  // namespace mrt::airboard
