// Geometry and resolution of the two-mouse dead-reckoning sensor (manual
// ch. 4), ROS-free.
#pragma once

#include <cstdint>
#include <string>

#include "mrt_common/pose2d.h"

namespace mrt::mice {

using mrt::common::Point2D;
using mrt::common::Pose2D;

/// One optical mouse under the body: where it is and how it counts.
struct MouseParams {
  /// Pose of the mouse frame in base_link (x forward along the mouse's
  /// longitudinal axis, y to its left), metres and radians.
  Pose2D mount;
  /// Resolution on the floor it runs on, counts per metre (400 cpi = 15748).
  double counts_per_m = 15748.0;
};

/// Everything the core needs to turn raw counts into body motion and to
/// decide whether a sample is erroneous. Loaded once, validated, never
/// re-read.
struct MiceParams {
  MouseParams left;
  MouseParams right;
  /// A sample is flagged when |residual| > detection_factor * quantisation
  /// bound + detection_relative * mean path length of the two mice.
  double detection_factor = 1.0;
  double detection_relative = 0.0;

  /// Throws std::invalid_argument naming the offending parameter.
  void validate() const;
  /// Distance D between the two mice (m).
  double distance() const;
};

/// The manual's parameters of §4.2, derived from a general placement:
/// D, the mouse orientations sigma_r and sigma_l with respect to the robot
/// heading, and delta, the angle between the robot heading and the normal
/// to the joining line (the normal pointing forward-ish, i.e. the joining
/// line turned by -90 degrees when it runs from the right to the left mouse).
struct ManualGeometry {
  double D = 0.0;
  double sigma_l = 0.0;
  double sigma_r = 0.0;
  double delta = 0.0;
};

ManualGeometry manual_geometry(const MiceParams& p);

/// The manual's Fig. 4.1 placement: mice at (0, +-D/2), parallel, their x
/// axes along the joining line (pointing to the robot's right, yaw -90
/// degrees) so that the x readings of the two mice must agree and the
/// robot heading is the mice's y axis.
MiceParams manual_placement(double D, double counts_per_m);

/// Integer counts of one sample of the two mice, each in its own frame.
struct MiceCounts {
  std::int64_t left_dx = 0, left_dy = 0, right_dx = 0, right_dy = 0;
};

}  // namespace mrt::mice
