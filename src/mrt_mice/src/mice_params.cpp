#include "mrt_mice/mice_params.h"

#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::mice {

namespace {
void check_mouse(const MouseParams& m, const std::string& name) {
  if (!std::isfinite(m.mount.x) || !std::isfinite(m.mount.y) || !std::isfinite(m.mount.theta))
    throw std::invalid_argument(name + ": mount must be finite");
  if (!(m.counts_per_m > 0.0) || !std::isfinite(m.counts_per_m))
    throw std::invalid_argument(name + ".counts_per_m: must be a positive number, got " +
                                std::to_string(m.counts_per_m));
}
}  // namespace

void MiceParams::validate() const {
  check_mouse(left, "left");
  check_mouse(right, "right");
  if (!(distance() > 1e-3))
    throw std::invalid_argument("left/right: the two mice must be at least 1 mm apart, got " +
                                std::to_string(distance()) + " m");
  if (!(detection_factor > 0.0) || !std::isfinite(detection_factor))
    throw std::invalid_argument("detection_factor: must be positive");
  if (!(detection_relative >= 0.0) || !std::isfinite(detection_relative))
    throw std::invalid_argument("detection_relative: must be >= 0");
}

double MiceParams::distance() const {
  return std::hypot(right.mount.x - left.mount.x, right.mount.y - left.mount.y);
}

ManualGeometry manual_geometry(const MiceParams& p) {
  ManualGeometry g;
  const double ex = p.left.mount.x - p.right.mount.x, ey = p.left.mount.y - p.right.mount.y;
  g.D = std::hypot(ex, ey);
  g.sigma_l = p.left.mount.theta;
  g.sigma_r = p.right.mount.theta;
  // Normal to the joining line (right -> left turned by -90 deg): for the
  // symmetric placement it is the robot's +x axis, so delta = 0.
  const double nx = ey, ny = -ex;
  g.delta = mrt::common::normalize_angle(std::atan2(ny, nx));
  return g;
}

MiceParams manual_placement(double D, double counts_per_m) {
  MiceParams p;
  const double yaw = -mrt::common::kPi / 2.0;
  p.left.mount = Pose2D(0.0, D / 2.0, yaw);
  p.right.mount = Pose2D(0.0, -D / 2.0, yaw);
  p.left.counts_per_m = p.right.counts_per_m = counts_per_m;
  return p;
}

}  // namespace mrt::mice
