// SE(2) pose: a rigid transform of the plane (ROS-free, header-only).
#pragma once

#include <cmath>

#include "mrt_common/angle.h"

namespace mrt::common {

struct Point2D {
  double x = 0.0;
  double y = 0.0;
};

/// Pose of a frame B expressed in a frame A: maps points of B into A by
/// p_A = R(theta) p_B + (x, y). theta is kept in (-pi, pi].
struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;

  Pose2D() = default;
  Pose2D(double x_, double y_, double theta_) : x(x_), y(y_), theta(normalize_angle(theta_)) {}

  /// Composition: (A<-B) * (B<-C) = (A<-C).
  Pose2D operator*(const Pose2D& o) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return Pose2D(x + c * o.x - s * o.y, y + s * o.x + c * o.y, theta + o.theta);
  }

  /// Inverse: (A<-B)^-1 = (B<-A).
  Pose2D inverse() const {
    const double c = std::cos(theta), s = std::sin(theta);
    return Pose2D(-c * x - s * y, s * x - c * y, -theta);
  }

  /// Maps a point given in this pose's frame into the parent frame.
  Point2D transform(const Point2D& p) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {x + c * p.x - s * p.y, y + s * p.x + c * p.y};
  }

  /// Maps a point of the parent frame into this pose's frame.
  Point2D inverse_transform(const Point2D& p) const {
    const double c = std::cos(theta), s = std::sin(theta);
    const double dx = p.x - x, dy = p.y - y;
    return {c * dx + s * dy, -s * dx + c * dy};
  }
};

/// Pose reached by moving with a constant body twist (vx, vy, omega) for dt
/// seconds from the identity: the exact SE(2) exponential (an arc, or a
/// segment when omega is 0), not an Euler step.
inline Pose2D exp_twist(double vx, double vy, double omega, double dt) {
  const double th = omega * dt;
  double a, b;  // sin(th)/th and (1-cos(th))/th, by series near 0
  if (std::fabs(th) < 1e-6) {
    a = 1.0 - th * th / 6.0;
    b = th / 2.0 - th * th * th / 24.0;
  } else {
    a = std::sin(th) / th;
    b = (1.0 - std::cos(th)) / th;
  }
  return Pose2D((a * vx - b * vy) * dt, (b * vx + a * vy) * dt, th);
}

}  // namespace mrt::common
