// The robot's track of its visitor from the camera's Person percepts: the
// Person of the visitor's colour (its badge) nearest the prediction within a
// gate, placed in the map with the localizer's pose; velocity from the
// positions over the last `velocity_window` seconds. ROS-free.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <utility>

#include "mrt_common/pose2d.h"

namespace mrt::followme {

using common::Point2D;
using common::Pose2D;

/// One Person percept: colour, distance (m), bearing (rad, CCW from ahead).
struct PersonPercept {
  std::string color;
  double distance = 0.0;
  double bearing = 0.0;
};

struct VisitorTrack {
  Point2D position;
  Point2D velocity;    // m/s
  double last_seen = -1e9;
  double speed() const;
};

class VisitorTracker {
 public:
  explicit VisitorTracker(std::string color, double gate = 1.5, double velocity_window = 1.0)
      : color_(std::move(color)), gate_(gate), window_(velocity_window) {}

  /// One camera frame at time t seen from `robot` (the localizer's pose);
  /// returns true when the visitor was among the percepts.
  template <class Range>
  bool update(double t, const Pose2D& robot, const Range& persons) {
    std::optional<Point2D> best;
    double best_d = 1e9;
    for (const PersonPercept& p : persons) {
      if (p.color != color_) continue;
      const Point2D w = robot.transform({p.distance * std::cos(p.bearing), p.distance * std::sin(p.bearing)});
      const double d = track_ ? std::hypot(w.x - track_->position.x, w.y - track_->position.y) : 0.0;
      if ((!track_ || d < gate_ + track_->speed() * (t - track_->last_seen)) && d < best_d) {
        best = w;
        best_d = d;
      }
    }
    if (!best) return false;
    observe(t, *best);
    return true;
  }

  /// The visitor seen at `p` (map frame) at time t: camera frames through
  /// update(); a tracker of its own (MAP's track, in the distributed
  /// bringup) directly.
  void observe(double t, const Point2D& p);

  const std::optional<VisitorTrack>& track() const { return track_; }
  /// Seconds since the visitor was last seen (infinite before the first time).
  double unseen_for(double t) const { return track_ ? t - track_->last_seen : 1e9; }

 private:

  std::string color_;
  double gate_, window_;
  std::optional<VisitorTrack> track_;
  std::deque<std::pair<double, Point2D>> history_;
};

}  // namespace mrt::followme
