// Differential odometry from the shaft encoders' cumulative ticks (the
// in-process loop; encoder_odometry_node for the distributed bringup without
// the AIRBoard). ROS-free.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "mrt_common/pose2d.h"

namespace mrt::followme {

/// Differential odometry from the encoder ticks (the AIRBoard's encoders).
class EncoderOdometry {
 public:
  EncoderOdometry(double wheel_radius, double track, int ticks_per_rev)
      : k_(2.0 * M_PI * wheel_radius / ticks_per_rev), track_(track) {}
  void update(const std::vector<std::int64_t>& ticks) {
    if (ticks.size() < 2) return;
    if (!prev_.empty()) {
      const double dl = static_cast<double>(ticks[0] - prev_[0]) * k_;
      const double dr = static_cast<double>(ticks[1] - prev_[1]) * k_;
      const double ds = 0.5 * (dl + dr), dth = (dr - dl) / track_;
      pose_ = pose_ * common::exp_twist(ds, 0.0, dth, 1.0);
      travelled_ += std::abs(ds) + 0.5 * track_ * std::abs(dth);
    }
    prev_ = ticks;
  }
  const common::Pose2D& pose() const { return pose_; }
  double travelled() const { return travelled_; }

 private:
  double k_, track_;
  std::vector<std::int64_t> prev_;
  common::Pose2D pose_;
  double travelled_ = 0.0;
};

}  // namespace mrt::followme
