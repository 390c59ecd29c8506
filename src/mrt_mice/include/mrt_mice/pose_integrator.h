// Pose integration, manual eqs. 4.3-4.5 as corrected in NOTES.md.
#pragma once

#include "mrt_mice/mice_params.h"

namespace mrt::mice {

/// X' = X + sqrt(dx^2 + dy^2) cos(Theta + atan2(dy, dx)),
/// Y' = Y + sqrt(dx^2 + dy^2) sin(Theta + atan2(dy, dx)),
/// Theta' = Theta + dtheta (wrapped to (-pi, pi]).
Pose2D integrate_pose(const Pose2D& pose, const Pose2D& delta);

/// Accumulates body displacements into a pose in the odometry frame and
/// keeps the distance travelled.
class PoseIntegrator {
 public:
  explicit PoseIntegrator(const Pose2D& start = Pose2D()) : pose_(start) {}
  void reset(const Pose2D& start = Pose2D()) { pose_ = start; distance_ = 0.0; rotation_ = 0.0; }
  void add(const Pose2D& delta);
  const Pose2D& pose() const { return pose_; }
  /// Path length of base_link (sum of chord lengths, m).
  double distance() const { return distance_; }
  /// Total absolute rotation (rad).
  double rotation() const { return rotation_; }

 private:
  Pose2D pose_;
  double distance_ = 0.0;
  double rotation_ = 0.0;
};

}  // namespace mrt::mice
