// Sub-lattice accuracy (ROS-free): after the search has found the pose of
// most evidence (and thereby which map feature each percept matches), a
// robust Gauss-Newton least-squares fit of the pose to the matched
// percepts, optionally fused with a prior (odometry's prediction) -- an
// iterated EKF update with the percepts as measurements.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "mrt_murea/localizer.h"

namespace mrt::murea {

using Covariance3 = std::array<double, 9>;  // row-major x, y, theta

struct RefineOptions {
  bool enabled = true;
  int iterations = 6;                  // Gauss-Newton steps at most
  double sigma_range_base = 0.01;      // m: percept distance noise sd = base + per_metre * distance
  double sigma_range_per_metre = 0.02;
  double sigma_bearing = 0.01;         // rad: percept bearing noise sd
  double sigma_map = 0.01;             // m: feature position (line width, post radius)
  double huber = 2.0;                  // residuals beyond this many sd weigh less (Huber)
  double max_shift_xy = 0.3;           // m: a fit farther than this from the start is rejected
  double max_shift_theta = 0.17453292519943295;  // rad (10 deg)
};

struct Refined {
  Pose2D pose;
  Covariance3 covariance{};  // inverse of the normal equations' matrix (incl. the prior)
  std::size_t inliers = 0;   // percepts within their tolerance of a feature at the final pose
  bool ok = false;           // false: too few constraints, singular, or moved too far
};

/// Fits the pose, starting at `start`, to the percepts that lie within
/// their class tolerance (the search's) of a matching feature: a
/// field-line or wall point to the nearest segment (distance along its
/// normal), a goal or post to the nearest point of its class and colour
/// (both coordinates). Each residual is weighted by the percept's
/// reliability over the variance of its position along the residual
/// (distance and bearing noise rotated into the world, plus sigma_map).
/// With `prior` and `prior_covariance`, the prior's information is added
/// (an iterated Kalman update).
Refined refine(const Localizer& localizer, const std::vector<Percept>& percepts, const Pose2D& start,
               const Pose2D* prior, const Covariance3* prior_covariance, const RefineOptions& options);

}  // namespace mrt::murea
