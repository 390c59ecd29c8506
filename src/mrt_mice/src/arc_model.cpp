#include "mrt_mice/arc_model.h"

#include <cmath>

namespace mrt::mice {

namespace {
Point2D rotate(const Point2D& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
double dot(const Point2D& a, const Point2D& b) { return a.x * b.x + a.y * b.y; }
}  // namespace

ArcModel::ArcModel(const MiceParams& params) : params_(params) {
  params_.validate();
  d_ = {params_.right.mount.x - params_.left.mount.x, params_.right.mount.y - params_.left.mount.y};
  D_ = std::hypot(d_.x, d_.y);
  e_ = {d_.x / D_, d_.y / D_};
  mid_ = {(params_.right.mount.x + params_.left.mount.x) / 2.0,
          (params_.right.mount.y + params_.left.mount.y) / 2.0};
}

Point2D ArcModel::left_in_body(double dx, double dy) const {
  const double k = 1.0 / params_.left.counts_per_m;
  return rotate({dx * k, dy * k}, params_.left.mount.theta);
}

Point2D ArcModel::right_in_body(double dx, double dy) const {
  const double k = 1.0 / params_.right.counts_per_m;
  return rotate({dx * k, dy * k}, params_.right.mount.theta);
}

ArcSolution ArcModel::solve(const MiceCounts& c) const {
  return solve_body(left_in_body(static_cast<double>(c.left_dx), static_cast<double>(c.left_dy)),
                    right_in_body(static_cast<double>(c.right_dx), static_cast<double>(c.right_dy)));
}

ArcSolution ArcModel::solve_body(const Point2D& ul, const Point2D& ur) const {
  ArcSolution s;
  const Point2D diff{ur.x - ul.x, ur.y - ul.y};
  // J d = (-d.y, d.x): the direction the right mouse moves, relative to the
  // left one, when the body turns counter-clockwise.
  const Point2D jd{-d_.y, d_.x};
  s.dtheta = dot(diff, jd) / (D_ * D_);
  s.residual = dot(diff, e_);
  // Mean of u_i = V + dtheta J p_i gives V = u_mean - dtheta J p_mid.
  const Point2D um{(ur.x + ul.x) / 2.0, (ur.y + ul.y) / 2.0};
  s.vx_dt = um.x + s.dtheta * mid_.y;
  s.vy_dt = um.y - s.dtheta * mid_.x;
  s.delta = mrt::common::exp_twist(s.vx_dt, s.vy_dt, s.dtheta, 1.0);
  s.length_left = std::hypot(ul.x, ul.y);
  s.length_right = std::hypot(ur.x, ur.y);
  return s;
}

void ArcModel::predict_counts(double vx, double vy, double omega, double dt, double* ldx,
                              double* ldy, double* rdx, double* rdy) const {
  auto mouse = [&](const MouseParams& m, double* ox, double* oy) {
    const Point2D v{vx - omega * m.mount.y, vy + omega * m.mount.x};
    const Point2D r = rotate(v, -m.mount.theta);
    *ox = r.x * dt * m.counts_per_m;
    *oy = r.y * dt * m.counts_per_m;
  };
  mouse(params_.left, ldx, ldy);
  mouse(params_.right, rdx, rdy);
}

double manual_dtheta(double x_r, double y_r, double x_l, double y_l, double D) {
  const double l_r = std::hypot(x_r, y_r), l_l = std::hypot(x_l, y_l);
  const double gamma = std::fabs(std::atan2(y_r, x_r) - std::atan2(y_l, x_l));
  const double sq = l_r * l_r + l_l * l_l - 2.0 * std::cos(gamma) * l_r * l_l;
  const double sign = (y_r - y_l) > 0.0 ? 1.0 : ((y_r - y_l) < 0.0 ? -1.0 : 0.0);
  return std::sqrt(std::max(0.0, sq)) / D * sign;
}

}  // namespace mrt::mice
