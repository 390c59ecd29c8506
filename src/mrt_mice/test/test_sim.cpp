// Calibration and odometry against mrt_sim (ROS-free, deterministic).
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/angle.h"
#include "mrt_mice/calibrator.h"
#include "mrt_mice/mice_odometry.h"
#include "mrt_sim/sensors.h"
#include "sim_protocol.h"

using namespace mrt::mice;
using mrt::common::deg_to_rad;
using mrt::common::rad_to_deg;

namespace {

// An IANUS3 whose mice are not where the drawing says: resolutions 1-2 %
// off the nominal 400 cpi, placement off by millimetres and degrees.
sim::SimMice real_mice(double noise) {
  sim::SimMice m;
  m.truth.left.mount = Pose2D(0.123, 0.097, deg_to_rad(2.5));
  m.truth.left.counts_per_m = 15748.0 * 1.017;
  m.truth.right.mount = Pose2D(-0.118, 0.058, deg_to_rad(-1.8));
  m.truth.right.counts_per_m = 15748.0 * 0.988;
  m.noise = noise;
  return m;
}

TEST(SimModel, MouseDisplacementMatchesArcModel) {
  // The simulator's closed-form mouse and our inverse model agree.
  const MiceParams p = real_mice(0).truth;
  ArcModel m(p);
  double lx, ly, rx, ry;
  m.predict_counts(0.3, -0.1, 0.9, 0.05, &lx, &ly, &rx, &ry);
  const auto d = mrt::sim::mouse_displacement(p.left.mount, {0.3, -0.1, 0.9}, 0.05);
  EXPECT_NEAR(lx, d.x * p.left.counts_per_m, 1e-9);
  EXPECT_NEAR(ly, d.y * p.left.counts_per_m, 1e-9);
}

void expect_recovers(const sim::SimMice& m, const sim::Operator& op = sim::Operator()) {
  mrt::sim::Simulator simulator(sim::make_world(m, 5));
  const auto runs = sim::calibration_runs(simulator, 10, 5, op);
  ASSERT_EQ(runs.size(), 15u);
  const CalibrationResult res = calibrate(runs);
  const ManualGeometry g = manual_geometry(m.truth), e = res.geometry;
  EXPECT_NEAR(e.D, g.D, 0.005 * g.D);
  EXPECT_NEAR(rad_to_deg(e.sigma_l), rad_to_deg(g.sigma_l), 0.2);
  EXPECT_NEAR(rad_to_deg(e.sigma_r), rad_to_deg(g.sigma_r), 0.2);
  EXPECT_NEAR(rad_to_deg(e.delta), rad_to_deg(g.delta), 0.2);
  for (int i = 0; i < 2; ++i) {
    const MouseParams& t = i ? m.truth.right : m.truth.left;
    const MouseParams& r = i ? res.params.right : res.params.left;
    EXPECT_NEAR(r.counts_per_m, t.counts_per_m, 0.005 * t.counts_per_m) << i;
    EXPECT_NEAR(r.mount.x, t.mount.x, 0.001) << i;
    EXPECT_NEAR(r.mount.y, t.mount.y, 0.001) << i;
  }
}

TEST(SimCalibration, RecoversParametersWithoutNoise) { expect_recovers(real_mice(0.0)); }
TEST(SimCalibration, RecoversParametersWithNoise) { expect_recovers(real_mice(0.01)); }

TEST(SimCalibration, RecoversParametersWithAnImperfectOperator) {
  // Pushes of 500 +- 2 mm and turns of 360 +- 0.3 degrees (1 sigma).
  sim::Operator op;
  op.push_sigma = 0.002;
  op.turn_sigma = deg_to_rad(0.3);
  op.seed = 31;
  expect_recovers(real_mice(0.01), op);
}

TEST(SimCalibration, RecoversManualPlacement) {
  sim::SimMice m;
  m.truth = manual_placement(0.24, 15748.0);
  m.truth.left.counts_per_m *= 1.012;
  m.truth.right.mount = Pose2D(0.003, -0.121, deg_to_rad(-88.5));
  expect_recovers(m);
}

TEST(SimOdometry, CalibratedFollowsGroundTruthOver20m) {
  const sim::SimMice m = real_mice(0.002);
  mrt::sim::Simulator calib_sim(sim::make_world(m, 7));
  const MiceParams params = calibrate(sim::calibration_runs(calib_sim)).params;
  mrt::sim::Simulator s(sim::make_world(m, 8));
  MiceOdometry odo(params);
  auto on = [&](const mrt::sim::RobotState& r) { odo.update(sim::to_counts(r.mice)); };
  // 20 m: straight legs and arcs of both signs at 1 m/s.
  sim::drive(s, {1.0, 0.0, 0.0}, 5000, on);
  sim::drive(s, {1.0, 0.0, 0.4}, 5000, on);
  sim::drive(s, {1.0, 0.0, -0.3}, 5000, on);
  sim::drive(s, {1.0, 0.0, 0.0}, 5000, on);
  sim::settle(s, on);
  const Pose2D truth = s.robots()[0].pose;
  const double err = std::hypot(odo.pose().x - truth.x, odo.pose().y - truth.y);
  EXPECT_NEAR(odo.distance(), 20.0, 0.02);
  EXPECT_LT(err, 0.01 * 20.0) << "error " << err << " m";
  EXPECT_LT(std::fabs(mrt::common::angle_diff(odo.pose().theta, truth.theta)), deg_to_rad(1.0));
  EXPECT_EQ(odo.stats().flagged, 0u);
}

TEST(SimOdometry, NoFalseAlarmWhenTheMotionReversesWithinASample) {
  // Back and forth faster than the 50 Hz samples (37 Hz forward, 29 Hz
  // turning): the mice reverse within a sample, so each report is the
  // difference of two quantised positions. The simulator keeps a floor
  // remainder, so each report is within one count per axis of the truth,
  // and the rigid-body constraint holds for any motion of the body (not
  // only for a constant twist: u_r - u_l = (integral of omega) J (p_r - p_l)
  // is across the joining line whatever the twist did), so no sample may
  // exceed the quantisation bound. Exact mounts, no noise, no faults.
  for (int layout = 0; layout < 2; ++layout) {
    sim::SimMice m = real_mice(0.0);
    if (layout == 1) {  // side by side, as in the manual's Fig. 4.1
      m.truth.left.mount = Pose2D(0.004, 0.097, deg_to_rad(1.5));
      m.truth.right.mount = Pose2D(-0.003, -0.104, deg_to_rad(-2.0));
    }
    mrt::sim::Simulator s(sim::make_world(m, 40 + layout));
    MiceOdometry odo(m.truth);
    long samples = 0, reversing = 0;
    auto on = [&](const mrt::sim::RobotState& r) {
      odo.update(sim::to_counts(r.mice));
      ++samples;
    };
    const double dt = s.dt();
    double last_v = 0.0;
    for (long k = 0; k < 20000; ++k) {
      const double t = k * dt;
      const double v = 0.3 * std::sin(2 * M_PI * 37.0 * t) + 0.05;
      const double w = 1.5 * std::sin(2 * M_PI * 29.0 * t + 1.0);
      reversing += (v > 0) != (last_v > 0);
      last_v = v;
      sim::drive(s, {v, 0.0, w}, 1, on);
    }
    sim::settle(s, on);
    ASSERT_GT(samples, 990);
    EXPECT_GT(reversing, 1000);  // ~2 per period of 37 Hz for 20 s
    EXPECT_EQ(odo.stats().flagged, 0u)
        << "layout " << layout << ": largest residual " << odo.stats().max_abs_residual / odo.detector().quantisation_bound()
        << " quantisation bounds";
    // Some residuals come close to the bound: the test would see a
    // quantisation error of more than one count.
    EXPECT_GT(odo.stats().max_abs_residual, 0.3 * odo.detector().quantisation_bound()) << "layout " << layout;
  }
}

TEST(SimOdometry, DetectsAndReducesSimulatorFaults) {
  // The simulator's fault: in a 1 ms step a mouse loses up to all of that
  // step's length (fault_rate per step). On straight and curved drives the
  // reduced odometry ends closer to the truth than the uncorrected one.
  sim::SimMice m = real_mice(0.0);
  m.fault_rate = 0.02;
  m.fault_max_fraction = 1.0;
  double sum_with = 0.0, sum_without = 0.0;
  int faulty = 0, caught = 0;
  for (std::uint64_t seed = 20; seed < 26; ++seed) {
    mrt::sim::Simulator s(sim::make_world(m, seed));
    OdometryOptions off;
    off.reduce_errors = false;
    MiceOdometry with(m.truth), without(m.truth, off);
    auto on = [&](const mrt::sim::RobotState& r) {
      const auto c = sim::to_counts(r.mice);
      const bool flagged = with.update(c).detection.flagged;
      without.update(c);
      if (r.mice.left_fault || r.mice.right_fault) {
        ++faulty;
        caught += flagged;
      }
    };
    // One drive per seed: straight, or an arc of either sign.
    const double w = seed % 3 == 0 ? 0.0 : (seed % 3 == 1 ? 0.5 : -0.5);
    sim::drive(s, {0.8, 0.0, w}, 6000, on);
    sim::settle(s, on);
    const Pose2D truth = s.robots()[0].pose;
    const double ew = std::hypot(with.pose().x - truth.x, with.pose().y - truth.y);
    const double eo = std::hypot(without.pose().x - truth.x, without.pose().y - truth.y);
    EXPECT_LT(ew, eo) << "seed " << seed;
    EXPECT_LT(std::fabs(mrt::common::angle_diff(with.pose().theta, truth.theta)),
              std::fabs(mrt::common::angle_diff(without.pose().theta, truth.theta)))
        << "seed " << seed;
    sum_with += ew;
    sum_without += eo;
  }
  EXPECT_GT(faulty, 500);
  EXPECT_LT(sum_with, sum_without / 2) << "with reduction " << sum_with << " m, without " << sum_without;
  EXPECT_GT(caught, faulty * 3 / 4) << caught << " of " << faulty;
}

}  // namespace
