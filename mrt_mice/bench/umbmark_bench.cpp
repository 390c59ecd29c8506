// UMBmark (Borenstein & Feng) of the two-mouse odometry in mrt_sim: a 4 m
// square driven 5 times clockwise and 5 times counter-clockwise by an IANUS3
// (open loop: the simulator is commanded the square and the odometry's
// final pose is compared with the ground truth; the original protocol
// drives the robot by its odometry back to the start and measures where it
// really stopped, the same error seen from the other side)
// whose mice have realistic systematic errors (resolutions 1-2 % off the
// nominal 400 cpi, placement a few mm and degrees off the drawing). The
// odometry runs with the nominal parameters (before calibration) and with
// those estimated by the calibration of manual §4.2 run in the same
// simulator (after). Prints E_max,syst for both, the published figure of
// the original sensor, and how many injected slips the detector flags.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_mice/calibrator.h"
#include "mrt_mice/mice_odometry.h"
#include "umbmark.h"

using namespace mrt::mice;
using namespace mrt::mice::umbmark;
using mrt::common::deg_to_rad;

namespace {

constexpr double kPublished = 114.0;  // mm, Bonarini, Matteucci, Restelli, ICINCO 2004

}  // namespace

int main() {
  const auto t_start = std::chrono::steady_clock::now();
  const sim::SimMice mice = as_built(0.003);

  // Calibration: the protocol of §4.2 in the same simulator, by a careful
  // person (pushes within +-2 mm, turns within +-0.3 degrees, 1 sigma).
  const CalibrationResult calib = calibrate_as_operator(mice, 99, nominal());

  OdometryOptions raw;
  raw.reduce_errors = false;
  MiceOdometry before(nominal()), before_raw(nominal(), raw), after(calib.params);
  std::vector<Pose2D> cw_b, ccw_b, cw_r, ccw_r, cw_a, ccw_a;
  for (int run = 0; run < 10; ++run) {
    const bool clockwise = run < 5;
    const auto e = run_square(1000 + run, clockwise, mice, {&after, &before, &before_raw}, nullptr);
    (clockwise ? cw_a : ccw_a).push_back(e[0]);
    (clockwise ? cw_b : ccw_b).push_back(e[1]);
    (clockwise ? cw_r : ccw_r).push_back(e[2]);
  }
  const double eb = e_max_syst(cw_b, ccw_b) * 1000.0, ea = e_max_syst(cw_a, ccw_a) * 1000.0;
  const double er = e_max_syst(cw_r, ccw_r) * 1000.0;

  // Slip detection: the same square with slips injected in 5 % of the
  // samples (a mouse blind for 20-100 % of a sample), calibrated parameters.
  Slips slips;
  slips.rate = 0.05;
  for (int run = 0; run < 4; ++run) {
    MiceOdometry o(calib.params);
    run_square(2000 + run, run % 2 == 0, mice, {&o}, &slips);
  }
  // The manual's Fig. 4.1 layout: mice side by side 20 cm apart, with the
  // same kind of systematic errors; UMBmark before and after calibration,
  // and the same slips. Straight runs and turns in place move both mice
  // across their joining line, where the constraint sees nothing.
  sim::SimMice side;
  side.truth.left.mount = Pose2D(0.004, 0.097, deg_to_rad(1.5));
  side.truth.right.mount = Pose2D(-0.003, -0.104, deg_to_rad(-2.0));
  side.truth.left.counts_per_m = 15748.0 * 1.012;
  side.truth.right.counts_per_m = 15748.0 * 0.985;
  side.noise = mice.noise;
  MiceParams side_nominal;
  side_nominal.left.mount = Pose2D(0.0, 0.1, 0.0);
  side_nominal.right.mount = Pose2D(0.0, -0.1, 0.0);
  side_nominal.left.counts_per_m = side_nominal.right.counts_per_m = 15748.0;
  const CalibrationResult side_calib = calibrate_as_operator(side, 98, side_nominal);
  double sb, sa;
  {
    MiceOdometry b(side_nominal), a(side_calib.params);
    std::vector<Pose2D> cwb, ccwb, cwa, ccwa;
    for (int run = 0; run < 10; ++run) {
      const bool clockwise = run < 5;
      const auto e = run_square(1100 + run, clockwise, side, {&a, &b}, nullptr);
      (clockwise ? cwa : ccwa).push_back(e[0]);
      (clockwise ? cwb : ccwb).push_back(e[1]);
    }
    sb = e_max_syst(cwb, ccwb) * 1000.0;
    sa = e_max_syst(cwa, ccwa) * 1000.0;
  }
  Slips side_slips;
  side_slips.rate = 0.05;
  for (int run = 0; run < 2; ++run) {
    MiceOdometry o(side_calib.params);
    run_square(2100 + run, run % 2 == 0, side, {&o}, &side_slips);
  }
  // The simulator's own faults (a mouse loses up to half of single 1 ms
  // steps, most of them smaller than one count).
  sim::SimMice faulty = mice;
  faulty.fault_rate = 0.002;
  long sim_faults = 0, sim_flagged = 0;
  {
    mrt::sim::Simulator s(sim::make_world(faulty, 3000));
    MiceOdometry o(calib.params);
    auto on = [&](const mrt::sim::RobotState& r) {
      const bool f = o.update(sim::to_counts(r.mice)).detection.flagged;
      if (r.mice.left_fault || r.mice.right_fault) {
        ++sim_faults;
        sim_flagged += f;
      }
    };
    sim::drive(s, {kSpeed, 0.0, 0.0}, 40000, on);
  }

  // Cost of one sample through the whole chain.
  MiceOdometry perf(calib.params);
  MiceCounts c;
  const int n = 2000000;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    c.left_dx = 150 + (i & 3);
    c.left_dy = 3 - (i & 1);
    c.right_dx = 149 + (i & 1);
    c.right_dy = -2 + (i & 3);
    perf.update(c);
  }
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / n;

  std::printf("umbmark_e_max_syst_before_calibration: %.1f mm\n", eb);
  std::printf("umbmark_e_max_syst_before_calibration_no_reduction: %.1f mm\n", er);
  std::printf("umbmark_e_max_syst_after_calibration: %.1f mm\n", ea);
  std::printf("umbmark_e_max_syst_published: %.1f mm\n", kPublished);
  std::printf("umbmark_side_by_side_e_max_syst_before_calibration: %.1f mm\n", sb);
  std::printf("umbmark_side_by_side_e_max_syst_after_calibration: %.1f mm\n", sa);
  std::printf("umbmark_calibration_ratio: %.4f ratio\n", ea / eb);
  std::printf("umbmark_vs_published_ratio: %.4f ratio\n", ea / kPublished);
  std::printf("calibration_rms_residual: %.2f counts\n", calib.rms_residual);
  std::printf("slips_injected: %ld count\n", slips.injected);
  std::printf("slips_detected_fraction: %.4f ratio\n",
              slips.injected ? static_cast<double>(slips.detected) / slips.injected : 0.0);
  std::printf("slips_detected_fraction_side_by_side_mice: %.4f ratio\n",
              side_slips.injected ? static_cast<double>(side_slips.detected) / side_slips.injected : 0.0);
  std::printf("false_alarm_fraction: %.5f ratio\n",
              slips.clean ? static_cast<double>(slips.false_alarms) / slips.clean : 0.0);
  std::printf("sim_step_faults_detected_fraction: %.4f ratio\n",
              sim_faults ? static_cast<double>(sim_flagged) / sim_faults : 0.0);
  std::printf("odometry_update_time: %.1f ns\n", ns);
  std::printf("bench_wall_time: %.2f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count());
  return 0;
}
