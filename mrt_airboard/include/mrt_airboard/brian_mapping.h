// Mapping from Mr. BRIAN command names (manual chapter 10) to a body twist.
// ROS-free.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mrt_airboard/kinematics.h"

namespace mrt::airboard {

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
  double speed_scale = 0.01;               // cm/s -> m/s
  double angle_scale = 0.017453292519943295;     // deg -> rad
  double rotation_scale = 0.017453292519943295;  // deg/s -> rad/s

  /// Defaults for a base: polar (SpeedModule, SpeedAngle, Rotation) for
  /// omni, unicycle (Speed, Jog) for differential.
  static BrianMappingParams for_base(BaseType t);
  /// Parses "polar" / "unicycle"; throws std::invalid_argument.
  static Mode parse_mode(const std::string& s);
  void validate() const;
};

class BrianMapping {
 public:
  explicit BrianMapping(BrianMappingParams p);
  /// Twist from one cycle's (name, value) commands; std::nullopt when a
  /// mapped command (speed, angle in polar mode, rotation) is NaN or
  /// infinite, so that the caller drops and counts the array.
  std::optional<Twist2D> to_twist(const std::vector<std::pair<std::string, double>>& commands) const;
  const BrianMappingParams& params() const { return p_; }

 private:
  BrianMappingParams p_;
};

}  // namespace mrt::airboard
