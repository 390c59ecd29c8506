#include "mrt_airboard/kinematics.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace mrt::airboard {

namespace {
void require(bool ok, const std::string& param, const std::string& what) {
  if (!ok) throw std::invalid_argument("base parameter '" + param + "' " + what);
}
bool finite_pos(double v) { return std::isfinite(v) && v > 0.0; }
bool finite_nonneg(double v) { return std::isfinite(v) && v >= 0.0; }
}  // namespace

void BaseParams::validate() const {
  require(finite_pos(wheel_radius), "wheel_radius", "must be > 0 (m)");
  require(finite_nonneg(max_wheel_speed), "max_wheel_speed", "must be >= 0 (rad/s, 0 = no limit)");
  require(finite_nonneg(max_wheel_accel), "max_wheel_accel", "must be >= 0 (rad/s^2, 0 = no limit)");
  require(finite_nonneg(deadband_linear), "deadband_linear", "must be >= 0 (m/s)");
  require(finite_nonneg(deadband_angular), "deadband_angular", "must be >= 0 (rad/s)");
  require(counts_per_rev > 0, "counts_per_rev", "must be > 0");
  if (type == BaseType::kDifferential) {
    require(finite_pos(track), "track", "must be > 0 (m)");
  } else {
    require(finite_pos(wheel_distance), "wheel_distance", "must be > 0 (m)");
    require(wheel_angles.size() >= 3 && wheel_angles.size() <= 4, "wheel_angles",
            "must list 3 or 4 angles (degrees in YAML)");
    for (double a : wheel_angles) require(std::isfinite(a), "wheel_angles", "must be finite");
    // The wheel directions must span the plane (checked by the kinematics).
    OmniKinematics check(wheel_radius, wheel_distance, wheel_angles);
  }
}

BaseType parse_base_type(const std::string& s) {
  if (s == "differential") return BaseType::kDifferential;
  if (s == "omni") return BaseType::kOmni;
  throw std::invalid_argument("base parameter 'type' must be 'differential' or 'omni', got '" + s + "'");
}

BaseParams base_preset(const std::string& name) {
  const mrt::common::BasePreset& preset = mrt::common::base_preset(name);
  BaseParams p;
  static_cast<BaseGeometry&>(p) = preset.geometry;
  p.name = preset.name;
  p.max_wheel_speed = preset.max_wheel_speed;
  return p;
}

// ---------------------------------------------------------------- differential

DifferentialKinematics::DifferentialKinematics(double wheel_radius, double track)
    : r_(wheel_radius), track_(track) {
  if (!finite_pos(r_) || !finite_pos(track_))
    throw std::invalid_argument("DifferentialKinematics: wheel radius and track must be > 0");
}

std::vector<double> DifferentialKinematics::inverse(const Twist2D& t) const {
  return mrt::common::differential_inverse(r_, track_, t);
}

Twist2D DifferentialKinematics::forward(const std::vector<double>& w) const {
  return mrt::common::differential_forward(r_, track_, w);
}

// ---------------------------------------------------------------- omni

OmniKinematics::OmniKinematics(double wheel_radius, double wheel_distance, std::vector<double> angles)
    : r_(wheel_radius), dist_(wheel_distance), angles_(std::move(angles)) {
  if (!finite_pos(r_) || !finite_pos(dist_) || angles_.size() < 3)
    throw std::invalid_argument("OmniKinematics: needs radius > 0, distance > 0 and >= 3 wheels");
  if (!mrt::common::omni_spans_plane(dist_, angles_))
    throw std::invalid_argument(
        "base parameter 'wheel_angles': the omni wheel directions do not span the plane");
}

std::vector<double> OmniKinematics::inverse(const Twist2D& t) const {
  return mrt::common::omni_inverse(r_, dist_, angles_, t);
}

Twist2D OmniKinematics::forward(const std::vector<double>& w) const {
  return mrt::common::omni_forward(r_, dist_, angles_, w);
}

std::unique_ptr<BaseKinematics> make_kinematics(const BaseParams& p) {
  if (p.type == BaseType::kDifferential)
    return std::make_unique<DifferentialKinematics>(p.wheel_radius, p.track);
  return std::make_unique<OmniKinematics>(p.wheel_radius, p.wheel_distance, p.wheel_angles);
}

// ---------------------------------------------------------------- limits

VelocityLimiter::VelocityLimiter(const BaseParams& p) : p_(p), kin_(make_kinematics(p)) {}

void VelocityLimiter::reset() {
  last_.clear();
  board_stopped_ = false;
}

void VelocityLimiter::set_board_stopped(bool stopped) {
  board_stopped_ = stopped;
  if (stopped) last_.clear();  // the board's set-points are 0
}

void VelocityLimiter::set_limits(double max_wheel_speed, double max_wheel_accel) {
  BaseParams p = p_;
  p.max_wheel_speed = max_wheel_speed;
  p.max_wheel_accel = max_wheel_accel;
  p.validate();
  p_ = std::move(p);
}

VelocityLimiter::Result VelocityLimiter::update(const Twist2D& requested, double dt) {
  Twist2D t = requested;
  if (!std::isfinite(t.vx) || !std::isfinite(t.vy) || !std::isfinite(t.omega)) t = Twist2D{};
  if (!kin_->holonomic()) t.vy = 0.0;
  if (std::hypot(t.vx, t.vy) < p_.deadband_linear) t.vx = t.vy = 0.0;
  if (std::fabs(t.omega) < p_.deadband_angular) t.omega = 0.0;

  Result r;
  r.wheels = kin_->inverse(t);
  r.saturated = saturate_preserving_direction(r.wheels, p_.max_wheel_speed) < 1.0;

  // From rest: at the start, after reset(), and while the board reports it
  // stopped the motors.
  if (board_stopped_ || last_.size() != r.wheels.size()) last_.assign(r.wheels.size(), 0.0);
  if (p_.max_wheel_accel > 0.0 && dt > 0.0) {
    std::vector<double> delta(r.wheels.size());
    for (std::size_t i = 0; i < delta.size(); ++i) delta[i] = r.wheels[i] - last_[i];
    if (saturate_preserving_direction(delta, p_.max_wheel_accel * dt) < 1.0) {
      r.accel_limited = true;
      for (std::size_t i = 0; i < delta.size(); ++i) r.wheels[i] = last_[i] + delta[i];
    }
  }
  last_ = r.wheels;
  return r;
}

}  // namespace mrt::airboard
