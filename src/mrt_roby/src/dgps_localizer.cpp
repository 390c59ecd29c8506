#include "mrt_roby/dgps_localizer.h"

#include <algorithm>
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
  need(sigma_gbas > 0 && sigma_sbas > 0 && sigma_fix > 0, "sigma_*: expected numbers > 0 (m)");
}

DgpsLocalizer::DgpsLocalizer(const common::Pose2D& initial, DgpsLocalizerOptions o)
    : o_(o), plane_(o.datum), pose_(initial), var_xy_(o.initial_var), var_yaw_(o.initial_var) {}

void DgpsLocalizer::predict(double vx, double omega, double dt) {
  if (!(dt > 0.0)) return;
  pose_ = pose_ * common::exp_twist(vx, 0.0, omega, dt);
  const double dist = std::fabs(vx) * dt, turn = std::fabs(omega) * dt;
  var_xy_ += o_.odom_var_per_m * dist;
  var_yaw_ += o_.yaw_var_per_rad * turn + o_.yaw_var_per_m * dist;
}

void DgpsLocalizer::correct(const common::GeoPoint& fix, double var) {
  const common::Point2D p = plane_.to_local(fix);
  correct(p.x, p.y, var);
}

double DgpsLocalizer::fix_variance(int status, bool cov_known, double var_east, double var_north) const {
  if (status < 0) return -1.0;
  if (cov_known && std::isfinite(var_east) && std::isfinite(var_north) && std::max(var_east, var_north) > 0.0)
    return std::max(var_east, var_north);
  const double s = status >= 2 ? o_.sigma_gbas : status == 1 ? o_.sigma_sbas : o_.sigma_fix;
  return s * s;
}

std::array<double, 9> DgpsLocalizer::covariance() const {
  return {var_xy_, 0.0, 0.0, 0.0, var_xy_, 0.0, 0.0, 0.0, var_yaw_};
}

void DgpsLocalizer::wheel_state(double left, double right, double stamp) {
  const common::Twist2D t = common::differential_forward(o_.wheel_radius, o_.track, {left, right});
  if (last_stamp_ && stamp > *last_stamp_) {
    predict(t.vx, t.omega, stamp - *last_stamp_);
    twist_ = t;
  }
  last_stamp_ = stamp;
}

void DgpsLocalizer::correct(double x, double y, double var) {
  if (!(var > 0.0)) var = o_.sigma_gbas * o_.sigma_gbas;
  ++fixes_;
  if (have_fix_) {
    const double fdx = x - last_fix_.x, fdy = y - last_fix_.y;
    const double odx = pose_.x - pose_at_last_fix_.x, ody = pose_.y - pose_at_last_fix_.y;
    const double turn = std::fabs(common::angle_diff(pose_.theta, pose_at_last_fix_.theta));
    if (std::hypot(fdx, fdy) > o_.course_min_travel && std::hypot(odx, ody) > o_.course_min_travel &&
        turn < o_.course_max_turn) {
      const double err = common::angle_diff(std::atan2(fdy, fdx), std::atan2(ody, odx));
      pose_ = common::Pose2D(pose_.x, pose_.y, pose_.theta + o_.heading_gain * err);
      // The course between two fixes d apart: variance about 2 var / d^2.
      const double h = o_.heading_gain, d = std::hypot(fdx, fdy);
      var_yaw_ = (1 - h) * (1 - h) * var_yaw_ + h * h * 2.0 * var / (d * d);
    }
  }
  pose_ = common::Pose2D(pose_.x + o_.position_gain * (x - pose_.x),
                         pose_.y + o_.position_gain * (y - pose_.y), pose_.theta);
  const double g = o_.position_gain;
  var_xy_ = (1 - g) * (1 - g) * var_xy_ + g * g * var;
  have_fix_ = true;
  last_fix_ = {x, y};
  pose_at_last_fix_ = pose_;
}

}  // namespace mrt::roby
