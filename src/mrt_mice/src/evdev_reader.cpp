#include "mrt_mice/evdev_reader.h"

#include <poll.h>

#include <stdexcept>

namespace mrt::mice {

void EvdevReaderOptions::validate() const {
  if (left_device.empty())
    throw std::invalid_argument("~left_device: required (e.g. /dev/input/by-id/usb-...-event-mouse)");
  if (right_device.empty()) throw std::invalid_argument("~right_device: required");
  if (!(reconnect_period > 0.0)) throw std::invalid_argument("~reconnect_period: must be > 0");
  if (left_device == right_device) throw std::invalid_argument("~right_device: must differ from ~left_device");
}

EvdevReader::EvdevReader(const EvdevReaderOptions& o, Listener listener)
    : o_((o.validate(), o)),
      listener_(std::move(listener)),
      left_(o_.left_device, o_.grab),
      right_(o_.right_device, o_.grab),
      aligner_(o_.align) {}

void EvdevReader::reopen(double now) {
  if (tried_ && now < next_try_) return;
  tried_ = true;
  next_try_ = now + o_.reconnect_period;
  for (int i = 0; i < 2; ++i) {
    EvdevMouse& m = mouse(i);
    if (m.connected()) continue;
    if (m.open()) {
      notify(Event::kOpened, i, "opened " + m.path() + (m.grabbed() ? " (grabbed)" : ""));
      // Both mice start afresh: what the other one counted while this one
      // was away has no partner and is dropped.
      discard_counts();
    } else {
      notify(Event::kOpenFailed, i, m.last_error());
    }
  }
}

bool EvdevReader::step(double now, int timeout_ms) {
  pollfd fds[2];
  int n = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    reopen(now);
    if (left_.connected()) fds[n++] = {left_.fd(), POLLIN, 0};
    if (right_.connected()) fds[n++] = {right_.fd(), POLLIN, 0};
  }
  if (n == 0) return false;
  ::poll(fds, static_cast<nfds_t>(n), timeout_ms);
  std::lock_guard<std::mutex> lock(mutex_);
  for (int i = 0; i < 2; ++i) {
    EvdevMouse& m = mouse(i);
    if (m.connected() && !m.poll(acc(i))) {
      ++unplugs_[i];
      notify(Event::kLost, i, "lost " + m.last_error() + "; reconnecting");
    }
  }
  return true;
}

void EvdevReader::discard_counts() {
  std::int64_t dx, dy;
  left_acc_.take(&dx, &dy);
  right_acc_.take(&dx, &dy);
}

std::optional<MiceCounts> EvdevReader::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!left_.connected() || !right_.connected()) {
    discard_counts();
    ++withheld_;
    return std::nullopt;
  }
  MiceCounts c;
  left_acc_.take(&c.left_dx, &c.left_dy);
  right_acc_.take(&c.right_dx, &c.right_dy);
  return c;
}

std::optional<MiceCounts> EvdevReader::take(double now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!left_.connected() || !right_.connected()) {
    discard_counts();
    aligner_.reset();
    ++withheld_;
    return std::nullopt;
  }
  for (int i = 0; i < 2; ++i)
    for (const auto& r : acc(i).take_reports()) aligner_.add(i, r.t, r.dx, r.dy);
  return aligner_.take(now);
}

AlignerStats EvdevReader::align_stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return aligner_.stats();
}

EvdevDeviceStatus EvdevReader::status(int i) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const EvdevMouse& m = i ? right_ : left_;
  const EvdevAccumulator& a = i ? right_acc_ : left_acc_;
  EvdevDeviceStatus s;
  s.path = m.path();
  s.connected = m.connected();
  s.grabbed = m.grabbed();
  s.last_error = m.last_error();
  s.connects = m.connects();
  s.unplugs = unplugs_[i];
  s.reports = a.reports();
  s.dropped = a.dropped();
  return s;
}

bool EvdevReader::both_connected() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return left_.connected() && right_.connected();
}

std::string EvdevReader::missing_locked() const {
  std::string out;
  for (int i = 0; i < 2; ++i) {
    const EvdevMouse& m = i ? right_ : left_;
    if (m.connected()) continue;
    if (!out.empty()) out += " and ";
    out += std::string(i ? "right" : "left") + " mouse " + m.path();
  }
  return out;
}

std::string EvdevReader::missing() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return missing_locked();
}

std::uint64_t EvdevReader::withheld() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return withheld_;
}

}  // namespace mrt::mice
