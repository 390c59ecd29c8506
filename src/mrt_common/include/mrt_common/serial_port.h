// The stack's one serial-port abstraction (header-only, ROS-free, POSIX
// termios): a raw 8N1 line without flow control, on a real /dev/ttyUSB*,
// /dev/ttyS* or a pseudo-terminal. Used by the AIRBoard driver
// (mrt_airboard: non-blocking, polled) and DCDT's serial links (mrt_dcdt:
// blocking, the descriptor handed to its stream link with release()).
//
// Hand-written on termios because no Debian library fits: Boost.Asio's
// serial_port wants its io_context and its own asynchronous model (both
// users poll their descriptors themselves), and libserialport
// (libserialport-dev) would add a dependency for what is one tcsetattr.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace mrt::common {

class SerialError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How a port is opened.
struct SerialOptions {
  int baud = 115200;  ///< one of the standard rates 9600 ... 921600
  /// true: O_NONBLOCK and VMIN = VTIME = 0, read() returns 0 when nothing
  /// is there; false: blocking reads that wait for at least one byte.
  bool non_blocking = true;
  /// true: a device that is not a terminal is an error; false: it is used
  /// as it is, unconfigured (a FIFO or a socket standing in for a line).
  bool require_tty = true;
  bool flush_input = true;  ///< drop stale input and output once configured
};

/// termios speed of a baud rate; throws SerialError for a non-standard one.
inline speed_t baud_to_speed(int baud) {
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

class SerialPort {
 public:
  SerialPort() = default;
  ~SerialPort() { close(); }
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  /// Opens `path` raw 8N1 at `baud`, non-blocking, flushing stale input.
  /// Throws SerialError with the path and errno text.
  void open(const std::string& path, int baud) {
    SerialOptions o;
    o.baud = baud;
    open(path, o);
  }

  void open(const std::string& path, const SerialOptions& o) {
    close();
    const speed_t sp = baud_to_speed(o.baud);
    const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | (o.non_blocking ? O_NONBLOCK : 0));
    if (fd < 0) throw SerialError(error_text("cannot open", path));
    termios t{};
    if (tcgetattr(fd, &t) != 0) {
      if (!o.require_tty) {
        adopt(fd, path);
        return;
      }
      const std::string e = error_text("not a serial device:", path);
      ::close(fd);
      throw SerialError(e);
    }
    cfmakeraw(&t);  // also VMIN 1, VTIME 0: blocking reads wait for a byte
    t.c_cflag |= CLOCAL | CREAD;
    t.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
    t.c_iflag &= ~(IXON | IXOFF | IXANY);
    if (o.non_blocking) {
      t.c_cc[VMIN] = 0;
      t.c_cc[VTIME] = 0;
    }
    cfsetispeed(&t, sp);
    cfsetospeed(&t, sp);
    if (tcsetattr(fd, TCSANOW, &t) != 0) {
      const std::string e = error_text("cannot configure", path);
      ::close(fd);
      throw SerialError(e);
    }
    if (o.flush_input) tcflush(fd, TCIOFLUSH);
    adopt(fd, path);
  }

  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  bool is_open() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }

  /// Gives up ownership: returns the descriptor (the caller closes it).
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

  /// Reads what is available (0 when nothing, non-blocking ports). Throws
  /// SerialError when the device has gone (EIO, hang-up), after closing it.
  std::size_t read(uint8_t* buf, std::size_t cap) {
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
    const std::string e = error_text("read failed on", path_);
    close();
    throw SerialError(e);
  }

  /// Waits up to `timeout_ms` for input; true when readable.
  bool wait_readable(int timeout_ms) {
    if (fd_ < 0) return false;
    pollfd p{fd_, POLLIN, 0};
    return ::poll(&p, 1, timeout_ms) > 0 && (p.revents & POLLIN);
  }

  /// Writes all bytes (waiting briefly, at most 20 times 5 ms, when the
  /// driver's buffer is full). Throws SerialError when the device has gone,
  /// after closing it, or when the buffer stays full.
  void write(const uint8_t* data, std::size_t n) {
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
      const std::string e = error_text("write failed on", path_);
      close();
      throw SerialError(e);
    }
  }

 private:
  static std::string error_text(const std::string& what, const std::string& path) {
    return what + " " + path + ": " + std::strerror(errno);
  }
  void adopt(int fd, const std::string& path) {
    fd_ = fd;
    path_ = path;
  }

  int fd_ = -1;
  std::string path_;
};

}  // namespace mrt::common
