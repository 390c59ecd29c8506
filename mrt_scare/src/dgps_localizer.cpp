#include "mrt_scare/dgps_localizer.h"

#include <cmath>

namespace mrt::scare {

DgpsLocalizer::DgpsLocalizer(const common::Pose2D& initial, DgpsLocalizerOptions o)
    : o_(o), pose_(initial) {}

void DgpsLocalizer::predict(double vx, double omega, double dt) {
  if (!(dt > 0.0)) return;
  pose_ = pose_ * common::exp_twist(vx, 0.0, omega, dt);
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

}  // namespace mrt::scare
