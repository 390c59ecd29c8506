// Odometry from wheel encoder counts, for every base of base_kinematics.h
// (differential or omni): the AIRBoard driver's (mrt_airboard's
// BoardSession) and FollowMe's (the in-process loop, encoder_odometry_node).
// ROS-free, header-only.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_common/base_kinematics.h"
#include "mrt_common/pose2d.h"

namespace mrt::common {

/// Integrates cumulative encoder counts into the pose of base_link in odom.
/// Each update turns the count increments into wheel travels (counts times
/// 2 pi r / counts_per_rev, m), the travels into a body displacement with the
/// forward kinematics of a unit wheel, and composes the exact constant-twist
/// arc (exp_twist), so a constant command yields an exact circle whatever
/// the update rate. Differential: ds = (dl + dr) / 2, dtheta = (dr - dl) /
/// track.
class WheelOdometry {
 public:
  /// `twist_window`: the twist is measured over at least this long (s), so
  /// encoder quantisation does not make it noisy when updates are close.
  /// Throws std::invalid_argument for a non-positive wheel radius, track or
  /// count, or an omni geometry that does not span the plane.
  WheelOdometry(const BaseGeometry& geometry, int counts_per_rev, double twist_window = 0.01)
      : g_(geometry),
        unit_(geometry),
        m_per_count_(2.0 * kPi * geometry.wheel_radius / counts_per_rev),
        rad_per_count_(2.0 * kPi / counts_per_rev),
        lever_(geometry.type == BaseType::kDifferential ? 0.5 * geometry.track : geometry.wheel_distance),
        twist_window_(twist_window) {
    if (!(geometry.wheel_radius > 0.0) || !std::isfinite(geometry.wheel_radius))
      throw std::invalid_argument("WheelOdometry: wheel_radius must be > 0");
    if (counts_per_rev <= 0) throw std::invalid_argument("WheelOdometry: counts_per_rev must be > 0");
    if (geometry.type == BaseType::kDifferential && !(geometry.track > 0.0))
      throw std::invalid_argument("WheelOdometry: track must be > 0");
    if (geometry.type == BaseType::kOmni && !omni_spans_plane(geometry.wheel_distance, geometry.wheel_angles))
      throw std::invalid_argument("WheelOdometry: the omni wheel directions do not span the plane");
    unit_.wheel_radius = 1.0;  // the kinematics of the wheels' travels (m), not of their angles
  }

  /// Feeds cumulative counts (wrap-free) taken at `time` (s; only the twist
  /// needs it). The first call (and the first after reset()) only sets the
  /// reference. Throws std::invalid_argument unless there is one count per
  /// wheel.
  void update(const std::vector<std::int64_t>& counts, double time = 0.0) {
    if (counts.size() != g_.wheel_count())
      throw std::invalid_argument("WheelOdometry::update: expected " + std::to_string(g_.wheel_count()) +
                                  " wheel counts, got " + std::to_string(counts.size()));
    if (!have_ref_) {
      ref_ = twist_ref_ = counts;
      ref_time_ = twist_ref_time_ = time;
      have_ref_ = true;
      twist_ = Twist2D{};
      return;
    }
    std::vector<double> travel(counts.size());
    bool moved = false;
    for (std::size_t i = 0; i < counts.size(); ++i) {
      travel[i] = static_cast<double>(counts[i] - ref_[i]) * m_per_count_;
      moved = moved || counts[i] != ref_[i];
    }
    if (!moved && time - ref_time_ <= 0.0) return;
    const Twist2D d = forward(unit_, travel);  // the displacement as a twist applied for unit time
    pose_ = pose_ * exp_twist(d.vx, d.vy, d.omega, 1.0);
    travelled_ += std::hypot(d.vx, d.vy) + lever_ * std::abs(d.omega);
    const double tw = time - twist_ref_time_;
    if (tw >= twist_window_ * (1.0 - 1e-9) && tw > 0.0) {
      std::vector<double> speeds(counts.size());
      for (std::size_t i = 0; i < counts.size(); ++i)
        speeds[i] = static_cast<double>(counts[i] - twist_ref_[i]) * rad_per_count_ / tw;
      twist_ = forward(g_, speeds);
      twist_ref_ = counts;
      twist_ref_time_ = time;
    }
    ref_ = counts;
    ref_time_ = time;
  }

  /// Forgets the reference counts (after a reconnection the board may have
  /// restarted); keeps the pose; the twist becomes 0.
  void reset() {
    have_ref_ = false;
    twist_ = Twist2D{};
  }

  const Pose2D& pose() const { return pose_; }
  void set_pose(const Pose2D& p) { pose_ = p; }
  /// Body twist over the last twist window (m/s, rad/s); 0 without a time.
  const Twist2D& twist() const { return twist_; }
  /// Path length so far (m): the centre's travel plus the turns times the
  /// wheels' lever (half the track; the omni wheels' distance).
  double travelled() const { return travelled_; }
  const BaseGeometry& geometry() const { return g_; }

 private:
  BaseGeometry g_, unit_;
  double m_per_count_, rad_per_count_, lever_, twist_window_;
  bool have_ref_ = false;
  std::vector<std::int64_t> ref_, twist_ref_;
  double ref_time_ = 0.0, twist_ref_time_ = 0.0;
  Pose2D pose_;
  Twist2D twist_;
  double travelled_ = 0.0;
};

}  // namespace mrt::common
