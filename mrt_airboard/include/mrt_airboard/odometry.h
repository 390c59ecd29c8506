// Odometry from wheel encoder counts. ROS-free.
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_airboard/kinematics.h"
#include "mrt_common/pose2d.h"

namespace mrt::airboard {

/// Integrates encoder counts into a pose of base_link in odom. Each update
/// turns the count increments into a body displacement with the forward
/// kinematics and composes the exact constant-twist arc (exp_twist), so a
/// constant command yields an exact circle whatever the update rate.
class EncoderOdometry {
 public:
  /// `twist_window`: the twist is measured over at least this long (s), so
  /// encoder quantisation does not make it noisy when updates are close.
  explicit EncoderOdometry(const BaseParams& p, double twist_window = 0.01);

  /// Feeds cumulative counts (wrap-free) taken at `time` (s). The first call
  /// (and the first after reset()) only sets the reference.
  void update(const std::vector<int64_t>& counts, double time);
  /// Forgets the reference counts (after a reconnection the board may have
  /// restarted); keeps the pose; the twist becomes 0.
  void reset();

  const mrt::common::Pose2D& pose() const { return pose_; }
  /// Body twist over the last twist window (m/s, rad/s).
  const Twist2D& twist() const { return twist_; }
  void set_pose(const mrt::common::Pose2D& p) { pose_ = p; }

 private:
  std::unique_ptr<BaseKinematics> kin_;
  double rad_per_count_;
  bool have_ref_ = false;
  std::vector<int64_t> ref_;
  double ref_time_ = 0.0;
  double twist_window_;
  std::vector<int64_t> twist_ref_;
  double twist_ref_time_ = 0.0;
  mrt::common::Pose2D pose_;
  Twist2D twist_;
};

}  // namespace mrt::airboard
