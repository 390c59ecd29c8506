#include "mrt_sim/kinematics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mrt_common/angle.h"

namespace mrt::sim {

using mrt::common::deg_to_rad;

BaseGeometry base_preset(const std::string& name) {
  BaseGeometry g;
  g.name = name;
  if (name == "ianus3") {
    g.type = BaseType::kDifferential;
    g.wheel_radius = 0.05;
    g.track = 0.38;
    g.max_wheel_speed = 1.2 / 0.05;  // 24 rad/s
    g.body_radius = 0.25;
  } else if (name == "p3at") {
    g.type = BaseType::kDifferential;
    g.wheel_radius = 0.11;
    g.track = 0.40;
    g.max_wheel_speed = 1.2 / 0.11;
    g.body_radius = 0.33;
  } else if (name == "triskar") {
    g.type = BaseType::kOmni;
    g.wheel_radius = 0.04;
    g.omni_radius = 0.20;
    g.wheel_angles = {deg_to_rad(90), deg_to_rad(210), deg_to_rad(330)};
    g.max_wheel_speed = 40.0;  // 1.6 m/s surface speed
    g.body_radius = 0.25;
  } else if (name == "omni4") {
    g.type = BaseType::kOmni;
    g.wheel_radius = 0.04;
    g.omni_radius = 0.20;
    g.wheel_angles = {deg_to_rad(45), deg_to_rad(135), deg_to_rad(225), deg_to_rad(315)};
    g.max_wheel_speed = 40.0;
    g.body_radius = 0.25;
  } else {
    throw std::invalid_argument("unknown base preset '" + name +
                                "' (expected ianus3, p3at, triskar or omni4)");
  }
  return g;
}

std::vector<double> twist_to_wheels(const BaseGeometry& g, const Twist2D& t) {
  if (g.type == BaseType::kDifferential) {
    const double half = 0.5 * t.omega * g.track;
    return {(t.vx - half) / g.wheel_radius, (t.vx + half) / g.wheel_radius};
  }
  std::vector<double> w;
  w.reserve(g.wheel_angles.size());
  for (double a : g.wheel_angles)
    w.push_back((-std::sin(a) * t.vx + std::cos(a) * t.vy + g.omni_radius * t.omega) / g.wheel_radius);
  return w;
}

Twist2D wheels_to_twist(const BaseGeometry& g, const std::vector<double>& w) {
  if (w.size() != g.wheel_count())
    throw std::invalid_argument("wheels_to_twist: expected " + std::to_string(g.wheel_count()) +
                                " wheel speeds, got " + std::to_string(w.size()));
  Twist2D t;
  if (g.type == BaseType::kDifferential) {
    t.vx = 0.5 * g.wheel_radius * (w[0] + w[1]);
    t.omega = g.wheel_radius * (w[1] - w[0]) / g.track;
    return t;
  }
  // Least squares J t = v with rows J_i = (-sin a, cos a, L) and surface
  // speeds v_i = r w_i: solve the 3x3 normal equations (J^T J) t = J^T v by
  // Cramer's rule. Exact for three wheels, the pseudo-inverse for more.
  double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double b[3] = {0, 0, 0};
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double row[3] = {-std::sin(g.wheel_angles[i]), std::cos(g.wheel_angles[i]), g.omni_radius};
    const double v = g.wheel_radius * w[i];
    for (int r = 0; r < 3; ++r) {
      b[r] += row[r] * v;
      for (int c = 0; c < 3; ++c) m[r][c] += row[r] * row[c];
    }
  }
  auto det3 = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double d = det3(m);
  if (std::fabs(d) < 1e-12)
    throw std::invalid_argument("wheels_to_twist: the wheel angles of base '" + g.name +
                                "' do not determine the twist");
  double out[3];
  for (int k = 0; k < 3; ++k) {
    double mk[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) mk[r][c] = c == k ? b[r] : m[r][c];
    out[k] = det3(mk) / d;
  }
  t.vx = out[0];
  t.vy = out[1];
  t.omega = out[2];
  return t;
}

double saturate_wheels(const BaseGeometry& g, std::vector<double>& w) {
  double peak = 0.0;
  for (double v : w) peak = std::max(peak, std::fabs(v));
  if (peak <= g.max_wheel_speed || peak == 0.0) return 1.0;
  const double scale = g.max_wheel_speed / peak;
  for (double& v : w) v *= scale;
  return scale;
}

}  // namespace mrt::sim
