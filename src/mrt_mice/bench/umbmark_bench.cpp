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

// UMBmark (5 clockwise and 5 counter-clockwise squares) of the odometries
// `a` and `b` (and `c` when given): E_max,syst of each, mm.
std::vector<double> run_umbmark(const sim::SimMice& mice, int seed, std::vector<MiceOdometry*> odos) {
  std::vector<std::vector<Pose2D>> cw(odos.size()), ccw(odos.size());
  for (int run = 0; run < 10; ++run) {
    const bool clockwise = run < 5;
    const auto e = run_square(seed + run, clockwise, mice, odos, nullptr);
    for (std::size_t k = 0; k < odos.size(); ++k) (clockwise ? cw[k] : ccw[k]).push_back(e[k]);
  }
  std::vector<double> out;
  for (std::size_t k = 0; k < odos.size(); ++k) out.push_back(e_max_syst(cw[k], ccw[k]) * 1000.0);
  return out;
}

// Slip detection: squares with slips injected in 5 % of the samples (a
// mouse blind for 20-100 % of a sample).
Slips slip_runs(const sim::SimMice& mice, const MiceParams& params, int seed, int runs) {
  Slips slips;
  slips.rate = 0.05;
  for (int run = 0; run < runs; ++run) {
    MiceOdometry o(params);
    run_square(seed + run, run % 2 == 0, mice, {&o}, &slips);
  }
  return slips;
}

// The manual's Fig. 4.1 layout: mice side by side 20 cm apart, with the
// same kind of systematic errors. Straight runs and turns in place move both
// mice across their joining line, where the constraint sees nothing.
struct SideBySide {
  sim::SimMice mice;
  MiceParams nominal;
};
SideBySide side_by_side(double noise) {
  SideBySide s;
  s.mice.truth.left.mount = Pose2D(0.004, 0.097, deg_to_rad(1.5));
  s.mice.truth.right.mount = Pose2D(-0.003, -0.104, deg_to_rad(-2.0));
  s.mice.truth.left.counts_per_m = 15748.0 * 1.012;
  s.mice.truth.right.counts_per_m = 15748.0 * 0.985;
  s.mice.noise = noise;
  s.nominal.left.mount = Pose2D(0.0, 0.1, 0.0);
  s.nominal.right.mount = Pose2D(0.0, -0.1, 0.0);
  s.nominal.left.counts_per_m = s.nominal.right.counts_per_m = 15748.0;
  return s;
}

// The simulator's own faults (a mouse loses up to half of single 1 ms
// steps, most of them smaller than one count): how many are flagged.
std::pair<long, long> sim_faults(const sim::SimMice& mice, const MiceParams& params) {
  sim::SimMice faulty = mice;
  faulty.fault_rate = 0.002;
  long faults = 0, flagged = 0;
  mrt::sim::Simulator s(sim::make_world(faulty, 3000));
  MiceOdometry o(params);
  auto on = [&](const mrt::sim::RobotState& r) {
    const bool f = o.update(sim::to_counts(r.mice)).detection.flagged;
    if (r.mice.left_fault || r.mice.right_fault) {
      ++faults;
      flagged += f;
    }
  };
  sim::drive(s, {kSpeed, 0.0, 0.0}, 40000, on);
  return {faults, flagged};
}

// The same robot with mrt_sim's physical mouse model instead of the ideal
// one (the estimator's exact inverse): each mouse reports at 125 Hz on its
// own clock (the right one 5 ms later and 100 ppm fast; the reports aligned
// by CountAligner as in mice_evdev_node) and loses track above 1 m/s or 15 g
// (the simulated base jumps to each leg's speed within 1 ms: 51 g at
// 0.5 m/s, so the first 1 ms step of every leg is lost, and of every
// calibration push and turn). With `floor`, also a carpet (resolution
// 0.97) over x in [2, 6] m, |y| >= 0.5 m (most of the squares' far half) and
// a 5 cm strip 3 mm lower (above the 2 mm lift-off: blind over it, the front
// mouse first) across the far leg of each square at |y| = 2 m; the
// calibration pushes and turns (along y = 0) stay on plain floor.
sim::SimMice physical(const sim::SimMice& ideal, bool floor) {
  sim::SimMice m = ideal;
  for (auto& p : m.physics) {
    p.enabled = true;
    p.report_rate = 125.0;
  }
  m.physics[1].phase = 0.005;
  m.physics[1].drift_ppm = 100.0;
  if (!floor) return m;
  auto patch = [](const char* name, double x0, double y0, double x1, double y1, double res, double clear) {
    mrt::sim::Surface s;
    s.name = name;
    s.min_x = x0, s.min_y = y0, s.max_x = x1, s.max_y = y1;
    s.resolution = res;
    s.clearance = clear;
    return s;
  };
  m.surfaces = {patch("carpet", 2.0, 0.5, 6.0, 6.0, 0.97, 0.0), patch("carpet", 2.0, -6.0, 6.0, -0.5, 0.97, 0.0),
                patch("dip", 3.0, 2.0, 5.0, 2.05, 1.0, 0.003), patch("dip", 3.0, -2.05, 5.0, -2.0, 1.0, 0.003)};
  return m;
}

struct PhysicalFigures {
  double before = 0.0, after = 0.0, rms = 0.0;
  Slips slips;
};

// UMBmark, calibration and slips of the physical model (same seeds as the ideal one).
PhysicalFigures physical_figures(const sim::SimMice& ideal, bool floor) {
  const sim::SimMice phys = physical(ideal, floor);
  PhysicalFigures f;
  const CalibrationResult calib = calibrate_as_operator(phys, 99, nominal());
  MiceOdometry before(nominal()), after(calib.params);
  const std::vector<double> e = run_umbmark(phys, 1000, {&after, &before});
  f.after = e[0];
  f.before = e[1];
  f.rms = calib.rms_residual;
  f.slips = slip_runs(phys, calib.params, 2000, 4);
  return f;
}

// Cost of one sample through the whole chain, ns.
double update_cost(const MiceParams& params) {
  MiceOdometry perf(params);
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
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / n;
}

double fraction(long part, long whole) { return whole ? static_cast<double>(part) / whole : 0.0; }

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
  const std::vector<double> e = run_umbmark(mice, 1000, {&after, &before, &before_raw});
  const double ea = e[0], eb = e[1], er = e[2];
  const Slips slips = slip_runs(mice, calib.params, 2000, 4);

  // Side by side: UMBmark before and after calibration, and the same slips.
  const SideBySide side = side_by_side(mice.noise);
  const CalibrationResult side_calib = calibrate_as_operator(side.mice, 98, side.nominal);
  MiceOdometry side_before(side.nominal), side_after(side_calib.params);
  const std::vector<double> se = run_umbmark(side.mice, 1100, {&side_after, &side_before});
  const double sa = se[0], sb = se[1];
  const Slips side_slips = slip_runs(side.mice, side_calib.params, 2100, 2);

  // The physical mouse model, same protocol and seeds: clocks and limits
  // only, then with the floor.
  const PhysicalFigures pc = physical_figures(mice, false), pf = physical_figures(mice, true);

  const auto [faults, flagged] = sim_faults(mice, calib.params);
  const double ns = update_cost(calib.params);

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
  std::printf("slips_detected_fraction: %.4f ratio\n", fraction(slips.detected, slips.injected));
  std::printf("slips_detected_fraction_side_by_side_mice: %.4f ratio\n",
              fraction(side_slips.detected, side_slips.injected));
  std::printf("false_alarm_fraction: %.5f ratio\n", fraction(slips.false_alarms, slips.clean));
  std::printf("sim_step_faults_detected_fraction: %.4f ratio\n", fraction(flagged, faults));
  for (const auto& [name, f] : {std::pair<const char*, const PhysicalFigures&>{"physical", pc},
                                 std::pair<const char*, const PhysicalFigures&>{"physical_floor", pf}}) {
    std::printf("%s_umbmark_e_max_syst_before_calibration: %.1f mm\n", name, f.before);
    std::printf("%s_umbmark_e_max_syst_after_calibration: %.1f mm\n", name, f.after);
    std::printf("%s_vs_ideal_ratio: %.4f ratio\n", name, f.after / ea);
    std::printf("%s_calibration_rms_residual: %.2f counts\n", name, f.rms);
    std::printf("%s_slips_detected_fraction: %.4f ratio\n", name, fraction(f.slips.detected, f.slips.injected));
    std::printf("%s_false_alarm_fraction: %.5f ratio\n", name, fraction(f.slips.false_alarms, f.slips.clean));
  }
  std::printf("odometry_update_time: %.1f ns\n", ns);
  std::printf("bench_wall_time: %.2f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count());
  return 0;
}
