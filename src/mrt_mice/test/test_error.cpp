// Error detection and reduction (manual §4.2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mrt_common/pose2d.h"
#include "mrt_mice/error_detector.h"
#include "mrt_mice/error_reducer.h"
#include "mrt_mice/mice_odometry.h"
#include "test_util.h"

using namespace mrt::mice;
using mrt::common::exp_twist;

namespace {

TEST(ErrorDetector, ThresholdIsTheQuantisationBound) {
  MiceParams p = manual_placement(0.2, 10000.0);
  ErrorDetector d(p);
  EXPECT_NEAR(d.quantisation_bound(), std::sqrt(2.0) * 2e-4, 1e-15);
  ArcModel m(p);
  MiceCounts c;
  c.left_dx = 100;
  c.right_dx = 102;  // 2 counts: within sqrt(2) * 2 counts
  EXPECT_FALSE(d.check(m.solve(c)).flagged);
  c.right_dx = 103;  // 3 counts: beyond
  const Detection det = d.check(m.solve(c));
  EXPECT_TRUE(det.flagged);
  EXPECT_NEAR(det.residual, 3e-4, 1e-12);
}

TEST(ErrorDetector, RelativeTermScalesWithPathLength) {
  MiceParams p = manual_placement(0.2, 10000.0);
  p.detection_relative = 0.01;
  ErrorDetector d(p);
  ArcModel m(p);
  MiceCounts c;
  c.left_dy = c.right_dy = 1000;  // 0.1 m: adds 1 mm to the threshold
  c.left_dx = 100;
  c.right_dx = 110;
  EXPECT_FALSE(d.check(m.solve(c)).flagged);
  c.right_dx = 115;
  EXPECT_TRUE(d.check(m.solve(c)).flagged);
}

TEST(ErrorDetector, ConsistentQuantisedReadingsAreNeverFlagged) {
  const MiceParams p = test::general_placement();
  test::QuantisedMice mice(p);
  MiceOdometry odo(p);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 5000; ++i) {
    const auto r = odo.update(mice.step(u(rng), u(rng), 3 * u(rng), 0.02));
    ASSERT_FALSE(r.detection.flagged) << "sample " << i << " residual " << r.detection.residual;
  }
}

TEST(ErrorDetector, FlagsInjectedUnderReads) {
  // Forward at 0.5 m/s with the general placement (the joining line is not
  // across the motion): a 20 % under-read of either mouse is flagged.
  const MiceParams p = test::general_placement();
  for (int bad = 0; bad < 2; ++bad) {
    test::QuantisedMice mice(p);
    MiceOdometry odo(p);
    int flagged = 0, injected = 0;
    for (int i = 0; i < 200; ++i) {
      const bool fault = i % 10 == 5;
      injected += fault;
      const auto r = odo.update(mice.step(0.5, 0.0, 0.3, 0.02, fault && bad == 0 ? 0.8 : 1.0,
                                          fault && bad == 1 ? 0.8 : 1.0));
      if (r.detection.flagged) {
        ++flagged;
        EXPECT_TRUE(fault) << "false alarm at " << i;
      }
    }
    EXPECT_EQ(flagged, injected);
  }
}

TEST(ErrorReducer, OneConsistentMouseCorrectsTheOther) {
  const MiceParams p = test::general_placement();
  ArcModel m(p);
  ErrorDetector det(p);
  ErrorReducer red(m, 3 * det.quantisation_bound());
  double lx, ly, rx, ry;
  m.predict_counts(0.5, 0.1, 0.8, 0.02, &lx, &ly, &rx, &ry);
  const Point2D ul = m.left_in_body(lx, ly), ur = m.right_in_body(rx, ry);
  const auto truth = m.solve_body(ul, ur).delta;
  // Left loses 35 % of its length.
  const Point2D ul_bad{ul.x * 0.65, ul.y * 0.65};
  const ArcSolution s = m.solve_body(ul_bad, ur);
  ASSERT_TRUE(det.check(s).flagged);
  const Reduction r = red.reduce(s, ul_bad, ur, true);
  EXPECT_EQ(r.correction, Correction::kLeftScaled);
  EXPECT_NEAR(r.scale, 1.0 / 0.65, 1e-9);
  const auto fixed = m.solve_body(r.u_left, r.u_right).delta;
  EXPECT_NEAR(fixed.x, truth.x, 1e-12);
  EXPECT_NEAR(fixed.y, truth.y, 1e-12);
  EXPECT_NEAR(fixed.theta, truth.theta, 1e-12);
  // The same for the right mouse.
  const Point2D ur_bad{ur.x * 0.5, ur.y * 0.5};
  const ArcSolution s2 = m.solve_body(ul, ur_bad);
  const Reduction r2 = red.reduce(s2, ul, ur_bad, true);
  EXPECT_EQ(r2.correction, Correction::kRightScaled);
  const auto fixed2 = m.solve_body(r2.u_left, r2.u_right).delta;
  EXPECT_NEAR(fixed2.theta, truth.theta, 1e-12);
}

TEST(ErrorReducer, BothWrongIsReduced) {
  const MiceParams p = test::general_placement();
  ArcModel m(p);
  ErrorReducer red(m, 1e-5);
  double lx, ly, rx, ry;
  m.predict_counts(0.5, 0.0, 0.5, 0.02, &lx, &ly, &rx, &ry);
  const Point2D ul = m.left_in_body(lx, ly), ur = m.right_in_body(rx, ry);
  const auto truth = m.solve_body(ul, ur).delta;
  const Point2D ul_bad{ul.x * 0.6, ul.y * 0.6}, ur_bad{ur.x * 0.9, ur.y * 0.9};
  const ArcSolution s = m.solve_body(ul_bad, ur_bad);
  const Reduction r = red.reduce(s, ul_bad, ur_bad, true);
  const auto fixed = m.solve_body(r.u_left, r.u_right).delta;
  auto err = [&](const Pose2D& d) {
    return std::hypot(d.x - truth.x, d.y - truth.y) + 0.1 * std::fabs(d.theta - truth.theta);
  };
  EXPECT_LT(err(fixed), err(s.delta));
  // What is left is the better mouse's loss: the pose is 10 % short.
  EXPECT_NEAR(fixed.x, 0.9 * truth.x, 1e-3 * std::fabs(truth.x) + 1e-9);
}

TEST(ErrorReducer, DeadMouseRebuiltFromTheLastGoodSample) {
  const MiceParams p = test::general_placement();
  ArcModel m(p);
  ErrorReducer red(m, 1e-4);
  double lx, ly, rx, ry;
  m.predict_counts(0.4, 0.0, 0.2, 0.02, &lx, &ly, &rx, &ry);
  const Point2D ul = m.left_in_body(lx, ly), ur = m.right_in_body(rx, ry);
  red.reduce(m.solve_body(ul, ur), ul, ur, false);  // learns the directions
  const Point2D zero{0, 0};
  const Reduction r = red.reduce(m.solve_body(zero, ur), zero, ur, true);
  EXPECT_EQ(r.correction, Correction::kLeftRebuilt);
  EXPECT_NEAR(r.u_left.x, ul.x, 1e-12);
  EXPECT_NEAR(r.u_left.y, ul.y, 1e-12);
  // Without history it cannot be done.
  ErrorReducer fresh(m, 1e-4);
  EXPECT_EQ(fresh.reduce(m.solve_body(zero, ur), zero, ur, true).correction,
            Correction::kUncorrectable);
}

// A 10 m trajectory of arcs with random under-reads (the §4.2 fault: up to
// half of a sample's length lost by one mouse, sometimes both): reduction
// ends closer to the truth than no correction.
TEST(MiceOdometry, ReductionBeatsNoCorrection) {
  const MiceParams p = test::general_placement();
  test::QuantisedMice mice(p);
  OdometryOptions with, without;
  without.reduce_errors = false;
  MiceOdometry a(p, with), b(p, without);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  mrt::common::Pose2D truth;
  int faults = 0, flagged = 0;
  for (int i = 0; i < 1000; ++i) {
    const double v = 0.5, w = 0.6 * std::sin(i * 0.01);
    double fl = 1.0, fr = 1.0;
    if (u(rng) < 0.1) {
      (u(rng) < 0.5 ? fl : fr) = 1.0 - 0.5 * u(rng);
      if (u(rng) < 0.2) fl = fr = 0.9;
      ++faults;
    }
    const MiceCounts c = mice.step(v, 0.0, w, 0.02, fl, fr);
    truth = truth * exp_twist(v, 0.0, w, 0.02);
    flagged += a.update(c).detection.flagged;
    b.update(c);
  }
  const double ea = std::hypot(a.pose().x - truth.x, a.pose().y - truth.y);
  const double eb = std::hypot(b.pose().x - truth.x, b.pose().y - truth.y);
  EXPECT_LT(ea, eb / 3.0) << "reduced " << ea << " m, uncorrected " << eb << " m";
  EXPECT_LT(std::fabs(mrt::common::angle_diff(a.pose().theta, truth.theta)),
            std::fabs(mrt::common::angle_diff(b.pose().theta, truth.theta)));
  // Small losses and equal losses of both mice go unseen.
  EXPECT_GT(flagged, faults * 3 / 4);
  EXPECT_EQ(a.stats().flagged, static_cast<std::uint64_t>(flagged));
  EXPECT_GT(a.stats().corrected, 0u);
}

TEST(MiceOdometry, CovarianceGrowsWithDistanceAndFlags) {
  const MiceParams p = test::general_placement();
  test::QuantisedMice mice(p);
  MiceOdometry odo(p);
  double last = 0.0;
  for (int i = 0; i < 100; ++i) {
    odo.update(mice.step(0.5, 0.0, 0.0, 0.02));
    EXPECT_GT(odo.covariance()[0], last);
    last = odo.covariance()[0];
  }
  MiceOdometry clean(p), faulty(p);
  test::QuantisedMice m1(p), m2(p);
  for (int i = 0; i < 50; ++i) {
    clean.update(m1.step(0.5, 0.0, 0.0, 0.02));
    faulty.update(m2.step(0.5, 0.0, 0.0, 0.02, i % 5 ? 1.0 : 0.5));
  }
  EXPECT_GT(faulty.stats().flagged, 0u);
  EXPECT_GT(faulty.covariance()[0], clean.covariance()[0]);
  EXPECT_GT(faulty.covariance()[8], clean.covariance()[8]);
}

}  // namespace
