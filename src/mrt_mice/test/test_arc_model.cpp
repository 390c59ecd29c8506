// Closed-form cases of the arc model (manual §4.1, eq. 4.2 as corrected).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mrt_common/pose2d.h"
#include "mrt_mice/arc_model.h"
#include "test_util.h"

using mrt::common::exp_twist;
using namespace mrt::mice;

namespace {

// Manual placement, D = 0.2 m, 10000 counts/m: one count is 0.1 mm.
constexpr double kD = 0.2;
constexpr double kC = 10000.0;
// Quantisation: each reading is off by < 1 count per axis, i.e. by at most
// sqrt(2)/c in length; the heading is off by at most twice that over D.
const double kLenTol = std::sqrt(2.0) / kC;
const double kAngTol = 2.0 * kLenTol / kD;

TEST(ArcModel, PureRotationInPlace) {
  // 0.3 rad counter-clockwise about the midpoint: each mouse runs an arc of
  // 0.1 * 0.3 = 0.03 m = 300 counts; the right one forward, the left one
  // backward, i.e. along the mice's y axes (yaw -90 degrees).
  ArcModel m(manual_placement(kD, kC));
  MiceCounts c;
  c.left_dy = -300;
  c.right_dy = 300;
  const ArcSolution s = m.solve(c);
  EXPECT_NEAR(s.dtheta, 0.3, 1e-12);
  EXPECT_NEAR(s.delta.theta, 0.3, 1e-12);
  EXPECT_NEAR(s.delta.x, 0.0, 1e-12);
  EXPECT_NEAR(s.delta.y, 0.0, 1e-12);
  EXPECT_NEAR(s.residual, 0.0, 1e-12);
  // The corrected eq. 4.2 says the same.
  EXPECT_NEAR(manual_dtheta(0.0, 300.0, 0.0, -300.0, kD * kC), 0.3, 1e-12);
}

TEST(ArcModel, ClockwiseRotationHasNegativeSign) {
  ArcModel m(manual_placement(kD, kC));
  MiceCounts c;
  c.left_dy = 500;
  c.right_dy = -500;
  EXPECT_NEAR(m.solve(c).dtheta, -0.5, 1e-12);
  EXPECT_NEAR(manual_dtheta(0.0, -500.0, 0.0, 500.0, kD * kC), -0.5, 1e-12);
}

TEST(ArcModel, PureTranslationInAnyDirection) {
  // The sensor does not depend on the kinematics: sideways and backwards too.
  ArcModel m(manual_placement(kD, kC));
  for (int k = 0; k < 24; ++k) {
    const double beta = k * M_PI / 12.0;
    // Robot-frame motion (cos b, sin b) * 0.1 m; the mouse frame is turned by
    // -90 degrees so it reads (-sin b, cos b) * 0.1 m.
    MiceCounts c;
    c.left_dx = c.right_dx = std::llround(-std::sin(beta) * 0.1 * kC);
    c.left_dy = c.right_dy = std::llround(std::cos(beta) * 0.1 * kC);
    const ArcSolution s = m.solve(c);
    EXPECT_EQ(s.dtheta, 0.0) << "beta " << beta;
    EXPECT_NEAR(s.delta.x, 0.1 * std::cos(beta), kLenTol) << "beta " << beta;
    EXPECT_NEAR(s.delta.y, 0.1 * std::sin(beta), kLenTol) << "beta " << beta;
    EXPECT_TRUE(std::isfinite(s.delta.x) && std::isfinite(s.delta.y));
  }
}

TEST(ArcModel, ConstantCurvatureArc) {
  // v = 0.5 m/s, omega = 1 rad/s for 0.2 s: radius 0.5 m, angle 0.2 rad.
  // Right mouse at 0.6 m from the centre runs 0.12 m, the left one 0.08 m.
  ArcModel m(manual_placement(kD, kC));
  MiceCounts c;
  c.right_dy = 1200;
  c.left_dy = 800;
  const ArcSolution s = m.solve(c);
  EXPECT_NEAR(s.dtheta, 0.2, 1e-12);
  EXPECT_NEAR(s.delta.x, 0.5 * std::sin(0.2), 1e-12);
  EXPECT_NEAR(s.delta.y, 0.5 * (1.0 - std::cos(0.2)), 1e-12);
  EXPECT_NEAR(manual_dtheta(0.0, 1200.0, 0.0, 800.0, kD * kC), 0.2, 1e-12);
  // Same arc driven backwards, and a tight arc around a centre between the mice.
  c.right_dy = -1200;
  c.left_dy = -800;
  const ArcSolution b = m.solve(c);
  EXPECT_NEAR(b.dtheta, -0.2, 1e-12);
  EXPECT_NEAR(b.delta.x, -0.5 * std::sin(0.2), 1e-12);
  EXPECT_NEAR(b.delta.y, 0.5 * (1.0 - std::cos(0.2)), 1e-12);
  c.right_dy = 300;  // v = 0.05, omega = 1 for 0.2 s: centre 5 cm left of the middle
  c.left_dy = -100;
  const ArcSolution t = m.solve(c);
  EXPECT_NEAR(t.dtheta, 0.2, 1e-12);
  EXPECT_NEAR(t.delta.x, 0.05 * std::sin(0.2), 1e-12);
  EXPECT_NEAR(t.delta.y, 0.05 * (1.0 - std::cos(0.2)), 1e-12);
}

TEST(ArcModel, StraightMotionDoesNotDivideByZero) {
  ArcModel m(manual_placement(kD, kC));
  MiceCounts c;  // all zero
  ArcSolution s = m.solve(c);
  EXPECT_EQ(s.delta.x, 0.0);
  EXPECT_EQ(s.delta.y, 0.0);
  EXPECT_EQ(s.delta.theta, 0.0);
  c.left_dy = c.right_dy = 1;  // one count straight ahead
  s = m.solve(c);
  EXPECT_NEAR(s.delta.x, 1e-4, 1e-15);
  EXPECT_EQ(s.delta.theta, 0.0);
  c.right_dy = 2;  // the smallest turn there is
  s = m.solve(c);
  EXPECT_NEAR(s.dtheta, 1e-4 / kD, 1e-15);
  EXPECT_TRUE(std::isfinite(s.delta.x));
  EXPECT_NEAR(s.delta.x, 1.5e-4, 1e-9);
}

TEST(ArcModel, ManualPlacementConstraintIsXEquality) {
  // For Fig. 4.1, consistent readings have x_r == x_l (the residual).
  ArcModel m(manual_placement(kD, kC));
  double lx, ly, rx, ry;
  m.predict_counts(0.3, -0.2, 0.7, 0.1, &lx, &ly, &rx, &ry);
  EXPECT_NEAR(lx, rx, 1e-9);
  MiceCounts c;
  c.left_dx = 100;
  c.right_dx = 130;
  // x axes point to the robot's right, the joining line runs left -> right,
  // so the residual is x_r - x_l in metres.
  EXPECT_NEAR(m.solve(c).residual, (130.0 - 100.0) / kC, 1e-12);
}

TEST(ArcModel, GeneralEq42AgreesWithLeastSquares) {
  // Exact readings of random motions: the corrected eq. 4.2 and the general
  // solver give the same dtheta for the symmetric placement.
  ArcModel m(manual_placement(kD, kC));
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    double lx, ly, rx, ry;
    m.predict_counts(u(rng), u(rng), 3.0 * u(rng), 0.05, &lx, &ly, &rx, &ry);
    const double d = manual_dtheta(rx, ry, lx, ly, kD * kC);
    const ArcSolution s =
        m.solve_body(m.left_in_body(lx, ly), m.right_in_body(rx, ry));
    EXPECT_NEAR(s.dtheta, d, 1e-9);
  }
}

TEST(ArcModel, GeneralPlacementRandomMotions) {
  const MiceParams p = test::general_placement();
  ArcModel m(p);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double cmin = std::min(p.left.counts_per_m, p.right.counts_per_m);
  const double e_u = std::sqrt(2.0) / cmin;
  const double D = p.distance();
  const double e_th = 2.0 * e_u / D;
  const double mid = std::hypot((p.left.mount.x + p.right.mount.x) / 2,
                                (p.left.mount.y + p.right.mount.y) / 2);
  for (int i = 0; i < 500; ++i) {
    const double vx = u(rng), vy = u(rng), w = (i % 5 == 0) ? 0.0 : 4.0 * u(rng), dt = 0.02;
    double lx, ly, rx, ry;
    m.predict_counts(vx, vy, w, dt, &lx, &ly, &rx, &ry);
    MiceCounts c;
    c.left_dx = std::llround(lx);
    c.left_dy = std::llround(ly);
    c.right_dx = std::llround(rx);
    c.right_dy = std::llround(ry);
    const ArcSolution s = m.solve(c);
    const mrt::common::Pose2D truth = exp_twist(vx, vy, w, dt);
    const double len = std::hypot(vx, vy) * dt;
    const double e_pos = e_u + e_th * mid + len * e_th;
    EXPECT_NEAR(s.delta.theta, truth.theta, e_th);
    EXPECT_NEAR(s.delta.x, truth.x, e_pos);
    EXPECT_NEAR(s.delta.y, truth.y, e_pos);
    // Half-count rounding keeps the residual within the detector's bound.
    EXPECT_LT(std::fabs(s.residual), std::sqrt(2.0) * 0.5 *
                                         (1 / p.left.counts_per_m + 1 / p.right.counts_per_m) + 1e-12);
  }
}

TEST(ArcModel, GeneralPlacementExactArc) {
  // Real-valued readings reproduce exp_twist to rounding.
  ArcModel m(test::general_placement());
  double lx, ly, rx, ry;
  m.predict_counts(0.4, 0.25, -2.0, 0.1, &lx, &ly, &rx, &ry);
  const ArcSolution s = m.solve_body(m.left_in_body(lx, ly), m.right_in_body(rx, ry));
  const auto t = exp_twist(0.4, 0.25, -2.0, 0.1);
  EXPECT_NEAR(s.delta.x, t.x, 1e-12);
  EXPECT_NEAR(s.delta.y, t.y, 1e-12);
  EXPECT_NEAR(s.delta.theta, t.theta, 1e-12);
  EXPECT_NEAR(s.residual, 0.0, 1e-12);
}

// A general placement worked out by hand (not from predict_counts): left
// mouse at (0.1, 0.1) turned +90 degrees (its x axis along the body's y),
// right mouse at (-0.1, -0.05) turned 180 degrees (facing backwards),
// 10000 counts/m. A mouse reads m_i = R(-phi_i) (V + dtheta J p_i), with
// R(-90)(x, y) = (y, -x), R(-180)(x, y) = (-x, -y), J(x, y) = (-y, x).
// Joining line p_r - p_l = (-0.2, -0.15): D = 0.25, e = (-0.8, -0.6).
MiceParams hand_placement() {
  MiceParams p;
  p.left.mount = Pose2D(0.1, 0.1, M_PI / 2);
  p.right.mount = Pose2D(-0.1, -0.05, M_PI);
  p.left.counts_per_m = p.right.counts_per_m = kC;
  return p;
}

TEST(ArcModel, GeneralPlacementRotationInPlaceByHand) {
  // 0.2 rad about base_link: left 0.2 J p_l = (-0.02, 0.02) m, read as
  // (0.02, 0.02) m = (200, 200) counts; right 0.2 J p_r = (0.01, -0.02) m,
  // read as (-0.01, 0.02) m = (-100, 200) counts.
  ArcModel m(hand_placement());
  const Point2D ul = m.left_in_body(200, 200), ur = m.right_in_body(-100, 200);
  EXPECT_NEAR(ul.x, -0.02, 1e-15);
  EXPECT_NEAR(ul.y, 0.02, 1e-15);
  EXPECT_NEAR(ur.x, 0.01, 1e-15);
  EXPECT_NEAR(ur.y, -0.02, 1e-15);
  MiceCounts c;
  c.left_dx = 200;
  c.left_dy = 200;
  c.right_dx = -100;
  c.right_dy = 200;
  const ArcSolution s = m.solve(c);
  EXPECT_NEAR(s.dtheta, 0.2, 1e-12);
  EXPECT_NEAR(s.delta.theta, 0.2, 1e-12);
  EXPECT_NEAR(s.delta.x, 0.0, 1e-12);
  EXPECT_NEAR(s.delta.y, 0.0, 1e-12);
  EXPECT_NEAR(s.residual, 0.0, 1e-12);
  // Arc lengths: |p_l| 0.2 = 0.02 sqrt 2, |p_r| 0.2 = 0.2 sqrt(0.0125).
  EXPECT_NEAR(s.length_left, 0.02 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s.length_right, 0.2 * std::sqrt(0.0125), 1e-12);
}

TEST(ArcModel, GeneralPlacementSidewaysTranslationByHand) {
  // 5 cm to the left (V = (0, 0.05)): left reads R(-90)(0, 0.05) =
  // (0.05, 0) = (500, 0); right reads R(-180)(0, 0.05) = (0, -500).
  ArcModel m(hand_placement());
  MiceCounts c;
  c.left_dx = 500;
  c.right_dy = -500;
  ArcSolution s = m.solve(c);
  EXPECT_NEAR(s.dtheta, 0.0, 1e-12);
  EXPECT_NEAR(s.delta.x, 0.0, 1e-12);
  EXPECT_NEAR(s.delta.y, 0.05, 1e-12);
  EXPECT_NEAR(s.residual, 0.0, 1e-12);
  // Each mouse enters the residual: 10 more counts on the left's x axis
  // move it (0, 1 mm) in the body: residual -(0, 0.001).e = +0.6 mm; 10
  // more on the right's x axis move it (-1 mm, 0): +(-0.001, 0).e = +0.8 mm.
  c.left_dx = 510;
  s = m.solve(c);
  EXPECT_NEAR(s.residual, 0.0006, 1e-12);
  c.left_dx = 500;
  c.right_dx = 10;
  s = m.solve(c);
  EXPECT_NEAR(s.residual, 0.0008, 1e-12);
}

TEST(ArcModel, GeneralPlacementArcByHand) {
  // V = (0.05, 0), dtheta = 0.2: left moves (0.05 - 0.02, 0.02) = (0.03,
  // 0.02) m, reads (0.02, -0.03) = (200, -300); right moves (0.05 + 0.01,
  // -0.02), reads (-0.06, 0.02) = (-600, 200). The chord of the arc:
  // (0.05 sin 0.2 / 0.2, 0.05 (1 - cos 0.2) / 0.2).
  ArcModel m(hand_placement());
  MiceCounts c;
  c.left_dx = 200;
  c.left_dy = -300;
  c.right_dx = -600;
  c.right_dy = 200;
  const ArcSolution s = m.solve(c);
  EXPECT_NEAR(s.dtheta, 0.2, 1e-12);
  EXPECT_NEAR(s.vx_dt, 0.05, 1e-12);
  EXPECT_NEAR(s.vy_dt, 0.0, 1e-12);
  EXPECT_NEAR(s.delta.x, 0.25 * std::sin(0.2), 1e-12);
  EXPECT_NEAR(s.delta.y, 0.25 * (1.0 - std::cos(0.2)), 1e-12);
  EXPECT_NEAR(s.residual, 0.0, 1e-12);
}

TEST(ArcModel, PredictCountsHandValues) {
  // Left mouse at (0.12, 0.08) turned 10 deg: pure rotation 1 rad/s for 1 s
  // moves it by J p = (-0.08, 0.12) m, read in its frame as R(-10deg) of that.
  ArcModel m(test::general_placement());
  double lx, ly, rx, ry;
  m.predict_counts(0.0, 0.0, 1.0, 1.0, &lx, &ly, &rx, &ry);
  const double c = std::cos(10 * M_PI / 180), s = std::sin(10 * M_PI / 180);
  EXPECT_NEAR(lx, (c * -0.08 + s * 0.12) * 15748.0, 1e-9);
  EXPECT_NEAR(ly, (-s * -0.08 + c * 0.12) * 15748.0, 1e-9);
}

TEST(ManualGeometry, SymmetricPlacement) {
  const ManualGeometry g = manual_geometry(manual_placement(0.3, kC));
  EXPECT_NEAR(g.D, 0.3, 1e-12);
  EXPECT_NEAR(g.delta, 0.0, 1e-12);
  EXPECT_NEAR(g.sigma_l, -M_PI / 2, 1e-12);
  EXPECT_NEAR(g.sigma_r, -M_PI / 2, 1e-12);
}

TEST(MiceParams, ValidateRejectsBadValues) {
  MiceParams p = manual_placement(0.2, kC);
  p.left.counts_per_m = 0.0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = manual_placement(0.0, kC);
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = manual_placement(0.2, kC);
  p.detection_factor = -1;
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

}  // namespace
