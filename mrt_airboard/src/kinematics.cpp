#include "mrt_airboard/kinematics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::airboard {

using mrt::common::deg_to_rad;

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
  BaseParams p;
  p.name = name;
  if (name == "ianus3") {
    p.type = BaseType::kDifferential;
    p.wheel_radius = 0.05;
    p.track = 0.38;
    p.max_wheel_speed = 24.0;  // 1.2 m/s
  } else if (name == "triskar") {
    p.type = BaseType::kOmni;
    p.wheel_radius = 0.04;
    p.wheel_distance = 0.20;
    p.wheel_angles = {deg_to_rad(90), deg_to_rad(210), deg_to_rad(330)};
    p.max_wheel_speed = 40.0;
  } else if (name == "omni4") {
    p.type = BaseType::kOmni;
    p.wheel_radius = 0.04;
    p.wheel_distance = 0.20;
    p.wheel_angles = {deg_to_rad(45), deg_to_rad(135), deg_to_rad(225), deg_to_rad(315)};
    p.max_wheel_speed = 40.0;
  } else {
    throw std::invalid_argument("unknown base preset '" + name + "' (expected ianus3, triskar or omni4)");
  }
  return p;
}

// ---------------------------------------------------------------- differential

DifferentialKinematics::DifferentialKinematics(double wheel_radius, double track)
    : r_(wheel_radius), track_(track) {
  if (!finite_pos(r_) || !finite_pos(track_))
    throw std::invalid_argument("DifferentialKinematics: wheel radius and track must be > 0");
}

std::vector<double> DifferentialKinematics::inverse(const Twist2D& t) const {
  const double half = 0.5 * t.omega * track_;
  return {(t.vx - half) / r_, (t.vx + half) / r_};
}

Twist2D DifferentialKinematics::forward(const std::vector<double>& w) const {
  if (w.size() != 2)
    throw std::invalid_argument("DifferentialKinematics::forward: expected 2 wheel speeds, got " +
                                std::to_string(w.size()));
  Twist2D t;
  t.vx = 0.5 * r_ * (w[0] + w[1]);
  t.omega = r_ * (w[1] - w[0]) / track_;
  return t;
}

// ---------------------------------------------------------------- omni

OmniKinematics::OmniKinematics(double wheel_radius, double wheel_distance, std::vector<double> angles)
    : r_(wheel_radius), dist_(wheel_distance), angles_(std::move(angles)) {
  const std::size_t n = angles_.size();
  if (!finite_pos(r_) || !finite_pos(dist_) || n < 3)
    throw std::invalid_argument("OmniKinematics: needs radius > 0, distance > 0 and >= 3 wheels");
  // Jacobian rows (surface speed per unit twist): J_i = (-sin a, cos a, L).
  // pinv = (J^T J)^-1 J^T, with the 3x3 inverse by the adjugate.
  double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  std::vector<double> j(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    j[3 * i + 0] = -std::sin(angles_[i]);
    j[3 * i + 1] = std::cos(angles_[i]);
    j[3 * i + 2] = dist_;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[r][c] += j[3 * i + r] * j[3 * i + c];
  }
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  const double scale = m[0][0] * m[1][1] * m[2][2];
  if (!(std::fabs(det) > 1e-9 * std::max(1.0, std::fabs(scale))))
    throw std::invalid_argument(
        "base parameter 'wheel_angles': the omni wheel directions do not span the plane");
  double inv[3][3];
  inv[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
  inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  inv[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
  inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  inv[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
  inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
  inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  pinv_.assign(3 * n, 0.0);
  for (int r = 0; r < 3; ++r)
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) pinv_[r * n + i] += inv[r][k] * j[3 * i + k];
}

std::vector<double> OmniKinematics::inverse(const Twist2D& t) const {
  std::vector<double> w;
  w.reserve(angles_.size());
  for (double a : angles_)
    w.push_back((-std::sin(a) * t.vx + std::cos(a) * t.vy + dist_ * t.omega) / r_);
  return w;
}

Twist2D OmniKinematics::forward(const std::vector<double>& w) const {
  const std::size_t n = angles_.size();
  if (w.size() != n)
    throw std::invalid_argument("OmniKinematics::forward: expected " + std::to_string(n) +
                                " wheel speeds, got " + std::to_string(w.size()));
  double out[3] = {0, 0, 0};
  for (int r = 0; r < 3; ++r)
    for (std::size_t i = 0; i < n; ++i) out[r] += pinv_[r * n + i] * r_ * w[i];
  return Twist2D{out[0], out[1], out[2]};
}

std::unique_ptr<BaseKinematics> make_kinematics(const BaseParams& p) {
  if (p.type == BaseType::kDifferential)
    return std::make_unique<DifferentialKinematics>(p.wheel_radius, p.track);
  return std::make_unique<OmniKinematics>(p.wheel_radius, p.wheel_distance, p.wheel_angles);
}

// ---------------------------------------------------------------- limits

double saturate_preserving_direction(std::vector<double>& w, double max_abs) {
  if (!(max_abs > 0.0)) return 1.0;
  double peak = 0.0;
  for (double v : w) peak = std::max(peak, std::fabs(v));
  if (peak <= max_abs) return 1.0;
  const double s = max_abs / peak;
  for (double& v : w) v *= s;
  return s;
}

VelocityLimiter::VelocityLimiter(const BaseParams& p) : p_(p), kin_(make_kinematics(p)) {}

void VelocityLimiter::reset() { last_.clear(); }

VelocityLimiter::Result VelocityLimiter::update(const Twist2D& requested, double dt) {
  Twist2D t = requested;
  if (!std::isfinite(t.vx) || !std::isfinite(t.vy) || !std::isfinite(t.omega)) t = Twist2D{};
  if (!kin_->holonomic()) t.vy = 0.0;
  if (std::hypot(t.vx, t.vy) < p_.deadband_linear) t.vx = t.vy = 0.0;
  if (std::fabs(t.omega) < p_.deadband_angular) t.omega = 0.0;

  Result r;
  r.wheels = kin_->inverse(t);
  r.saturated = saturate_preserving_direction(r.wheels, p_.max_wheel_speed) < 1.0;

  if (last_.size() != r.wheels.size()) last_.assign(r.wheels.size(), 0.0);  // from rest
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
