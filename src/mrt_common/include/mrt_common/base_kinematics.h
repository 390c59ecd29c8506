// Kinematics of the MRT robot bases, shared by mrt_sim (the simulated robot)
// and mrt_airboard (the motor board's processing sub-module, manual chapter
// 5, section 2.1). ROS-free, header-only.
//
// Conventions (REP-103): body twist vx forward, vy left (m/s), omega
// counter-clockwise (rad/s); wheel speeds are angular speeds in rad/s.
//  - Differential, wheels [left, right], `track` apart; positive wheel speed
//    drives the robot forward: w = (vx -+ omega * track / 2) / r. vy is
//    ignored (the base cannot move sideways).
//  - Omni: wheel i sits at angle a_i (rad, from the body x axis) at
//    `wheel_distance` L from the centre and drives along (-sin a_i, cos a_i)
//    (counter-clockwise about the centre):
//    w_i = (-sin a_i vx + cos a_i vy + L omega) / r.
//    The forward kinematics is the least-squares solution (exact for three
//    wheels, the pseudo-inverse for four).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "mrt_common/angle.h"

namespace mrt::common {

/// Body-frame velocity: vx forward, vy left (m/s), omega counter-clockwise (rad/s).
struct Twist2D {
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;
};

enum class BaseType { kDifferential, kOmni };

/// The kinematic geometry of a base (defaults: IANUS3).
struct BaseGeometry {
  BaseType type = BaseType::kDifferential;
  double wheel_radius = 0.05;        // m
  double track = 0.38;               // m, differential: distance between the wheels
  double wheel_distance = 0.20;      // m, omni: wheel distance from the centre
  std::vector<double> wheel_angles;  // rad, omni: wheel positions, order = motor order

  std::size_t wheel_count() const {
    return type == BaseType::kDifferential ? 2 : wheel_angles.size();
  }
};

// ---------------------------------------------------------------- inverse

/// Wheel speeds [left, right] (rad/s) of a differential base realising `t`
/// (vy ignored).
inline std::vector<double> differential_inverse(double wheel_radius, double track, const Twist2D& t) {
  const double half = 0.5 * t.omega * track;
  return {(t.vx - half) / wheel_radius, (t.vx + half) / wheel_radius};
}

/// Wheel speeds (rad/s) of an omni base realising `t`, in the order of `wheel_angles`.
inline std::vector<double> omni_inverse(double wheel_radius, double wheel_distance,
                                        const std::vector<double>& wheel_angles, const Twist2D& t) {
  std::vector<double> w;
  w.reserve(wheel_angles.size());
  for (double a : wheel_angles)
    w.push_back((-std::sin(a) * t.vx + std::cos(a) * t.vy + wheel_distance * t.omega) / wheel_radius);
  return w;
}

inline std::vector<double> inverse(const BaseGeometry& g, const Twist2D& t) {
  return g.type == BaseType::kDifferential
             ? differential_inverse(g.wheel_radius, g.track, t)
             : omni_inverse(g.wheel_radius, g.wheel_distance, g.wheel_angles, t);
}

// ---------------------------------------------------------------- forward

namespace detail {

inline void require_wheel_count(std::size_t want, std::size_t got) {
  if (got != want)
    throw std::invalid_argument("forward kinematics: expected " + std::to_string(want) +
                                " wheel speeds, got " + std::to_string(got));
}

/// The design matrix J of an omni base, one row (-sin a_i, cos a_i, L) per
/// wheel: J t = r w for a body twist t = (vx, vy, omega).
inline Eigen::MatrixX3d omni_jacobian(double wheel_distance, const std::vector<double>& wheel_angles) {
  Eigen::MatrixX3d j(static_cast<Eigen::Index>(wheel_angles.size()), 3);
  for (std::size_t i = 0; i < wheel_angles.size(); ++i)
    j.row(static_cast<Eigen::Index>(i)) << -std::sin(wheel_angles[i]), std::cos(wheel_angles[i]), wheel_distance;
  return j;
}

/// Inverse of the 3x3 normal matrix J^T J of an omni base. Throws
/// std::invalid_argument when the wheel directions do not span the plane
/// (fewer than three wheels, or all wheels on one line through the centre):
/// |det| not above 1e-9 times the product of the diagonal (at least 1).
inline Eigen::Matrix3d omni_normal_inverse(double wheel_distance, const std::vector<double>& wheel_angles) {
  const Eigen::MatrixX3d j = omni_jacobian(wheel_distance, wheel_angles);
  const Eigen::Matrix3d m = j.transpose() * j;
  const double scale = m(0, 0) * m(1, 1) * m(2, 2);
  Eigen::Matrix3d inv;
  double det = 0.0;
  bool invertible = false;
  m.computeInverseAndDetWithCheck(inv, det, invertible, 1e-9 * std::max(1.0, std::fabs(scale)));
  if (!invertible) throw std::invalid_argument("wheel_angles: the omni wheel directions do not span the plane");
  return inv;
}

}  // namespace detail

/// Body twist of a differential base from its wheel speeds [left, right]
/// (rad/s). Throws std::invalid_argument unless there are two.
inline Twist2D differential_forward(double wheel_radius, double track, const std::vector<double>& w) {
  detail::require_wheel_count(2, w.size());
  Twist2D t;
  t.vx = 0.5 * wheel_radius * (w[0] + w[1]);
  t.omega = wheel_radius * (w[1] - w[0]) / track;
  return t;
}

/// Whether omni wheels at `wheel_angles`, `wheel_distance` from the centre,
/// determine the body twist (at least three wheels whose directions span the plane).
inline bool omni_spans_plane(double wheel_distance, const std::vector<double>& wheel_angles) {
  try {
    detail::omni_normal_inverse(wheel_distance, wheel_angles);
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

/// Body twist of an omni base from its wheel speeds (rad/s): the least-squares
/// solution of J t = r w, i.e. t = (J^T J)^-1 J^T r w (exact for three wheels).
/// Throws std::invalid_argument on a size mismatch or when the wheel
/// directions do not span the plane.
inline Twist2D omni_forward(double wheel_radius, double wheel_distance,
                            const std::vector<double>& wheel_angles, const std::vector<double>& w) {
  detail::require_wheel_count(wheel_angles.size(), w.size());
  const Eigen::VectorXd rw = wheel_radius * Eigen::Map<const Eigen::VectorXd>(w.data(), static_cast<Eigen::Index>(w.size()));
  const Eigen::Vector3d t = detail::omni_normal_inverse(wheel_distance, wheel_angles) *
                            (detail::omni_jacobian(wheel_distance, wheel_angles).transpose() * rw);
  return Twist2D{t(0), t(1), t(2)};
}

/// Body twist from wheel speeds (rad/s), least squares for more than three
/// omni wheels. Throws std::invalid_argument on a size mismatch or a
/// degenerate omni geometry.
inline Twist2D forward(const BaseGeometry& g, const std::vector<double>& w) {
  return g.type == BaseType::kDifferential
             ? differential_forward(g.wheel_radius, g.track, w)
             : omni_forward(g.wheel_radius, g.wheel_distance, g.wheel_angles, w);
}

// ---------------------------------------------------------------- saturation

/// Scales the whole vector so that no |w_i| exceeds `max_abs`, keeping the
/// direction of motion (and, for the wheel speeds of a base, the curvature).
/// `max_abs` <= 0 (or NaN) means no limit. Returns the scale applied (1 when
/// nothing changed).
inline double saturate_preserving_direction(std::vector<double>& w, double max_abs) {
  if (!(max_abs > 0.0)) return 1.0;
  double peak = 0.0;
  for (double v : w) peak = std::max(peak, std::fabs(v));
  if (peak <= max_abs) return 1.0;
  const double s = max_abs / peak;
  for (double& v : w) v *= s;
  return s;
}

// ---------------------------------------------------------------- presets

/// A robot base of the manual: its geometry and the physical numbers both
/// the simulator and the motor board need. The one source of these numbers.
struct BasePreset {
  std::string name;
  BaseGeometry geometry;
  double max_wheel_speed;  // rad/s, motor limit
  double body_radius;      // m, footprint circle
};

/// The presets:
///  - "ianus3":  differential, two central wheels [left, right], r 0.05 m,
///               track 0.38 m, max 24 rad/s (1.2 m/s), footprint 0.25 m.
///  - "p3at":    differential (skid steer treated as differential),
///               r 0.11 m, track 0.40 m, max 1.2 m/s, footprint 0.33 m.
///  - "triskar": omni, three wheels at 90, 210, 330 deg, 0.20 m from the
///               centre, r 0.04 m, max 40 rad/s (1.6 m/s), footprint 0.25 m.
///  - "omni4":   omni, four wheels at 45, 135, 225, 315 deg, 0.20 m,
///               r 0.04 m, max 40 rad/s, footprint 0.25 m.
inline const std::vector<BasePreset>& base_presets() {
  static const std::vector<BasePreset> presets = [] {
    std::vector<BasePreset> p;
    BaseGeometry g;
    g.type = BaseType::kDifferential;
    g.wheel_radius = 0.05;
    g.track = 0.38;
    p.push_back({"ianus3", g, 24.0, 0.25});  // 1.2 m/s
    g.wheel_radius = 0.11;
    g.track = 0.40;
    p.push_back({"p3at", g, 1.2 / 0.11, 0.33});
    g = BaseGeometry{};
    g.type = BaseType::kOmni;
    g.wheel_radius = 0.04;
    g.wheel_distance = 0.20;
    g.wheel_angles = {deg_to_rad(90), deg_to_rad(210), deg_to_rad(330)};
    p.push_back({"triskar", g, 40.0, 0.25});
    g.wheel_angles = {deg_to_rad(45), deg_to_rad(135), deg_to_rad(225), deg_to_rad(315)};
    p.push_back({"omni4", g, 40.0, 0.25});
    return p;
  }();
  return presets;
}

/// The named preset; throws std::invalid_argument for an unknown name.
inline const BasePreset& base_preset(const std::string& name) {
  const std::vector<BasePreset>& all = base_presets();
  std::string names;  // "a, b, c or d"
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].name == name) return all[i];
    names += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + all[i].name;
  }
  throw std::invalid_argument("unknown base preset '" + name + "' (expected " + names + ")");
}

/// Joint names of the wheels in the robot descriptions (mrt_description), in
/// the wheel order of mrt_msgs/WheelState: [left_wheel_joint,
/// right_wheel_joint] on a differential base, wheel_<i>_joint otherwise.
inline std::vector<std::string> wheel_joint_names(const BaseGeometry& g) {
  if (g.type == BaseType::kDifferential) return {"left_wheel_joint", "right_wheel_joint"};
  std::vector<std::string> names;
  for (std::size_t i = 0; i < g.wheel_count(); ++i) names.push_back("wheel_" + std::to_string(i) + "_joint");
  return names;
}

/// Wheel angle (rad) of a cumulative encoder count: 2 pi counts / counts_per_rev.
inline double encoder_angle(std::int64_t counts, double counts_per_rev) {
  return 2.0 * kPi * static_cast<double>(counts) / counts_per_rev;
}

}  // namespace mrt::common
