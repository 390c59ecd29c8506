// Angle helpers shared by the MRT packages (ROS-free, header-only).
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

namespace mrt::common {

constexpr double kPi = 3.14159265358979323846;

inline double deg_to_rad(double deg) { return deg * kPi / 180.0; }
inline double rad_to_deg(double rad) { return rad * 180.0 / kPi; }

/// Wraps an angle to (-pi, pi].
inline double normalize_angle(double a) {
  double r = std::remainder(a, 2.0 * kPi);  // in [-pi, pi]
  if (r <= -kPi) r += 2.0 * kPi;
  return r;
}

/// Signed smallest difference a - b, in (-pi, pi].
inline double angle_diff(double a, double b) { return normalize_angle(a - b); }

/// Weighted circular mean atan2(sum w sin, sum w cos), in (-pi, pi].
/// Throws std::invalid_argument when the sizes differ, when the weights do
/// not sum to a positive number, or when the mean is undefined (the weighted
/// unit vectors cancel out).
inline double circular_mean(const std::vector<double>& angles,
                            const std::vector<double>& weights) {
  if (angles.size() != weights.size())
    throw std::invalid_argument("circular_mean: angles and weights differ in size");
  double s = 0.0, c = 0.0, wsum = 0.0;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    s += weights[i] * std::sin(angles[i]);
    c += weights[i] * std::cos(angles[i]);
    wsum += weights[i];
  }
  if (!(wsum > 0.0)) throw std::invalid_argument("circular_mean: weights must sum to > 0");
  if (std::hypot(s, c) <= 1e-12 * wsum)
    throw std::invalid_argument("circular_mean: undefined, the angles cancel out");
  return normalize_angle(std::atan2(s, c));
}

inline double circular_mean(const std::vector<double>& angles) {
  return circular_mean(angles, std::vector<double>(angles.size(), 1.0));
}

}  // namespace mrt::common
