#include "mrt_map/kalman.h"

#include <cmath>
#include <limits>

namespace mrt::map {

Mat4 transition(const ClassDef& c, double dt) {
  Mat4 F = Mat4::Identity();
  if (c.motion == MotionModel::kConstantVelocity) {
    if (c.velocity_tau > 0.0) {  // integrated Ornstein-Uhlenbeck
      const double tau = c.velocity_tau, one_minus_a = -std::expm1(-dt / tau);
      F(0, 2) = F(1, 3) = tau * one_minus_a;
      F(2, 2) = F(3, 3) = 1.0 - one_minus_a;
    } else {
      F(0, 2) = dt;
      F(1, 3) = dt;
    }
  }
  return F;
}

Mat4 process_noise(const ClassDef& c, double dt, double accel_noise) {
  const double sa = accel_noise >= 0.0 ? accel_noise : c.accel_noise, q = sa * sa;
  Mat4 Q = Mat4::Zero();
  if (c.motion == MotionModel::kConstantVelocity) {
    double a = q * dt * dt * dt / 3.0, b = q * dt * dt / 2.0, d = q * dt;
    if (c.velocity_tau > 0.0) {
      // White acceleration through v' = -v/tau + w, integrated exactly over dt
      // (e = 1 - exp(-dt/tau)): q tau^2 (dt - 2 tau e + tau/2 (1 - (1-e)^2)),
      // q tau^2 / 2 e^2, q tau / 2 (1 - (1-e)^2).
      const double tau = c.velocity_tau, e = -std::expm1(-dt / tau), one_minus_a2 = e * (2.0 - e);
      a = q * tau * tau * (dt - 2.0 * tau * e + 0.5 * tau * one_minus_a2);
      b = 0.5 * q * tau * tau * e * e;
      d = 0.5 * q * tau * one_minus_a2;
    }
    Q(0, 0) = Q(1, 1) = a;
    Q(0, 2) = Q(2, 0) = Q(1, 3) = Q(3, 1) = b;
    Q(2, 2) = Q(3, 3) = d;
  } else {
    Q(0, 0) = Q(1, 1) = q * dt;
  }
  return Q;
}

Estimate initialize(const Observation& o, const ClassDef& c) {
  Estimate e;
  e.x << o.z, 0.0, 0.0;
  e.P.setZero();
  e.P.topLeftCorner<2, 2>() = o.R;
  const double sv = c.motion == MotionModel::kConstantVelocity ? c.init_speed_sigma : 1e-3;
  e.P(2, 2) = e.P(3, 3) = sv * sv;
  e.stamp = o.stamp;
  return e;
}

Estimate predict(const Estimate& e, const ClassDef& c, double t, double accel_noise) {
  if (!(t > e.stamp)) return e;
  const double dt = t - e.stamp;
  const Mat4 F = transition(c, dt);
  Estimate p;
  p.x = F * e.x;
  p.P = F * e.P * F.transpose() + process_noise(c, dt, accel_noise);
  p.stamp = t;
  return p;
}

double mahalanobis2(const Estimate& e, const Vec2& z, const Mat2& R) {
  const Vec2 y = z - e.x.head<2>();
  const Mat2 S = e.P.topLeftCorner<2, 2>() + R;
  // Closed-form 2x2 inverse (the association's inner loop).
  const double det = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
  if (!(det > 0.0)) return std::numeric_limits<double>::infinity();
  return (S(1, 1) * y.x() * y.x() - (S(0, 1) + S(1, 0)) * y.x() * y.y() + S(0, 0) * y.y() * y.y()) / det;
}

bool outside_gate(const Estimate& e, const Vec2& z, const Mat2& R, double gate) {
  // y'S^-1 y >= |y|^2 / lambda_max(S) >= |y|^2 / trace(S).
  return (z - e.x.head<2>()).squaredNorm() > gate * (e.P(0, 0) + e.P(1, 1) + R(0, 0) + R(1, 1));
}

void update(Estimate& e, const Vec2& z, const Mat2& R) {
  const Vec2 y = z - e.x.head<2>();
  const Mat2 S = e.P.topLeftCorner<2, 2>() + R;
  const Eigen::Matrix<double, 4, 2> PHt = e.P.leftCols<2>();
  const Eigen::Matrix<double, 4, 2> K = PHt * S.inverse();
  e.x += K * y;
  // Joseph form keeps P symmetric and positive.
  Eigen::Matrix<double, 4, 4> IKH = Mat4::Identity();
  IKH.leftCols<2>() -= K;
  e.P = IKH * e.P * IKH.transpose() + K * R * K.transpose();
}

void maneuver(Estimate& e, const ClassDef& c, double dt, const Mat2& R) {
  const double s2 = c.init_speed_sigma * c.init_speed_sigma;
  if (c.impulse_maneuver) {
    e.P.topLeftCorner<2, 2>() += dt * dt * s2 * Mat2::Identity();
    e.P.block<2, 2>(0, 2) += dt * s2 * Mat2::Identity();
    e.P.block<2, 2>(2, 0) += dt * s2 * Mat2::Identity();
    e.P.block<2, 2>(2, 2) += s2 * Mat2::Identity();
    return;
  }
  e.P.block<2, 2>(2, 2) = s2 * Mat2::Identity();
  e.P.block<2, 2>(0, 2).setZero();
  e.P.block<2, 2>(2, 0).setZero();
  e.P.topLeftCorner<2, 2>() += R;
}

void fuse_independent(Vec2& z, Mat2& R, const Vec2& z2, const Mat2& R2) {
  const Mat2 I1 = R.inverse(), I2 = R2.inverse();
  const Mat2 P = (I1 + I2).inverse();
  z = P * (I1 * z + I2 * z2);
  R = P;
}

Estimate covariance_intersection(const Estimate& a, const Estimate& b, double* omega) {
  // w from the position blocks alone (2x2, cheap): trace((w A^-1 + (1-w) B^-1)^-1).
  const Mat2 Ia2 = a.P.topLeftCorner<2, 2>().inverse(), Ib2 = b.P.topLeftCorner<2, 2>().inverse();
  auto cost = [&](double w) { return (w * Ia2 + (1.0 - w) * Ib2).inverse().trace(); };
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = cost(x1), f2 = cost(x2);
  for (int i = 0; i < 30; ++i) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = cost(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = cost(x2);
    }
  }
  double w = 0.5 * (lo + hi);
  // The ends (one estimate alone) are candidates too.
  if (cost(0.0) <= cost(w)) w = 0.0;
  if (cost(1.0) < cost(w)) w = 1.0;
  if (omega) *omega = w;
  const Mat4 Ia = a.P.inverse(), Ib = b.P.inverse();
  Estimate e;
  e.P = (w * Ia + (1.0 - w) * Ib).inverse();
  e.x = e.P * (w * Ia * a.x + (1.0 - w) * Ib * b.x);
  e.stamp = a.stamp;
  return e;
}

Ellipse principal_axes(const Mat2& C) {
  const double a = C(0, 0), d = C(1, 1), b = 0.5 * (C(0, 1) + C(1, 0));
  const double mean = 0.5 * (a + d), r = std::hypot(0.5 * (a - d), b);
  Ellipse e;
  e.major = std::max(0.0, mean + r);
  e.minor = std::max(0.0, mean - r);
  e.angle = 0.5 * std::atan2(2.0 * b, a - d);
  return e;
}

Estimate fuse_estimates(const Estimate& a, const Estimate& b) {
  const Mat4 Ia = a.P.inverse(), Ib = b.P.inverse();
  Estimate e;
  e.P = (Ia + Ib).inverse();
  e.x = e.P * (Ia * a.x + Ib * b.x);
  e.stamp = a.stamp;
  return e;
}

}  // namespace mrt::map
