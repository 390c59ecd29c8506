#include "mrt_airboard/serial_port.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

namespace mrt::airboard {

namespace {
speed_t to_speed(int baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 500000: return B500000;
    case 921600: return B921600;
    default: throw SerialError("unsupported baud rate " + std::to_string(baud));
  }
}
std::string err(const std::string& what, const std::string& path) {
  return what + " " + path + ": " + std::strerror(errno);
}
}  // namespace

SerialPort::~SerialPort() { close(); }

void SerialPort::open(const std::string& path, int baud) {
  close();
  const speed_t sp = to_speed(baud);
  int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw SerialError(err("cannot open", path));
  termios t{};
  if (tcgetattr(fd, &t) != 0) {
    const std::string e = err("not a serial device:", path);
    ::close(fd);
    throw SerialError(e);
  }
  cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
  t.c_iflag &= ~(IXON | IXOFF | IXANY);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  cfsetispeed(&t, sp);
  cfsetospeed(&t, sp);
  if (tcsetattr(fd, TCSANOW, &t) != 0) {
    const std::string e = err("cannot configure", path);
    ::close(fd);
    throw SerialError(e);
  }
  tcflush(fd, TCIOFLUSH);
  fd_ = fd;
  path_ = path;
}

void SerialPort::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::size_t SerialPort::read(uint8_t* buf, std::size_t cap) {
  if (fd_ < 0) throw SerialError("read: port not open");
  const ssize_t n = ::read(fd_, buf, cap);
  if (n > 0) return static_cast<std::size_t>(n);
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return 0;
  // n == 0 on a tty in non-blocking raw mode is "nothing"; check for hang-up.
  if (n == 0) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 0) > 0 && (p.revents & (POLLHUP | POLLERR | POLLNVAL))) {
      close();
      throw SerialError("device " + path_ + " hung up");
    }
    return 0;
  }
  const std::string e = err("read failed on", path_);
  close();
  throw SerialError(e);
}

bool SerialPort::wait_readable(int timeout_ms) {
  if (fd_ < 0) return false;
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, timeout_ms) > 0 && (p.revents & POLLIN);
}

void SerialPort::write(const uint8_t* data, std::size_t n) {
  if (fd_ < 0) throw SerialError("write: port not open");
  std::size_t done = 0;
  int waits = 0;
  while (done < n) {
    const ssize_t k = ::write(fd_, data + done, n - done);
    if (k > 0) {
      done += static_cast<std::size_t>(k);
      continue;
    }
    if (k < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) {
      if (++waits > 20) throw SerialError("write timed out on " + path_);
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, 5);
      continue;
    }
    const std::string e = err("write failed on", path_);
    close();
    throw SerialError(e);
  }
}

}  // namespace mrt::airboard
