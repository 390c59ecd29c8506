#include "mrt_mice/mice_odometry.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Core>

namespace mrt::mice {

void OdometryOptions::validate() const {
  auto nonneg = [](double v, const char* name) {
    if (!(v >= 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string(name) + ": must be a finite number >= 0");
  };
  nonneg(var_xy_per_m, "var_xy_per_m");
  nonneg(var_theta_per_rad, "var_theta_per_rad");
  nonneg(var_theta_per_m, "var_theta_per_m");
  nonneg(flagged_gain, "flagged_gain");
}

double ErrorStats::rms_residual() const {
  return samples > 0 ? std::sqrt(sum_sq_residual / static_cast<double>(samples)) : 0.0;
}

MiceOdometry::MiceOdometry(const MiceParams& params, const OdometryOptions& options)
    : params_(params),
      options_(options),
      model_(params),
      detector_(params),
      // Projections under ~3 quantisation bounds carry no usable scale.
      reducer_(model_, 3.0 * detector_.quantisation_bound()) {
  options_.validate();
}

void MiceOdometry::reset(const Pose2D& start) {
  integrator_.reset(start);
  reducer_.reset();
  cov_.fill(0.0);
  stats_ = ErrorStats();
}

StepResult MiceOdometry::update(const MiceCounts& c) {
  StepResult r;
  const Point2D ul = model_.left_in_body(static_cast<double>(c.left_dx), static_cast<double>(c.left_dy));
  const Point2D ur =
      model_.right_in_body(static_cast<double>(c.right_dx), static_cast<double>(c.right_dy));
  r.raw = model_.solve_body(ul, ur);
  r.detection = detector_.check(r.raw);
  if (options_.reduce_errors) {
    r.reduction = reducer_.reduce(r.raw, ul, ur, r.detection.flagged);
  } else {
    r.reduction.u_left = ul;
    r.reduction.u_right = ur;
    r.reduction.correction = r.detection.flagged ? Correction::kUncorrectable : Correction::kNone;
  }
  if (r.reduction.correction == Correction::kNone ||
      r.reduction.correction == Correction::kUncorrectable) {
    r.delta = r.raw.delta;
  } else {
    r.delta = model_.solve_body(r.reduction.u_left, r.reduction.u_right).delta;
  }

  ++stats_.samples;
  stats_.last_residual = r.raw.residual;
  stats_.max_abs_residual = std::max(stats_.max_abs_residual, std::fabs(r.raw.residual));
  stats_.sum_sq_residual += r.raw.residual * r.raw.residual;
  if (r.detection.flagged) {
    ++stats_.flagged;
    if (r.reduction.correction == Correction::kUncorrectable)
      ++stats_.uncorrectable;
    else
      ++stats_.corrected;
  }
  grow_covariance(r.delta, r.detection);
  integrator_.add(r.delta);
  return r;
}

void MiceOdometry::grow_covariance(const Pose2D& delta, const Detection& d) {
  // P' = F P F^T + Q with F the Jacobian of eqs. 4.3-4.5 w.r.t. the pose.
  const double th = integrator_.pose().theta;
  const double c = std::cos(th), s = std::sin(th);
  const double wx = c * delta.x - s * delta.y, wy = s * delta.x + c * delta.y;
  Eigen::Matrix3d F;
  F << 1, 0, -wy, 0, 1, wx, 0, 0, 1;
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> P(cov_.data());
  const Eigen::Matrix3d FP = F * P;
  Eigen::Matrix3d P2 = FP * F.transpose();
  const double ds = std::hypot(delta.x, delta.y);
  double q_xy = options_.var_xy_per_m * ds;
  double q_th = options_.var_theta_per_rad * std::fabs(delta.theta) + options_.var_theta_per_m * ds;
  if (d.flagged) {
    const double g = options_.flagged_gain * d.residual;
    q_xy += g * g;
    const double gt = g / params_.distance();
    q_th += gt * gt;
  }
  P2.diagonal() += Eigen::Vector3d(q_xy, q_xy, q_th);
  P = P2;
}

}  // namespace mrt::mice
