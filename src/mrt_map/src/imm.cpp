#include "mrt_map/imm.h"

#include <algorithm>
#include <cmath>

#include "mrt_map/kalman.h"

namespace mrt::map {

namespace {
double accel(const ImmDef& d, const ClassDef& c, int j) {
  if (j == 0) return d.quiet_accel_noise;
  return d.kicked_accel_noise > 0.0 ? d.kicked_accel_noise : c.accel_noise;
}
}  // namespace

ImmState imm_start(const Estimate& e, const ImmDef& d) {
  ImmState s;
  s.model = {e, e};
  const double sum = d.p_quiet_to_kicked + d.p_kicked_to_quiet;
  s.mu[0] = sum > 0.0 ? d.p_kicked_to_quiet / sum : 0.5;
  s.mu[1] = 1.0 - s.mu[0];
  return s;
}

void imm_predict(ImmState& s, const ClassDef& c, double t) {
  if (!(t > s.model[0].stamp)) return;
  const ImmDef& d = c.imm;
  // p[i][j]: probability of mode j after mode i.
  const double p[2][2] = {{1.0 - d.p_quiet_to_kicked, d.p_quiet_to_kicked},
                          {d.p_kicked_to_quiet, 1.0 - d.p_kicked_to_quiet}};
  std::array<Estimate, 2> mixed;
  std::array<double, 2> cbar{};
  for (int j = 0; j < 2; ++j) {
    cbar[j] = p[0][j] * s.mu[0] + p[1][j] * s.mu[1];
    double w[2];
    for (int i = 0; i < 2; ++i) w[i] = cbar[j] > 0.0 ? p[i][j] * s.mu[i] / cbar[j] : 0.5;
    Estimate& m = mixed[j];
    m.stamp = s.model[0].stamp;
    m.x = w[0] * s.model[0].x + w[1] * s.model[1].x;
    m.P.setZero();
    for (int i = 0; i < 2; ++i) {
      const Vec4 dx = s.model[i].x - m.x;
      m.P += w[i] * (s.model[i].P + dx * dx.transpose());
    }
  }
  for (int j = 0; j < 2; ++j) s.model[j] = predict(mixed[j], c, t, accel(d, c, j));
  s.mu = cbar;
}

void imm_update(ImmState& s, const Vec2& z, const Mat2& R) {
  double logl[2];
  for (int j = 0; j < 2; ++j) {
    const Mat2 S = s.model[j].P.topLeftCorner<2, 2>() + R;
    const double det = S.determinant();
    const double d2 = mahalanobis2(s.model[j], z, R);
    logl[j] = det > 0.0 && std::isfinite(d2) ? -0.5 * d2 - 0.5 * std::log(det) : -INFINITY;
    update(s.model[j], z, R);
  }
  const double top = std::max(logl[0], logl[1]);
  if (!std::isfinite(top)) return;  // no information on the modes: keep mu
  double w[2], sum = 0.0;
  for (int j = 0; j < 2; ++j) sum += (w[j] = s.mu[j] * std::exp(logl[j] - top));
  if (!(sum > 0.0)) return;
  for (int j = 0; j < 2; ++j) s.mu[j] = w[j] / sum;
}

Estimate imm_combine(const ImmState& s) {
  Estimate e;
  e.stamp = s.model[0].stamp;
  e.x = s.mu[0] * s.model[0].x + s.mu[1] * s.model[1].x;
  e.P.setZero();
  for (int j = 0; j < 2; ++j) {
    const Vec4 dx = s.model[j].x - e.x;
    e.P += s.mu[j] * (s.model[j].P + dx * dx.transpose());
  }
  return e;
}

}  // namespace mrt::map
