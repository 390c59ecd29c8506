// Kinematics of the MRT robot bases (ROS-free). The math and the preset
// numbers live once in mrt_common/base_kinematics.h; this header keeps the
// simulator's API: BaseGeometry adds the name, the motor limit and the
// footprint the simulator needs.
#pragma once

#include <string>
#include <vector>

#include "mrt_common/base_kinematics.h"

namespace mrt::sim {

/// Body-frame velocity: vx forward, vy left (m/s), omega counter-clockwise (rad/s).
using Twist2D = mrt::common::Twist2D;

using BaseType = mrt::common::BaseType;

/// Geometry of a base. Presets (see base_preset() and
/// mrt::common::base_presets() for the numbers): "ianus3", "p3at"
/// (differential), "triskar", "omni4" (omni).
/// Omni wheel i sits at angle wheel_angles[i] from the body x axis, at
/// distance `omni_radius`; it drives along the perpendicular direction
/// (-sin a, cos a) (counter-clockwise about the centre), so its surface
/// speed is v_i = -sin(a) vx + cos(a) vy + omni_radius * omega.
struct BaseGeometry {
  std::string name;
  BaseType type = BaseType::kDifferential;
  double wheel_radius = 0.05;        // m
  double track = 0.38;               // differential: distance between wheels, m
  double omni_radius = 0.20;         // omni: wheel distance from centre, m
  std::vector<double> wheel_angles;  // omni: rad
  double max_wheel_speed = 24.0;     // rad/s, |w_i| is clamped to this
  double body_radius = 0.25;         // m, footprint circle for collisions, sonar, vision

  std::size_t wheel_count() const { return type == BaseType::kDifferential ? 2 : wheel_angles.size(); }
};

/// Returns the named preset; throws std::invalid_argument for an unknown name.
BaseGeometry base_preset(const std::string& name);

/// Wheel angular speeds (rad/s) realising a body twist. Differential bases
/// ignore vy. Order: differential [left, right]; omni as wheel_angles.
inline std::vector<double> twist_to_wheels(const BaseGeometry& g, const Twist2D& t) {
  return g.type == BaseType::kDifferential
             ? mrt::common::differential_inverse(g.wheel_radius, g.track, t)
             : mrt::common::omni_inverse(g.wheel_radius, g.omni_radius, g.wheel_angles, t);
}

/// Body twist produced by wheel angular speeds (rad/s); least squares for
/// more than three omni wheels. Throws std::invalid_argument on a size
/// mismatch or when the omni wheel angles do not determine the twist.
inline Twist2D wheels_to_twist(const BaseGeometry& g, const std::vector<double>& wheel_speeds) {
  return g.type == BaseType::kDifferential
             ? mrt::common::differential_forward(g.wheel_radius, g.track, wheel_speeds)
             : mrt::common::omni_forward(g.wheel_radius, g.omni_radius, g.wheel_angles, wheel_speeds);
}

/// Scales the whole wheel-speed vector so that no wheel exceeds
/// g.max_wheel_speed, preserving the direction of motion. Returns the scale
/// applied (1 when nothing was saturated, or when max_wheel_speed <= 0).
inline double saturate_wheels(const BaseGeometry& g, std::vector<double>& wheel_speeds) {
  return mrt::common::saturate_preserving_direction(wheel_speeds, g.max_wheel_speed);
}

}  // namespace mrt::sim
