// The read loop of the two-mouse driver, ROS-free: both evdev devices read
// continuously (a 1 kHz mouse would overflow the kernel buffer between two
// publications), missing devices reopened every reconnect period, and the
// samples taken at the publication rate only while both mice are present.
// mice_evdev_node runs step() in its reader thread and take() in its timer.
//
// Thread-safe: step(), take() and the inspection calls lock one mutex. No
// clock is read: step() is given the time.
#pragma once

#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include "mrt_mice/count_aligner.h"
#include "mrt_mice/evdev_mouse.h"
#include "mrt_mice/mice_params.h"  // MiceCounts

namespace mrt::mice {

struct EvdevReaderOptions {
  std::string left_device, right_device;  // paths of the two evdev devices
  bool grab = true;                       // exclusive access (EVIOCGRAB)
  double reconnect_period = 1.0;          // s between reopen attempts
  AlignerOptions align;                   // take(now): both mice interpolated at now - align.delay

  /// Throws std::invalid_argument naming the option as its node parameter
  /// ("~right_device: ...").
  void validate() const;
};

/// What a diagnostics view of one device needs.
struct EvdevDeviceStatus {
  std::string path;
  bool connected = false;
  bool grabbed = false;
  std::string last_error;
  std::uint64_t connects = 0, unplugs = 0, reports = 0, dropped = 0;
};

class EvdevReader {
 public:
  enum class Event { kOpened, kOpenFailed, kLost };
  /// Told of each device event (device 0 left, 1 right) with a message;
  /// called with the reader's mutex held (must not call back into it).
  using Listener = std::function<void(Event, int device, const std::string& text)>;

  /// Throws std::invalid_argument when the options are invalid.
  explicit EvdevReader(const EvdevReaderOptions& o, Listener listener = {});

  /// One pass of the read loop at time `now` (s): reopens the missing
  /// devices when the reconnect period is over, waits up to `timeout_ms`
  /// for input and reads what both devices have. Returns false when no
  /// device is open (the caller sleeps a while before the next pass).
  bool step(double now, int timeout_ms);

  /// The counts since the last take, when both mice are present; otherwise
  /// nothing: the counts are dropped (a missing mouse is not a mouse
  /// standing still) and the sample is counted as withheld.
  std::optional<MiceCounts> take();
  /// The same, the two streams aligned: each mouse's reports, stamped with
  /// their event times, interpolated at `now - delay` (CountAligner). `now`
  /// is on the events' clock (evdev stamps with CLOCK_REALTIME by default:
  /// the wall clock). While a mouse is missing the aligner is reset.
  std::optional<MiceCounts> take(double now);
  AlignerStats align_stats() const;

  EvdevDeviceStatus status(int device) const;
  bool both_connected() const;
  /// The missing devices, e.g. "right mouse /dev/input/event7"; empty when none.
  std::string missing() const;
  std::uint64_t withheld() const;
  const EvdevReaderOptions& options() const { return o_; }

 private:
  void reopen(double now);
  void discard_counts();
  std::string missing_locked() const;
  EvdevMouse& mouse(int i) { return i ? right_ : left_; }
  EvdevAccumulator& acc(int i) { return i ? right_acc_ : left_acc_; }
  void notify(Event e, int i, const std::string& text) {
    if (listener_) listener_(e, i, text);
  }

  EvdevReaderOptions o_;
  Listener listener_;
  mutable std::mutex mutex_;
  EvdevMouse left_, right_;
  EvdevAccumulator left_acc_, right_acc_;
  CountAligner aligner_;
  std::uint64_t unplugs_[2] = {0, 0};
  std::uint64_t withheld_ = 0;
  bool tried_ = false;
  double next_try_ = 0.0;
};

}  // namespace mrt::mice
