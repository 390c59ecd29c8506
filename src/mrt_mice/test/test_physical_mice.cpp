// The odometry against mrt_sim's physical mouse model (mrt_sim/mouse_model.h):
// each mouse reports at 125 Hz on its own clock (the right one skewed by
// 0-8 ms, one USB frame, and 100 ppm fast), with speed and acceleration
// limits; the reports go through CountAligner as in mice_evdev_node.
//
// The robot (the staggered IANUS3 mice of config/ianus3_staggered.yaml, the
// odometry told their true placement so only timing can break the rigid-
// body check) drives a smooth varying twist for 10 s, ramped up over 1 s so
// no acceleration limit is hit (< 0.1 g): vx = 0.4 + 0.2 sin 1.3t m/s,
// omega = 0.8 sin 0.5t rad/s, about 4 m.
//
// Expected (worked out in test_count_aligner.cpp for the same motion):
// summing the reports since the last 50 Hz sample puts windows of 2 and 3
// reports (16 / 24 ms) side by side: at 0.4 m/s a 2-4 ms skew is 0.8-1.6 mm
// = 13-25 counts along the joining line, far above the detector's 0.18 mm,
// so most moving samples are flagged; aligned, none is, and the pose
// stays within 1 cm and 0.5 degrees of the truth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mrt_common/angle.h"
#include "mrt_mice/mice_odometry.h"
#include "sim_protocol.h"

using namespace mrt::mice;

namespace {

struct Result {
  long samples = 0, flagged = 0, faults = 0;
  double pos_err = 0.0, heading_err = 0.0;
};

sim::SimMice staggered(double skew) {
  sim::SimMice m;
  m.truth.left.mount = Pose2D(0.12, 0.10, 0.0);
  m.truth.right.mount = Pose2D(-0.12, 0.06, 0.0);
  m.truth.left.counts_per_m = m.truth.right.counts_per_m = 15748.0;
  for (auto& p : m.physics) {
    p.enabled = true;
    p.report_rate = 125.0;
  }
  m.physics[1].phase = skew;
  m.physics[1].drift_ppm = 100.0;
  return m;
}

Result run(double skew, bool aligned) {
  const sim::SimMice mice = staggered(skew);
  mrt::sim::Simulator s(sim::make_world(mice, 5));
  MiceOdometry odo(mice.truth);
  sim::AlignedMice align(aligned);
  Result res;
  for (int k = 1; k <= 10000; ++k) {
    const double t = k * s.dt(), ramp = std::min(1.0, t);
    s.set_twist(0, {ramp * (0.4 + 0.2 * std::sin(1.3 * t)), 0.0, ramp * 0.8 * std::sin(0.5 * t)});
    s.step();
    const mrt::sim::RobotState& r = s.robots()[0];
    if (!r.mice_ready) continue;
    ++res.samples;
    res.faults += r.mice.left_fault || r.mice.right_fault;
    res.flagged += odo.update(align(r.mice)).detection.flagged;
  }
  const Pose2D& truth = s.robots()[0].pose;  // started at the origin
  // The aligned odometry lags by the aligner's delay (10 ms): compare it
  // with the truth then, i.e. minus 10 ms of the final twist.
  const mrt::sim::Twist2D& tw = s.robots()[0].twist;
  const double lag = aligned ? AlignerOptions().delay : 0.0;
  const double tx = truth.x - lag * tw.vx * std::cos(truth.theta), ty = truth.y - lag * tw.vx * std::sin(truth.theta);
  res.pos_err = std::hypot(odo.pose().x - tx, odo.pose().y - ty);
  res.heading_err = std::fabs(mrt::common::angle_diff(odo.pose().theta, truth.theta - lag * tw.omega));
  return res;
}

}  // namespace

TEST(PhysicalMice, OneUsbFrameOfSkewGivesNoFalseAlarms) {
  for (double skew : {0.0, 0.001, 0.002, 0.004, 0.006, 0.008}) {
    const Result r = run(skew, true);
    std::printf("aligned, skew %.0f ms: %ld of %ld flagged, %.2f mm, %.3f deg\n", skew * 1e3, r.flagged, r.samples,
                r.pos_err * 1e3, r.heading_err * 180.0 / M_PI);
    EXPECT_EQ(r.samples, 500) << skew;
    EXPECT_EQ(r.faults, 0) << skew;  // no lift-off, speed or acceleration loss in this drive
    EXPECT_EQ(r.flagged, 0) << "skew " << skew;
    EXPECT_LT(r.pos_err, 0.01) << skew;
    EXPECT_LT(r.heading_err, mrt::common::deg_to_rad(0.5)) << skew;
  }
}

TEST(PhysicalMice, WithoutAlignmentTheSkewRaisesFalseAlarms) {
  // The same drives summing each sample's reports: the test above can fail.
  for (double skew : {0.002, 0.004}) {
    const Result r = run(skew, false);
    std::printf("not aligned, skew %.0f ms: %ld of %ld flagged\n", skew * 1e3, r.flagged, r.samples);
    EXPECT_GT(r.flagged, r.samples / 10) << "skew " << skew;
  }
}
