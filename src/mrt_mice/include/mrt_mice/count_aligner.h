// Aligns the two mice's count streams in time before the rigid-body check.
// ROS-free.
//
// On a robot the two mice are two USB devices polled by the host on their
// own schedules (typically every 8 ms at 125 Hz, with independent phases):
// counts summed "since the last publication" cover windows that differ by
// up to one USB frame, and a window holding three reports of one mouse and
// two of the other breaks the rigid-body constraint though nothing slipped.
// Each report is therefore kept with its own time stamp (the kernel's event
// time), each mouse's cumulative counts are interpolated linearly at one
// common instant, `delay` before the sampling time (so that both mice have
// reported past it), and the sample is the difference between two such
// instants.
#pragma once

#include <cstdint>
#include <deque>

#include "mrt_mice/mice_params.h"  // MiceCounts

namespace mrt::mice {

struct AlignerOptions {
  double delay = 0.010;   // s: common instant = sampling time - delay (>= one USB frame)
  double frame = 0.008;   // s: a report's counts were gathered over at most this long before it
  /// Throws std::invalid_argument naming the option.
  void validate() const;
};

struct AlignerStats {
  std::uint64_t reports = 0;
  std::uint64_t out_of_order = 0;  // reports older than the mouse's last one: dropped
  std::uint64_t late = 0;          // reports stamped before the last common instant: applied at it
};

class CountAligner {
 public:
  explicit CountAligner(AlignerOptions o = {});
  /// A report of mouse `mouse` (0 left, 1 right) stamped `t` (s): its counts
  /// since its previous report, in the mouse frame. A report older than the
  /// mouse's previous one is dropped (false, counted).
  bool add(int mouse, double t, std::int64_t dx, std::int64_t dy);
  /// The counts of both mice from the previous common instant to
  /// `now - delay`, each mouse's cumulative counts interpolated there and
  /// rounded (the rounding is carried to the next sample, never lost).
  MiceCounts take(double now);
  /// Forgets the reports (a mouse was unplugged: its counts are lost).
  void reset();
  const AlignerStats& stats() const { return stats_; }

 private:
  struct Report {
    double t;
    double x, y;  // cumulative counts after this report
    double span;  // s over which its counts were gathered
  };
  void value_at(int mouse, double t, double* x, double* y) const;

  AlignerOptions o_;
  std::deque<Report> r_[2];
  double base_[2][2] = {{0, 0}, {0, 0}};  // cumulative counts before the first kept report
  double cum_[2][2] = {{0, 0}, {0, 0}};   // cumulative counts after the last report
  std::int64_t out_[2][2] = {{0, 0}, {0, 0}};  // cumulative counts already handed out
  double last_t_[2] = {-1e300, -1e300};    // of the last report, as used (deferred ones moved)
  double last_raw_[2] = {-1e300, -1e300};  // of the last report, as stamped
  double instant_ = -1e300;  // the last common instant
  AlignerStats stats_;
};

}  // namespace mrt::mice
