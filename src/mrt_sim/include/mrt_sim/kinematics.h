// Kinematics of the MRT robot bases (ROS-free). The geometry type
// (mrt::common::BaseGeometry), the math and the preset numbers live once in
// mrt_common/base_kinematics.h, shared with mrt_airboard; BaseConfig adds
// the name, the motor limit and the footprint the simulator needs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_common/base_kinematics.h"

namespace mrt::sim {

/// Body-frame velocity: vx forward, vy left (m/s), omega counter-clockwise (rad/s).
using Twist2D = mrt::common::Twist2D;

using BaseType = mrt::common::BaseType;

using BaseGeometry = mrt::common::BaseGeometry;

/// A simulated base: its geometry (type, wheel_radius, track,
/// wheel_distance, wheel_angles: the one geometry type of the stack) and
/// what the simulator adds. Presets (see base_preset() and
/// mrt::common::base_presets() for the numbers): "ianus3", "p3at"
/// (differential), "triskar", "omni4" (omni). Omni wheel i sits at angle
/// wheel_angles[i] from the body x axis, at distance `wheel_distance` (the
/// world file's `omni_radius`); it drives along (-sin a, cos a), so its
/// surface speed is v_i = -sin(a) vx + cos(a) vy + wheel_distance * omega.
struct BaseConfig : BaseGeometry {
  std::string name;
  double max_wheel_speed = 24.0;  // rad/s, |w_i| is clamped to this
  double body_radius = 0.25;      // m, footprint circle for collisions, sonar, vision
};

/// Returns the named preset; throws std::invalid_argument for an unknown name.
BaseConfig base_preset(const std::string& name);

/// Wheel angular speeds (rad/s) realising a body twist. Differential bases
/// ignore vy. Order: differential [left, right]; omni as wheel_angles.
inline std::vector<double> twist_to_wheels(const BaseGeometry& g, const Twist2D& t) {
  return mrt::common::inverse(g, t);
}

/// Body twist produced by wheel angular speeds (rad/s); least squares for
/// more than three omni wheels. Throws std::invalid_argument on a size
/// mismatch or when the omni wheel angles do not determine the twist.
inline Twist2D wheels_to_twist(const BaseGeometry& g, const std::vector<double>& wheel_speeds) {
  return mrt::common::forward(g, wheel_speeds);
}

/// Scales the whole wheel-speed vector so that no wheel exceeds
/// g.max_wheel_speed, preserving the direction of motion. Returns the scale
/// applied (1 when nothing was saturated, or when max_wheel_speed <= 0).
inline double saturate_wheels(const BaseConfig& g, std::vector<double>& wheel_speeds) {
  return mrt::common::saturate_preserving_direction(wheel_speeds, g.max_wheel_speed);
}

}  // namespace mrt::sim
