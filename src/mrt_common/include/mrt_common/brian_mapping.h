// Mr. BRIAN's commands (manual chapter 10) as a body twist: how a rule base
// that speaks of Speed and Jog (differential bases) or SpeedModule,
// SpeedAngle and Rotation (omni bases) moves a base of base_kinematics.h.
// Shared by the AIRBoard driver (brian_commands), Roby's brian_cmd_vel_node
// and the in-process loops (Roby, FollowMe, RoboCup's Player). ROS-free,
// header-only.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mrt_common/base_kinematics.h"

namespace mrt::common {

/// How the rule base expresses motion.
///  - kPolar (omni bases): `speed` is the speed module (SpeedModule, cm/s in
///    the manual), `angle` the direction of motion in the body frame
///    (SpeedAngle, degrees, 0 = forward, counter-clockwise positive) and
///    `rotation` the turn rate.
///  - kUnicycle (differential bases): `speed` is the forward speed and
///    `rotation` the turn rate ("jog").
/// Each value is multiplied by its scale to reach SI units (defaults: cm/s ->
/// m/s, degrees -> rad, deg/s -> rad/s). Commands absent from an array count
/// as 0; unknown names are ignored; a non-finite value of a mapped command
/// invalidates the whole array (BrianMapping::to_twist returns nothing).
struct BrianMappingParams {
  enum class Mode { kPolar, kUnicycle } mode = Mode::kUnicycle;
  std::string speed_name = "Speed";
  std::string angle_name = "SpeedAngle";
  std::string rotation_name = "Jog";
  double speed_scale = 0.01;                     // cm/s -> m/s
  double angle_scale = 0.017453292519943295;     // deg -> rad
  double rotation_scale = 0.017453292519943295;  // deg/s -> rad/s

  /// Defaults for a base: polar (SpeedModule, SpeedAngle, Rotation) for
  /// omni, unicycle (Speed, Jog) for differential.
  static BrianMappingParams for_base(BaseType t) {
    BrianMappingParams p;
    if (t == BaseType::kOmni) {
      p.mode = Mode::kPolar;
      p.speed_name = "SpeedModule";
      p.angle_name = "SpeedAngle";
      p.rotation_name = "Rotation";
    }
    return p;
  }

  /// Parses "polar" / "unicycle"; throws std::invalid_argument.
  static Mode parse_mode(const std::string& s) {
    if (s == "polar") return Mode::kPolar;
    if (s == "unicycle") return Mode::kUnicycle;
    throw std::invalid_argument("brian parameter 'mode' must be 'polar' or 'unicycle', got '" + s + "'");
  }

  /// Throws std::invalid_argument naming the parameter (speed, angle,
  /// rotation, *_scale).
  void validate() const {
    if (speed_name.empty()) throw std::invalid_argument("brian parameter 'speed' must not be empty");
    if (rotation_name.empty()) throw std::invalid_argument("brian parameter 'rotation' must not be empty");
    if (mode == Mode::kPolar && angle_name.empty())
      throw std::invalid_argument("brian parameter 'angle' must not be empty in polar mode");
    for (double s : {speed_scale, angle_scale, rotation_scale})
      if (!std::isfinite(s)) throw std::invalid_argument("brian parameter '*_scale' must be finite");
  }
};

class BrianMapping {
 public:
  /// Throws std::invalid_argument (BrianMappingParams::validate).
  explicit BrianMapping(BrianMappingParams p) : p_(std::move(p)) { p_.validate(); }

  /// Twist from one cycle's (name, value) commands; std::nullopt when a
  /// mapped command (speed, angle in polar mode, rotation) is NaN or
  /// infinite, so that the caller drops and counts the array.
  std::optional<Twist2D> to_twist(const std::vector<std::pair<std::string, double>>& commands) const {
    const bool polar = p_.mode == BrianMappingParams::Mode::kPolar;
    double speed = 0.0, angle = 0.0, rot = 0.0;
    for (const auto& [name, value] : commands) {
      double* dst = nullptr;
      double scale = 0.0;
      if (name == p_.speed_name) {
        dst = &speed, scale = p_.speed_scale;
      } else if (polar && name == p_.angle_name) {
        dst = &angle, scale = p_.angle_scale;
      } else if (name == p_.rotation_name) {
        dst = &rot, scale = p_.rotation_scale;
      }
      if (!dst) continue;  // not ours
      *dst = value * scale;
      if (!std::isfinite(*dst)) return std::nullopt;  // NaN, inf, or overflow by the scale
    }
    Twist2D t;
    if (polar) {
      t.vx = speed * std::cos(angle);
      t.vy = speed * std::sin(angle);
    } else {
      t.vx = speed;
    }
    t.omega = rot;
    return t;
  }

  const BrianMappingParams& params() const { return p_; }

 private:
  BrianMappingParams p_;
};

}  // namespace mrt::common
