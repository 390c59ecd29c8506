// The arc model of manual §4.1 for a general placement of the two mice.
#pragma once

#include "mrt_mice/mice_params.h"

namespace mrt::mice {

/// What one sample says about the body motion. During a sample the body is
/// assumed to move with a constant twist, so every point of it (each mouse,
/// the base_link origin) runs along an arc with the same centre and angle.
struct ArcSolution {
  /// The twist integrated over the sample: (vx dt, vy dt, omega dt) in the
  /// body frame at the start of the sample (m, m, rad). dtheta = omega dt.
  double vx_dt = 0.0, vy_dt = 0.0, dtheta = 0.0;
  /// The body displacement (Delta x, Delta y, Delta theta): the pose of the
  /// new base_link in the old one, the chord of the arc (exact).
  Pose2D delta;
  /// Rigid-body residual: the mismatch (m) between the two mice's motions
  /// along their joining line, right minus left. 0 for consistent readings.
  double residual = 0.0;
  /// Arc lengths l_l and l_r travelled by the two mice (m).
  double length_left = 0.0, length_right = 0.0;
};

/// Solves the 4 readings for the 3 parameters of the arc.
///
/// Mouse i at p_i in base_link, rotated by phi_i, measures in its own frame
/// the integral of its velocity: m_i = R(-phi_i) (V + dtheta J p_i) with V =
/// (vx dt, vy dt), J the +90 degree rotation. In base_link, u_i = R(phi_i) m_i,
/// so u_r - u_l = dtheta J (p_r - p_l): the component across the joining
/// line gives dtheta (eq. 4.2, least squares), the component along it must
/// vanish (the rigid-body constraint, the residual). The mean of the two
/// gives V. Straight motion needs no special case: nothing is divided by
/// dtheta, and the arc is closed with the series form of exp (exp_twist).
class ArcModel {
 public:
  explicit ArcModel(const MiceParams& params);

  const MiceParams& params() const { return params_; }
  /// Unit vector of the joining line, from the left to the right mouse.
  Point2D joining_direction() const { return e_; }

  /// A mouse reading in counts, converted to metres and rotated into base_link.
  Point2D left_in_body(double dx_counts, double dy_counts) const;
  Point2D right_in_body(double dx_counts, double dy_counts) const;

  /// Solves a sample of raw counts.
  ArcSolution solve(const MiceCounts& c) const;
  /// Solves from the two mouse motions already in base_link (metres).
  ArcSolution solve_body(const Point2D& u_left, const Point2D& u_right) const;

  /// The inverse model, for tests and simulation: the (real-valued) counts
  /// the two mice read while the body moves with twist (vx, vy, omega) for dt.
  void predict_counts(double vx, double vy, double omega, double dt, double* left_dx,
                      double* left_dy, double* right_dx, double* right_dy) const;

 private:
  MiceParams params_;
  Point2D d_;   // p_r - p_l
  Point2D e_;   // d_ / |d_|
  double D_;
  Point2D mid_; // (p_r + p_l) / 2
};

/// Eq. 4.2 as corrected in NOTES.md, for the manual's symmetric placement:
/// dtheta = sqrt(l_r^2 + l_l^2 - 2 cos(gamma) l_r l_l) / D * sign(y_r - y_l),
/// with gamma = |alpha_r - alpha_l| the angle between the two readings.
/// Arguments are the raw readings of the two mice (any consistent unit) and
/// D in the same unit.
double manual_dtheta(double x_r, double y_r, double x_l, double y_l, double D);

}  // namespace mrt::mice
