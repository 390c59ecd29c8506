#include "mrt_airboard/state_tracker.h"

#include <algorithm>

namespace mrt::airboard {

void StateTracker::remember(double host_time) {
  const double o = host_time - board_time_;
  if (window_ <= 0.0) return;
  while (!recent_.empty() && recent_.back().second >= o) recent_.pop_back();
  recent_.emplace_back(host_time, o);
  while (recent_.front().first < host_time - window_) recent_.pop_front();
}

bool StateTracker::advance(uint32_t dms, double host_time) {
  const double dt = dms * 1e-3;
  board_time_ += dt;
  offset_ = std::min(offset_ + drift_ * dt, host_time - board_time_);
  remember(host_time);
  // The window's minimum includes this frame, so the offset stays at most
  // host_time - board_time_: a stamp is never later than its reception.
  if (!recent_.empty()) offset_ = std::max(offset_, recent_.front().second);
  return true;
}

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
    recent_.clear();
    remember(host_time);
    have_ = true;
    full_ = true;
    rebased_ = true;
    return true;
  }
  if (n != counts_.size()) return false;
  // Modular differences: correct across the u32 / i32 wraps as long as
  // updates are less than 2^31 ms and 2^31 counts apart. After SHORT_STATEs
  // only the low 16 bits of the previous clock and counts are known: 16-bit
  // differences then (the SHORT_STATE's own validity horizon).
  const int32_t dms = full_ ? static_cast<int32_t>(s.time_ms - last_ms_)
                            : static_cast<int16_t>(static_cast<uint16_t>(s.time_ms - last_ms_));
  if (dms <= 0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const uint32_t r = static_cast<uint32_t>(s.motors[i].ticks);
    counts_[i] += full_ ? static_cast<int32_t>(r - raw_[i])
                        : static_cast<int16_t>(static_cast<uint16_t>(r - raw_[i]));
    raw_[i] = r;
  }
  last_ms_ = s.time_ms;
  full_ = true;
  rebased_ = false;
  return advance(static_cast<uint32_t>(dms), host_time);
}

bool StateTracker::update_short(const ShortState& s, double host_time, uint32_t max_gap_ms) {
  const std::size_t n = s.ticks.size();
  if (!have_) {
    counts_.assign(n, 0);
    raw_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      raw_[i] = static_cast<uint32_t>(static_cast<int32_t>(s.ticks[i]));
      counts_[i] = s.ticks[i];
    }
    last_ms_ = s.time_ms;
    board_time_ = s.time_ms * 1e-3;
    offset_ = host_time - board_time_;
    recent_.clear();
    remember(host_time);
    have_ = true;
    full_ = false;
    rebased_ = true;
    return true;
  }
  if (n != counts_.size()) return false;
  // The frames arrive in board-time order: the 16-bit difference is the
  // elapsed time (less than 65.5 s: the node's link timeout is far shorter).
  const uint16_t dms = static_cast<uint16_t>(s.time_ms - static_cast<uint16_t>(last_ms_));
  if (dms == 0) return false;
  rebased_ = dms > max_gap_ms;
  for (std::size_t i = 0; i < n; ++i) {
    const uint16_t r = static_cast<uint16_t>(s.ticks[i]);
    const int16_t d = static_cast<int16_t>(static_cast<uint16_t>(r - static_cast<uint16_t>(raw_[i])));
    if (rebased_)
      counts_[i] = s.ticks[i];
    else
      counts_[i] += d;
    raw_[i] += static_cast<uint32_t>(static_cast<int32_t>(d));  // low 16 bits now equal r
  }
  last_ms_ += dms;
  full_ = false;
  return advance(dms, host_time);
}

}  // namespace mrt::airboard
