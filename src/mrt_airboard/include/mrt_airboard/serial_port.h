// Raw serial port (a real /dev/ttyUSB*, /dev/ttyS* or a pseudo-terminal):
// mrt_common's SerialPort, non-blocking, no hidden threads; and the
// reconnection back-off of the driver. ROS-free.
#pragma once

#include <algorithm>

#include "mrt_common/serial_port.h"

namespace mrt::airboard {

// The port itself is the stack's one serial abstraction, shared with DCDT's
// serial links: mrt_common/serial_port.h.
using SerialError = mrt::common::SerialError;
using SerialPort = mrt::common::SerialPort;

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
