#include "mrt_roby/dgps_localizer.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mrt::roby {

void DgpsLocalizerOptions::validate() const {
  auto need = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(what);
  };
  need(common::LocalTangentPlane::valid_datum(datum), "datum: expected [latitude, longitude] in degrees, |latitude| < 90");
  need(std::isfinite(wheel_radius) && wheel_radius > 0, "wheel_radius: expected a finite number > 0");
  need(std::isfinite(track) && track > 0, "track: expected a finite number > 0");
  need(position_gain >= 0 && position_gain <= 1, "position_gain: expected a number in [0, 1]");
  need(heading_gain >= 0 && heading_gain <= 1, "heading_gain: expected a number in [0, 1]");
}

DgpsLocalizer::DgpsLocalizer(const common::Pose2D& initial, DgpsLocalizerOptions o)
    : o_(o), plane_(o.datum), pose_(initial) {}

void DgpsLocalizer::predict(double vx, double omega, double dt) {
  if (!(dt > 0.0)) return;
  pose_ = pose_ * common::exp_twist(vx, 0.0, omega, dt);
}

void DgpsLocalizer::correct(const common::GeoPoint& fix) {
  const common::Point2D p = plane_.to_local(fix);
  correct(p.x, p.y);
}

void DgpsLocalizer::wheel_state(double left, double right, double stamp) {
  const common::Twist2D t = common::differential_forward(o_.wheel_radius, o_.track, {left, right});
  if (last_stamp_ && stamp > *last_stamp_) {
    predict(t.vx, t.omega, stamp - *last_stamp_);
    twist_ = t;
  }
  last_stamp_ = stamp;
}

void DgpsLocalizer::correct(double x, double y) {
  ++fixes_;
  if (have_fix_) {
    const double fdx = x - last_fix_.x, fdy = y - last_fix_.y;
    const double odx = pose_.x - pose_at_last_fix_.x, ody = pose_.y - pose_at_last_fix_.y;
    const double turn = std::fabs(common::angle_diff(pose_.theta, pose_at_last_fix_.theta));
    if (std::hypot(fdx, fdy) > o_.course_min_travel && std::hypot(odx, ody) > o_.course_min_travel &&
        turn < o_.course_max_turn) {
      const double err = common::angle_diff(std::atan2(fdy, fdx), std::atan2(ody, odx));
      pose_ = common::Pose2D(pose_.x, pose_.y, pose_.theta + o_.heading_gain * err);
    }
  }
  pose_ = common::Pose2D(pose_.x + o_.position_gain * (x - pose_.x),
                         pose_.y + o_.position_gain * (y - pose_.y), pose_.theta);
  have_fix_ = true;
  last_fix_ = {x, y};
  pose_at_last_fix_ = pose_;
}

}  // namespace mrt::roby
