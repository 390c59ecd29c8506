#include "mrt_followme/visitor_tracker.h"

#include <cmath>

namespace mrt::followme {

double VisitorTrack::speed() const { return std::hypot(velocity.x, velocity.y); }

void VisitorTracker::observe(double t, const Point2D& p) {
  history_.emplace_back(t, p);
  while (history_.size() > 2 && t - history_[1].first >= window_) history_.pop_front();
  VisitorTrack tr;
  tr.position = p;
  tr.last_seen = t;
  const auto& [t0, p0] = history_.front();
  if (t - t0 > 0.2) tr.velocity = {(p.x - p0.x) / (t - t0), (p.y - p0.y) / (t - t0)};
  track_ = tr;
}

}  // namespace mrt::followme
