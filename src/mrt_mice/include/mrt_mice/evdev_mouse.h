// A mouse read from a Linux evdev device (ROS-free): REL_X / REL_Y events
// committed at SYN_REPORT, the device grabbed so that it does not move the
// desktop cursor, unplug detected and the device reopened when it returns.
#pragma once

#include <cstdint>
#include <deque>
#include <string>

struct libevdev;

namespace mrt::mice {

/// Turns a stream of evdev events into counts in the mouse frame of
/// mrt_msgs/MouseReading (x forward along the mouse's longitudinal axis, y
/// to its left). evdev reports REL_X to the right and REL_Y towards the
/// user (backwards), so x = -REL_Y and y = -REL_X. Motion is committed at
/// SYN_REPORT; after SYN_DROPPED the partial report is discarded up to the
/// next SYN_REPORT, as the evdev protocol asks.
class EvdevAccumulator {
 public:
  /// One committed report with motion: its time stamp (the SYN_REPORT's
  /// event time, s) and counts in the mouse frame.
  struct Report {
    double t;
    std::int64_t dx, dy;
  };
  /// Feeds one event (type, code, value and time of struct input_event).
  void feed(std::uint16_t type, std::uint16_t code, std::int32_t value, double t = 0.0);
  /// Returns the committed counts since the last take and clears them (and
  /// the stamped reports).
  void take(std::int64_t* dx, std::int64_t* dy);
  /// The stamped reports since the last take (for CountAligner), clearing
  /// them and the counts.
  std::deque<Report> take_reports();
  std::uint64_t reports() const { return reports_; }
  std::uint64_t dropped() const { return dropped_; }

 private:
  std::int64_t pending_x_ = 0, pending_y_ = 0;  // evdev axes, this report
  std::int64_t dx_ = 0, dy_ = 0;                // mouse frame, committed
  bool discarding_ = false;
  std::uint64_t reports_ = 0;
  std::uint64_t dropped_ = 0;
  static constexpr std::size_t kMaxStamped = 4096;
  std::deque<Report> stamped_;
};

/// One evdev device: open (non-blocking), grab, read what is available,
/// close on unplug (ENODEV, EOF) and reopen on request. A real evdev device
/// is handled by libevdev (grab, event reading, the resynchronisation after
/// SYN_DROPPED); a file libevdev refuses because it is no evdev device (a
/// FIFO standing in for one in the tests: libevdev queries the device's
/// capabilities with ioctls) is read as struct input_event records.
class EvdevMouse {
 public:
  EvdevMouse(std::string path, bool grab) : path_(std::move(path)), grab_(grab) {}
  ~EvdevMouse();
  EvdevMouse(const EvdevMouse&) = delete;
  EvdevMouse& operator=(const EvdevMouse&) = delete;

  const std::string& path() const { return path_; }
  bool connected() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  /// Tries to open (and grab) the device; returns connected(). On failure
  /// last_error() says why.
  bool open();
  void close();
  /// Reads every event available now into `acc`; returns false (and
  /// closes) when the device went away.
  bool poll(EvdevAccumulator& acc);
  const std::string& last_error() const { return error_; }
  bool grabbed() const { return grabbed_; }
  /// True while the open device is read through libevdev.
  bool uses_libevdev() const { return dev_ != nullptr; }
  std::uint64_t connects() const { return connects_; }

 private:
  bool poll_libevdev(EvdevAccumulator& acc);
  bool poll_raw(EvdevAccumulator& acc);

  std::string path_;
  bool grab_;
  int fd_ = -1;
  ::libevdev* dev_ = nullptr;
  bool grabbed_ = false;
  std::string error_;
  std::uint64_t connects_ = 0;
};

}  // namespace mrt::mice
