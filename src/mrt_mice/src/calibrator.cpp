#include "mrt_mice/calibrator.h"

#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::mice {

namespace {
struct Vec {
  double x = 0.0, y = 0.0;
};
Vec rotate(const Vec& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
}  // namespace

CalibrationResult calibrate(const std::vector<CalibrationRun>& runs, const MiceParams& base) {
  CalibrationResult res;
  // Least squares of reading = k * amount over the runs of each kind:
  // k = sum(reading * amount) / sum(amount^2).
  Vec push_l, push_r, turn_l, turn_r;
  double push_w = 0.0, turn_w = 0.0;
  for (const auto& r : runs) {
    if (!std::isfinite(r.amount) || r.amount == 0.0)
      throw std::invalid_argument(r.source + ": run amount must be non-zero");
    const double a = r.amount;
    const Vec l{static_cast<double>(r.counts.left_dx), static_cast<double>(r.counts.left_dy)};
    const Vec rr{static_cast<double>(r.counts.right_dx), static_cast<double>(r.counts.right_dy)};
    if (r.kind == CalibrationRun::Kind::kPush) {
      push_l.x += l.x * a; push_l.y += l.y * a;
      push_r.x += rr.x * a; push_r.y += rr.y * a;
      push_w += a * a;
      ++res.pushes;
    } else {
      turn_l.x += l.x * a; turn_l.y += l.y * a;
      turn_r.x += rr.x * a; turn_r.y += rr.y * a;
      turn_w += a * a;
      ++res.turns;
    }
  }
  if (res.pushes == 0) throw std::invalid_argument("calibration needs at least one straight push");
  if (res.turns == 0) throw std::invalid_argument("calibration needs at least one turn in place");
  const Vec a_l{push_l.x / push_w, push_l.y / push_w}, a_r{push_r.x / push_w, push_r.y / push_w};
  const Vec b_l{turn_l.x / turn_w, turn_l.y / turn_w}, b_r{turn_r.x / turn_w, turn_r.y / turn_w};

  auto fit = [](const Vec& a, const Vec& b, const char* name) {
    MouseParams m;
    m.counts_per_m = std::hypot(a.x, a.y);
    if (!(m.counts_per_m > 0.0))
      throw std::invalid_argument(std::string(name) + " mouse read nothing during the pushes");
    const double phi = -std::atan2(a.y, a.x);
    // b = c R(-phi) J p  =>  J p = R(phi) b / c, J p = (-y, x).
    const Vec jp = rotate(b, phi);
    m.mount = Pose2D(jp.y / m.counts_per_m, -jp.x / m.counts_per_m, phi);
    return m;
  };
  res.params = base;
  res.params.left = fit(a_l, b_l, "left");
  res.params.right = fit(a_r, b_r, "right");
  res.params.validate();
  res.geometry = manual_geometry(res.params);

  // Residuals of every run against the fitted model.
  double ss = 0.0;
  int n = 0;
  for (const auto& r : runs) {
    const Vec kl = r.kind == CalibrationRun::Kind::kPush ? a_l : b_l;
    const Vec kr = r.kind == CalibrationRun::Kind::kPush ? a_r : b_r;
    RunResidual rr;
    rr.source = r.source;
    rr.kind = r.kind;
    rr.left = std::hypot(r.counts.left_dx - kl.x * r.amount, r.counts.left_dy - kl.y * r.amount);
    rr.right = std::hypot(r.counts.right_dx - kr.x * r.amount, r.counts.right_dy - kr.y * r.amount);
    ss += rr.left * rr.left + rr.right * rr.right;
    n += 2;
    res.residuals.push_back(rr);
  }
  res.rms_residual = std::sqrt(ss / n);
  return res;
}

}  // namespace mrt::mice
