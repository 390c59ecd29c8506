#include "mrt_mice/evdev_mouse.h"

#include <fcntl.h>
#include <linux/input.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mrt::mice {

void EvdevAccumulator::feed(std::uint16_t type, std::uint16_t code, std::int32_t value) {
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
}

EvdevMouse::~EvdevMouse() { close(); }

bool EvdevMouse::open() {
  if (fd_ >= 0) return true;
  const int fd = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    error_ = path_ + ": " + std::strerror(errno);
    return false;
  }
  grabbed_ = false;
  if (grab_) {
    // Exclusive access: the events no longer reach the desktop cursor.
    if (::ioctl(fd, EVIOCGRAB, 1) == 0)
      grabbed_ = true;
    else
      error_ = path_ + ": cannot grab: " + std::strerror(errno);
  }
  fd_ = fd;
  ++connects_;
  return true;
}

void EvdevMouse::close() {
  if (fd_ < 0) return;
  if (grabbed_) ::ioctl(fd_, EVIOCGRAB, 0);
  ::close(fd_);
  fd_ = -1;
  grabbed_ = false;
}

bool EvdevMouse::poll(EvdevAccumulator& acc) {
  if (fd_ < 0) return false;
  input_event ev[64];
  while (true) {
    const ssize_t n = ::read(fd_, ev, sizeof ev);
    if (n > 0) {
      const std::size_t k = static_cast<std::size_t>(n) / sizeof(input_event);
      for (std::size_t i = 0; i < k; ++i) acc.feed(ev[i].type, ev[i].code, ev[i].value);
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
