#include "mrt_airboard/brian_mapping.h"

#include <cmath>
#include <stdexcept>

namespace mrt::airboard {

BrianMappingParams BrianMappingParams::for_base(BaseType t) {
  BrianMappingParams p;
  if (t == BaseType::kOmni) {
    p.mode = Mode::kPolar;
    p.speed_name = "SpeedModule";
    p.angle_name = "SpeedAngle";
    p.rotation_name = "Rotation";
  }
  return p;
}

BrianMappingParams::Mode BrianMappingParams::parse_mode(const std::string& s) {
  if (s == "polar") return Mode::kPolar;
  if (s == "unicycle") return Mode::kUnicycle;
  throw std::invalid_argument("brian parameter 'mode' must be 'polar' or 'unicycle', got '" + s + "'");
}

void BrianMappingParams::validate() const {
  if (speed_name.empty()) throw std::invalid_argument("brian parameter 'speed' must not be empty");
  if (rotation_name.empty()) throw std::invalid_argument("brian parameter 'rotation' must not be empty");
  if (mode == Mode::kPolar && angle_name.empty())
    throw std::invalid_argument("brian parameter 'angle' must not be empty in polar mode");
  for (double s : {speed_scale, angle_scale, rotation_scale})
    if (!std::isfinite(s)) throw std::invalid_argument("brian parameter '*_scale' must be finite");
}

BrianMapping::BrianMapping(BrianMappingParams p) : p_(std::move(p)) { p_.validate(); }

std::optional<Twist2D> BrianMapping::to_twist(const std::vector<std::pair<std::string, double>>& commands) const {
  double speed = 0.0, angle = 0.0, rot = 0.0;
  for (const auto& [name, value] : commands) {
    double* dst = nullptr;
    double scale = 0.0;
    if (name == p_.speed_name) dst = &speed, scale = p_.speed_scale;
    else if (p_.mode == BrianMappingParams::Mode::kPolar && name == p_.angle_name) dst = &angle, scale = p_.angle_scale;
    else if (name == p_.rotation_name) dst = &rot, scale = p_.rotation_scale;
    if (!dst) continue;  // not ours
    *dst = value * scale;
    if (!std::isfinite(*dst)) return std::nullopt;  // NaN, inf, or overflow by the scale
  }
  Twist2D t;
  if (p_.mode == BrianMappingParams::Mode::kPolar) {
    t.vx = speed * std::cos(angle);
    t.vy = speed * std::sin(angle);
  } else {
    t.vx = speed;
  }
  t.omega = rot;
  return t;
}

}  // namespace mrt::airboard
