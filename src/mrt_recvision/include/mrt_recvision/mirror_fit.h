// Mirror calibration (ROS-free): fits the radial profile r(theta) of the
// camera from field marks at known floor distances (e.g. the centres of
// white lines seen along a ray while the robot stands at a known place),
// and reports the residuals in pixels and metres.
#pragma once

#include <vector>

#include "mrt_common/omni_camera.h"
#include "mrt_recvision/color_table.h"
#include "mrt_recvision/frame.h"

namespace mrt::recvision {

/// One mark: seen at image radius `radius` (px), known to lie `distance`
/// (m) from the point under the viewpoint.
struct MirrorMark {
  double radius = 0;
  double distance = 0;
};

struct MirrorFit {
  mrt::common::MirrorProfile profile;  // sampled fitted polynomial, a `table` mirror
  std::vector<double> coefficients;    // r = c1 theta + c2 theta^2 + ... (px)
  std::vector<double> residual_px;     // measured radius - fitted radius, per mark
  std::vector<double> residual_m;      // known distance - distance of the measured radius, per mark
  double rms_px = 0, rms_m = 0;
};

/// Least-squares fit of r(theta) = sum_k c_k theta^k, k = 1..degree (through
/// the centre), theta = atan(distance / height), sampled on [0, theta_max].
/// Throws std::invalid_argument with fewer marks than `degree` or when the
/// fitted profile is not increasing on [0, theta_max].
MirrorFit fit_mirror(const std::vector<MirrorMark>& marks, double height, double theta_max, int degree = 3);

/// Image radii (px, sub-pixel: the middle of the run) of the white runs
/// with green on both sides along the ray from (cx, cy) at `bearing` (rad,
/// image convention of omni_camera.h), between radii r_min and r_max.
std::vector<double> white_runs_along_ray(const Frame& f, const ColorTable& t, double cx, double cy, double bearing,
                                         double r_min, double r_max);

}  // namespace mrt::recvision
