#include "mrt_mice/evdev_mouse.h"

#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <linux/input.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mrt::mice {

void EvdevAccumulator::feed(std::uint16_t type, std::uint16_t code, std::int32_t value, double t) {
  if (type == EV_SYN && code == SYN_DROPPED) {
    ++dropped_;
    discarding_ = true;
    pending_x_ = pending_y_ = 0;
    return;
  }
  if (type == EV_SYN && code == SYN_REPORT) {
    if (!discarding_) {
      dx_ += -pending_y_;
      dy_ += -pending_x_;
      ++reports_;
      if (pending_x_ != 0 || pending_y_ != 0) {
        // Bounded: a consumer that never takes the reports merges the oldest.
        if (stamped_.size() >= kMaxStamped) {
          stamped_[1].dx += stamped_[0].dx;
          stamped_[1].dy += stamped_[0].dy;
          stamped_.pop_front();
        }
        stamped_.push_back({t, -pending_y_, -pending_x_});
      }
    }
    discarding_ = false;
    pending_x_ = pending_y_ = 0;
    return;
  }
  if (type == EV_REL && !discarding_) {
    if (code == REL_X) pending_x_ += value;
    if (code == REL_Y) pending_y_ += value;
  }
}

void EvdevAccumulator::take(std::int64_t* dx, std::int64_t* dy) {
  *dx = dx_;
  *dy = dy_;
  dx_ = dy_ = 0;
  stamped_.clear();
}

std::deque<EvdevAccumulator::Report> EvdevAccumulator::take_reports() {
  std::deque<Report> out;
  out.swap(stamped_);
  dx_ = dy_ = 0;
  return out;
}

namespace {
double stamp(const input_event& ev) {
  return static_cast<double>(ev.input_event_sec) + 1e-6 * static_cast<double>(ev.input_event_usec);
}
}  // namespace

EvdevMouse::~EvdevMouse() { close(); }

bool EvdevMouse::open() {
  if (fd_ >= 0) return true;
  const int fd = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    error_ = path_ + ": " + std::strerror(errno);
    return false;
  }
  grabbed_ = false;
  const int rc = libevdev_new_from_fd(fd, &dev_);
  if (rc < 0) dev_ = nullptr;  // not an evdev device: read as input_event records
  if (grab_) {
    // Exclusive access: the events no longer reach the desktop cursor.
    const int g = dev_ ? libevdev_grab(dev_, LIBEVDEV_GRAB) : -ENOTTY;
    if (g == 0)
      grabbed_ = true;
    else
      error_ = path_ + ": cannot grab: " + std::strerror(-g);
  }
  fd_ = fd;
  ++connects_;
  return true;
}

void EvdevMouse::close() {
  if (fd_ < 0) return;
  if (dev_) {
    if (grabbed_) libevdev_grab(dev_, LIBEVDEV_UNGRAB);
    libevdev_free(dev_);
    dev_ = nullptr;
  }
  ::close(fd_);
  fd_ = -1;
  grabbed_ = false;
}

bool EvdevMouse::poll(EvdevAccumulator& acc) {
  if (fd_ < 0) return false;
  return dev_ ? poll_libevdev(acc) : poll_raw(acc);
}

bool EvdevMouse::poll_libevdev(EvdevAccumulator& acc) {
  input_event ev{};
  while (true) {
    int rc = libevdev_next_event(dev_, LIBEVDEV_READ_FLAG_NORMAL, &ev);
    if (rc == LIBEVDEV_READ_STATUS_SUCCESS) {
      acc.feed(ev.type, ev.code, ev.value, stamp(ev));
      continue;
    }
    if (rc == LIBEVDEV_READ_STATUS_SYNC) {
      // SYN_DROPPED: libevdev has drained the kernel's queue and hands out
      // the device's state as sync events (keys, absolute axes: no motion).
      // The cut report is discarded, and the drained queue ends it.
      acc.feed(EV_SYN, SYN_DROPPED, 0);
      do rc = libevdev_next_event(dev_, LIBEVDEV_READ_FLAG_SYNC, &ev);
      while (rc == LIBEVDEV_READ_STATUS_SYNC);
      acc.feed(EV_SYN, SYN_REPORT, 0, stamp(ev));
      continue;
    }
    if (rc == -EAGAIN) return true;
    if (rc == -EINTR) continue;
    // -ENODEV (unplugged) or another read error: the device is gone.
    error_ = path_ + ": " + std::strerror(-rc);
    close();
    return false;
  }
}

bool EvdevMouse::poll_raw(EvdevAccumulator& acc) {
  input_event ev[64];
  while (true) {
    const ssize_t n = ::read(fd_, ev, sizeof ev);
    if (n > 0) {
      const std::size_t k = static_cast<std::size_t>(n) / sizeof(input_event);
      for (std::size_t i = 0; i < k; ++i) acc.feed(ev[i].type, ev[i].code, ev[i].value, stamp(ev[i]));
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
    if (n < 0 && errno == EINTR) continue;
    // ENODEV (unplugged) or end of file: the device is gone.
    error_ = path_ + (n == 0 ? ": end of file" : std::string(": ") + std::strerror(errno));
    close();
    return false;
  }
}

}  // namespace mrt::mice
