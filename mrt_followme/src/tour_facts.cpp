#include "mrt_followme/tour_facts.h"

#include <algorithm>
#include <cmath>

namespace mrt::followme {

void TourFactsTracker::set_exhibit(const Exhibit& e) {
  exhibit_ = e;
  looked_for_ = 0.0;
}

TourFacts TourFactsTracker::update(double t, const Pose2D& pose, const std::optional<Point2D>& visitor,
                                   double speed) {
  if (last_t_ < 0.0) last_seen_ = t;  // lost only after lost_time of looking
  const double dt = last_t_ < 0.0 ? 0.0 : std::max(0.0, t - last_t_);
  last_t_ = t;
  TourFacts f;
  if (exhibit_) f.exhibit_distance = std::hypot(exhibit_->stop.x - pose.x, exhibit_->stop.y - pose.y);
  if (visitor) {
    last_seen_ = t;
    f.visitor_seen = true;
    const double dx = visitor->x - pose.x, dy = visitor->y - pose.y;
    f.visitor_distance = std::hypot(dx, dy);
    f.visitor_bearing = common::normalize_angle(std::atan2(dy, dx) - pose.theta);
    const double from_spot =
        exhibit_ ? std::hypot(visitor->x - exhibit_->spot.x, visitor->y - exhibit_->spot.y) : 1e9;
    const bool stands = speed < opt_.still_speed;
    if (from_spot <= opt_.look_radius && stands) looked_for_ += dt;
    f.back = f.visitor_distance <= opt_.ready_distance;
    // Wandered: standing away from the exhibit and from the robot (one
    // walking up to the exhibit or behind the robot has not wandered).
    f.wandered = stands && f.visitor_distance > opt_.ready_distance && from_spot > opt_.wander_distance;
    // Ready: it has looked, left the spot and stands by the robot.
    f.ready = looked_for_ >= opt_.look_time && f.back && stands && from_spot > 0.5 * opt_.look_radius;
    if (f.visitor_distance > opt_.keep_max) lagging_ = true;
    if (f.visitor_distance <= opt_.keep_resume) lagging_ = false;
    if (speed < opt_.still_speed) {
      if (still_since_ < 0.0) still_since_ = t;
    } else {
      still_since_ = -1.0;
    }
    f.still = still_since_ >= 0.0 && t - still_since_ >= opt_.call_after;
  } else {
    f.lost = t - last_seen_ > opt_.lost_time;  // lost: look for it
    f.wandered = f.lost;
    still_since_ = -1.0;
  }
  f.lagging = lagging_;
  f.looked = looked_for_ >= opt_.look_time;
  return f;
}

}  // namespace mrt::followme
