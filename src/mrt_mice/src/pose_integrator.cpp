#include "mrt_mice/pose_integrator.h"

#include <cmath>

namespace mrt::mice {

Pose2D integrate_pose(const Pose2D& pose, const Pose2D& delta) {
  const double len = std::hypot(delta.x, delta.y);
  const double dir = len > 0.0 ? std::atan2(delta.y, delta.x) : 0.0;
  return Pose2D(pose.x + len * std::cos(pose.theta + dir), pose.y + len * std::sin(pose.theta + dir),
                pose.theta + delta.theta);
}

void PoseIntegrator::add(const Pose2D& delta) {
  pose_ = integrate_pose(pose_, delta);
  distance_ += std::hypot(delta.x, delta.y);
  rotation_ += std::fabs(delta.theta);
}

}  // namespace mrt::mice
