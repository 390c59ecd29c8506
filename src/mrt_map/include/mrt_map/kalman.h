// The Tracker's Kalman filter (state x, y, vx, vy; position measured) and
// the fusion rules of the Merger: information (independent sources) and
// covariance intersection (teammates' estimates, unknown correlation).
#pragma once

#include "mrt_map/conceptual_model.h"
#include "mrt_map/types.h"

namespace mrt::map {

/// Transition over dt: constant velocity F = [I dt*I; 0 I]; static F = I
/// with zero velocity (see process_noise).
Mat4 transition(const ClassDef& c, double dt);

/// Process noise over dt. Constant velocity: continuous white acceleration
/// of spectral density q = accel_noise^2: q*[dt^3/3 I, dt^2/2 I; dt^2/2 I, dt I].
/// Static: q*dt on the position only (a slow drift), none on the velocity.
/// `accel_noise` >= 0 replaces the class's (an IMM model's).
Mat4 process_noise(const ClassDef& c, double dt, double accel_noise = -1.0);

/// A new estimate from a first observation: velocity 0 with variance
/// init_speed_sigma^2 (CV) or 1e-6 (static).
Estimate initialize(const Observation& o, const ClassDef& c);

/// Predicts `e` to time t (no-op when t <= e.stamp).
Estimate predict(const Estimate& e, const ClassDef& c, double t, double accel_noise = -1.0);

/// Squared Mahalanobis distance of a position z (covariance R) from the
/// estimate's position: y' (H P H' + R)^-1 y.
double mahalanobis2(const Estimate& e, const Vec2& z, const Mat2& R);

/// A cheap sufficient test that mahalanobis2(e, z, R) > gate (|y|^2 beyond
/// gate * trace(S)), to skip far pairs.
bool outside_gate(const Estimate& e, const Vec2& z, const Mat2& R, double gate);

/// Kalman update with a position measurement.
void update(Estimate& e, const Vec2& z, const Mat2& R);

/// A manoeuvre found at an update `dt` after the previous one (the
/// observation beyond the gate of the predicted `e`, covariance R). Class
/// `maneuver: impulse` (a kick): a velocity jump of sigma s =
/// init_speed_sigma per axis at the start of the interval, carried to now,
/// P += [dt^2 s^2 I, dt s^2 I; dt s^2 I, s^2 I], so the update takes the
/// innovation into the velocity too. `reset` (default): the velocity is
/// forgotten (P_vv = s^2 I, uncorrelated) and P_pp += R.
void maneuver(Estimate& e, const ClassDef& c, double dt, const Mat2& R);

/// Information fusion of two independent position measurements.
void fuse_independent(Vec2& z, Mat2& R, const Vec2& z2, const Mat2& R2);

/// Covariance intersection of two estimates at the same time:
/// P^-1 = w Pa^-1 + (1-w) Pb^-1, x = P (w Pa^-1 xa + (1-w) Pb^-1 xb), with w
/// in [0, 1] minimising the trace of the CI of the two position blocks
/// (golden section on 2x2 matrices; the same w as on the full P when
/// position and velocity are uncorrelated). `omega` receives w when given.
Estimate covariance_intersection(const Estimate& a, const Estimate& b, double* omega = nullptr);

/// Eigen decomposition of a 2x2 covariance in closed form: the variances
/// along the principal axes (major >= minor >= 0) and the major axis angle.
struct Ellipse {
  double major = 0.0, minor = 0.0, angle = 0.0;
};
Ellipse principal_axes(const Mat2& C);

/// Information fusion of two estimates believed independent.
Estimate fuse_estimates(const Estimate& a, const Estimate& b);

}  // namespace mrt::map
