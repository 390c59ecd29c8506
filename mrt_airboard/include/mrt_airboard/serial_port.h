// Raw serial port (a real /dev/ttyUSB*, /dev/ttyS* or a pseudo-terminal).
// ROS-free, non-blocking, no hidden threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace mrt::airboard {

class SerialError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SerialPort {
 public:
  SerialPort() = default;
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  /// Opens `path` raw 8N1, no flow control, at `baud` (one of the standard
  /// rates up to 921600), non-blocking, and flushes stale input. Throws
  /// SerialError with the path and errno text.
  void open(const std::string& path, int baud);
  void close();
  bool is_open() const { return fd_ >= 0; }
  int fd() const { return fd_; }

  /// Reads what is available (0 when nothing). Throws SerialError when the
  /// device has gone (EIO, hang-up), after closing it.
  std::size_t read(uint8_t* buf, std::size_t cap);
  /// Waits up to `timeout_ms` for input; true when readable.
  bool wait_readable(int timeout_ms);
  /// Writes all bytes (waiting briefly if the driver's buffer is full).
  /// Throws SerialError when the device has gone, after closing it.
  void write(const uint8_t* data, std::size_t n);

 private:
  int fd_ = -1;
  std::string path_;
};

/// Exponential back-off between reconnection attempts.
class Backoff {
 public:
  Backoff(double min_s, double max_s) : min_(min_s), max_(max_s), cur_(min_s) {}
  /// True when an attempt is due at `now` (s).
  bool due(double now) const { return now >= next_; }
  /// Records a failed attempt at `now`; the delay doubles up to max.
  void failed(double now) {
    next_ = now + cur_;
    cur_ = std::min(max_, cur_ * 2.0);
  }
  void succeeded() { cur_ = min_; next_ = 0.0; }
  double current_delay() const { return cur_; }

 private:
  double min_, max_, cur_;
  double next_ = 0.0;
};

}  // namespace mrt::airboard
