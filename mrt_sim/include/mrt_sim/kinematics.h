// Kinematics of the MRT robot bases (ROS-free).
#pragma once

#include <string>
#include <vector>

namespace mrt::sim {

/// Body-frame velocity: vx forward, vy left (m/s), omega counter-clockwise (rad/s).
struct Twist2D {
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;
};

enum class BaseType { kDifferential, kOmni };

/// Geometry of a base. Presets (see base_preset()):
///  - "ianus3":  differential, two central wheels [left, right], wheel radius
///               0.05 m, track 0.38 m, max wheel speed 24 rad/s (1.2 m/s).
///  - "p3at":    differential (skid steer treated as differential), wheel
///               radius 0.11 m, track 0.40 m, max 1.2 m/s.
///  - "triskar": omni, three wheels at 90, 210, 330 degrees, 0.20 m from the
///               centre, radius 0.04 m.
///  - "omni4":   omni, four wheels at 45, 135, 225, 315 degrees, 0.20 m,
///               radius 0.04 m.
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
std::vector<double> twist_to_wheels(const BaseGeometry& g, const Twist2D& t);

/// Body twist produced by wheel angular speeds (rad/s); least squares for
/// more than three omni wheels. Throws std::invalid_argument on a size mismatch.
Twist2D wheels_to_twist(const BaseGeometry& g, const std::vector<double>& wheel_speeds);

/// Scales the whole wheel-speed vector so that no wheel exceeds
/// g.max_wheel_speed, preserving the direction of motion. Returns the scale
/// applied (1 when nothing was saturated).
double saturate_wheels(const BaseGeometry& g, std::vector<double>& wheel_speeds);

}  // namespace mrt::sim
