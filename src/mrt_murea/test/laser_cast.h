// Ray casting in a world file for the laser tests and murea_bench's laser
// runs (ROS-free): the world's walls and goal walls (solid_segments) and
// its posts as circles, as a laser sees them. Test code, written
// independently of MUREA's map code, from the world file as it is (not
// the occupancy grid MUREA localizes in).
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mrt_common/pose2d.h"
#include "mrt_world/occupancy_map.h"
#include "mrt_world/world.h"

namespace mrt::murea::test {

using mrt::common::Pose2D;

class LaserCaster {
 public:
  explicit LaserCaster(const std::string& world_file)
      : world_(mrt::world::load_map_world(world_file)), segments_(mrt::world::solid_segments(world_)) {}

  // The first hit of the ray from `o` along `angle` (m), or +inf.
  double cast(const Pose2D& o, double angle) const {
    const double dx = std::cos(angle), dy = std::sin(angle);
    double best = INFINITY;
    for (const auto& s : segments_) {
      // o + t d = a + u (b - a), t >= 0, 0 <= u <= 1 (Cramer's rule).
      const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y, den = dx * (-ey) - dy * (-ex);
      if (std::abs(den) < 1e-12) continue;
      const double rx = s.a.x - o.x, ry = s.a.y - o.y;
      const double t = (rx * (-ey) - ry * (-ex)) / den, u = (dx * ry - dy * rx) / den;
      if (t >= 0 && u >= 0 && u <= 1) best = std::min(best, t);
    }
    for (const auto& p : world_.posts) {
      // |o + t d - c|^2 = r^2: t^2 + 2 b t + c = 0.
      const double fx = o.x - p.center.x, fy = o.y - p.center.y;
      const double b = fx * dx + fy * dy, c = fx * fx + fy * fy - p.radius * p.radius, disc = b * b - c;
      if (disc < 0) continue;
      const double t = -b - std::sqrt(disc);
      if (t >= 0) best = std::min(best, t);
    }
    return best;
  }

  // n beams from angle_min by increment (in the laser's frame at `laser`),
  // Gaussian noise of sd `noise` on each hit; +inf beyond range_max.
  std::vector<float> ranges(const Pose2D& laser, int n, double angle_min, double increment, double range_max,
                            double noise, std::mt19937& rng) const {
    std::normal_distribution<double> nd(0.0, noise);
    std::vector<float> out;
    for (int i = 0; i < n; ++i) {
      const double r = cast(laser, laser.theta + angle_min + i * increment);
      out.push_back(std::isfinite(r) && r < range_max ? static_cast<float>(r + nd(rng)) : INFINITY);
    }
    return out;
  }

  // Distance from p to the nearest wall or post surface.
  double clearance(const mrt::common::Point2D& p) const {
    double d = INFINITY;
    for (const auto& s : segments_) d = std::min(d, mrt::world::distance_to_segment(p, s));
    for (const auto& q : world_.posts) d = std::min(d, std::hypot(p.x - q.center.x, p.y - q.center.y) - q.radius);
    return d;
  }

  const mrt::world::World& world() const { return world_; }

 private:
  mrt::world::World world_;
  std::vector<mrt::world::Segment> segments_;
};

// The odometry of a robot whose true motion is known: each true increment
// scaled by (1 + scale_error) in translation and turned by
// heading_drift rad per metre travelled, integrated from (0, 0, 0).
class DriftingOdometry {
 public:
  DriftingOdometry(const Pose2D& start, double scale_error, double heading_drift)
      : last_truth_(start), scale_(1.0 + scale_error), drift_(heading_drift) {}
  const Pose2D& update(const Pose2D& truth) {
    const Pose2D d = last_truth_.inverse() * truth;
    const double dist = std::hypot(d.x, d.y);
    odom_ = odom_ * Pose2D(scale_ * d.x, scale_ * d.y, d.theta + drift_ * dist);
    last_truth_ = truth;
    return odom_;
  }
  const Pose2D& odom() const { return odom_; }

 private:
  Pose2D last_truth_, odom_;
  double scale_, drift_;
};

// The path of the laser tests: an ellipse in the museum's south-west room
// (centre (6.2, 3), half-axes 2.5 m and 1.8 m), driven counter-clockwise
// at 0.25 rad/s of the ellipse's parameter (0.45 to 0.63 m/s), heading
// along the tangent.
inline Pose2D ellipse_pose(double t) {
  const double phi = 0.25 * t, cx = 6.2, cy = 3.0, rx = 2.5, ry = 1.8;
  return Pose2D(cx + rx * std::cos(phi), cy + ry * std::sin(phi), std::atan2(ry * std::cos(phi), -rx * std::sin(phi)));
}

}  // namespace mrt::murea::test
