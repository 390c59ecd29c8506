// murea_bench: global localization from one frame of simulated percepts
// (field-line points and unnamed goals) on the 18 x 12 m MSL field, over N
// random poses; then the first M of them by exhaustive evaluation of the
// lattice (identical best evidence asserted) for the speed-up.
// Usage: murea_bench [N=1000] [M=3] [world=<package>/test/data/msl_field.yaml] [tracking_s=300]
// Then tracking, kidnapping and the MCL baseline (bench_tracking.cpp), and
// a laser robot in the museum, MUREA and MCL on the same scans (bench_laser.cpp),
// the cost of staying ambiguous before and after carrying the modes (bench_ambiguous.cpp).
// Two noise levels: "global" (1 cm + 1 %, 0.01 rad, 5 m, 2 spurious
// points) and "global_sim_noise" (the simulator's 2 %, 0.01 rad, 6 m, 10).
// Prints `name: value unit` lines.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_murea/localizer.h"
#include "bench_common.h"
#include "mrt_common/cli.h"
#include "mrt_sim/world.h"

using mrt::common::angle_diff;
using mrt::common::kPi;
using mrt::murea::FeatureClass;
using mrt::murea::Percept;

namespace {

using namespace mrt::murea::bench;

struct Frame {
  mrt::common::Pose2D truth;
  std::vector<Percept> percepts;
  mrt::murea::Result result;
};

// Localizes n random poses of the field; prints the metrics prefixed by `name`.
std::vector<Frame> run(const std::string& name, const mrt::sim::World& world, const mrt::murea::Localizer& loc,
                       const Noise& nz, int n) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> ux(-9.0, 9.0), uy(-6.0, 6.0), ut(-kPi, kPi);
  std::vector<double> times, cpu, cells, sizes, err_xy, err_t, est_xy, est_t;
  std::vector<Frame> frames;
  int correct = 0, flagged = 0, timeouts = 0;
  mrt::cli::Progress progress("murea_bench " + name, n);
  for (int i = 0; i < n; ++i) {
    progress.update(i);
    Frame f;
    f.truth = mrt::common::Pose2D(ux(rng), uy(rng), ut(rng));
    const mrt::common::Pose2D mirror(-f.truth.x, -f.truth.y, f.truth.theta + kPi);
    f.percepts = simulate(world, f.truth, nz, rng);
    f.result = loc.localize(f.percepts);
    const mrt::murea::Result& r = f.result;
    times.push_back(r.time_ms);
    cpu.push_back(r.cpu_ms);
    cells.push_back(static_cast<double>(r.cells));
    sizes.push_back(static_cast<double>(f.percepts.size()));
    timeouts += r.complete ? 0 : 1;
    flagged += r.ambiguous ? 1 : 0;
    const bool on_truth = near(r.best.pose, f.truth);
    const mrt::common::Pose2D& ref = on_truth ? f.truth : mirror;
    const bool alt_ok = r.alternative && near(r.alternative->pose, on_truth ? mirror : f.truth);
    if ((on_truth || near(r.best.pose, mirror)) && alt_ok) ++correct;
    err_xy.push_back(std::hypot(r.best.pose.x - ref.x, r.best.pose.y - ref.y));
    err_t.push_back(mrt::common::rad_to_deg(std::abs(angle_diff(r.best.pose.theta, ref.theta))));
    est_xy.push_back(std::hypot(r.estimate.mean.x - ref.x, r.estimate.mean.y - ref.y));
    est_t.push_back(mrt::common::rad_to_deg(std::abs(angle_diff(r.estimate.mean.theta, ref.theta))));
    frames.push_back(std::move(f));
  }
  progress.finish();
  const double pct = 100.0 / std::max(1, n);
  std::cout << name << "_poses: " << n << " count\n"
            << name << "_correct_and_flagged_ambiguous: " << correct * pct << " %\n"
            << name << "_ambiguous_flagged: " << flagged * pct << " %\n"
            << name << "_timeouts: " << timeouts << " count\n"
            << name << "_percepts_per_frame_median: " << percentile(sizes, 0.5) << " count\n"
            << name << "_time_median: " << percentile(times, 0.5) << " ms\n"
            << name << "_time_p95: " << percentile(times, 0.95) << " ms\n"
            << name << "_time_max: " << percentile(times, 1.0) << " ms\n"
            << name << "_cpu_time_median: " << percentile(cpu, 0.5) << " ms\n"
            << name << "_cpu_time_p95: " << percentile(cpu, 0.95) << " ms\n"
            << name << "_cpu_time_max: " << percentile(cpu, 1.0) << " ms\n"
            << name << "_cells_median: " << percentile(cells, 0.5) << " count\n"
            << name << "_error_xy_median: " << percentile(err_xy, 0.5) << " m\n"
            << name << "_error_xy_p95: " << percentile(err_xy, 0.95) << " m\n"
            << name << "_error_theta_median: " << percentile(err_t, 0.5) << " deg\n"
            << name << "_error_theta_p95: " << percentile(err_t, 0.95) << " deg\n"
            << name << "_plateau_mean_error_xy_median: " << percentile(est_xy, 0.5) << " m\n"
            << name << "_plateau_mean_error_xy_p95: " << percentile(est_xy, 0.95) << " m\n"
            << name << "_plateau_mean_error_theta_median: " << percentile(est_t, 0.5) << " deg\n"
            << name << "_plateau_mean_error_theta_p95: " << percentile(est_t, 0.95) << " deg\n";
  return frames;
}

// Accuracy versus timeout: the anytime search cut at 1 ... 20 ms on the
// first frames of a run; a pose is correct within 0.3 m and 10 degrees of
// the truth or of its mirror.
// `cpu`: the deadline counts the thread's CPU time (one core's budget,
// independent of the machine's load); else wall-clock time.
void timeout_table(const mrt::murea::FeatureMap& map, const std::vector<Frame>& frames, bool cpu) {
  const std::size_t count = std::min<std::size_t>(frames.size(), 200);
  const std::string prefix = cpu ? "timeout_cpu_" : "timeout_";
  for (const double ms : {1.0, 2.0, 5.0, 10.0, 20.0}) {
    mrt::murea::SearchOptions opt;
    opt.timeout = ms / 1000.0;
    opt.timeout_cpu = cpu;
    const mrt::murea::Localizer loc(map, opt);
    int correct = 0, complete = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const Frame& f = frames[i];
      const mrt::murea::Result r = loc.localize(f.percepts);
      const mrt::common::Pose2D mirror(-f.truth.x, -f.truth.y, f.truth.theta + kPi);
      correct += near(r.best.pose, f.truth) || near(r.best.pose, mirror) ? 1 : 0;
      complete += r.complete ? 1 : 0;
    }
    const double pct = 100.0 / std::max<std::size_t>(1, count);
    std::cout << prefix << ms << "ms_correct: " << correct * pct << " %\n"
              << prefix << ms << "ms_complete: " << complete * pct << " %\n";
  }
}

// A preview of tracking's cost: the same frames searched only in a window
// of +-0.3 m and +-10 deg around a prediction off the truth by an odometry
// error (5 cm and 2 deg standard deviations).
void window_run(const mrt::murea::FeatureMap& map, const std::vector<Frame>& frames) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<double> times, cpu, err;
  int correct = 0;
  const std::size_t count = std::min<std::size_t>(frames.size(), 200);
  for (std::size_t i = 0; i < count; ++i) {
    const Frame& f = frames[i];
    const double px = f.truth.x + 0.05 * n01(rng), py = f.truth.y + 0.05 * n01(rng);
    const double pt = f.truth.theta + mrt::common::deg_to_rad(2) * n01(rng), w = mrt::common::deg_to_rad(10);
    mrt::murea::SearchOptions opt;
    opt.region = std::array<double, 4>{px - 0.3, py - 0.3, px + 0.3, py + 0.3};
    opt.heading_range = std::array<double, 2>{pt - w, pt + w};
    const mrt::murea::Result r = mrt::murea::Localizer(map, opt).localize(f.percepts);
    times.push_back(r.time_ms);
    cpu.push_back(r.cpu_ms);
    err.push_back(std::hypot(r.estimate.mean.x - f.truth.x, r.estimate.mean.y - f.truth.y));
    correct += near(r.estimate.mean, f.truth) ? 1 : 0;
  }
  std::cout << "window_correct: " << 100.0 * correct / std::max<std::size_t>(1, count) << " %\n"
            << "window_time_median: " << percentile(times, 0.5) << " ms\n"
            << "window_time_p95: " << percentile(times, 0.95) << " ms\n"
            << "window_cpu_time_median: " << percentile(cpu, 0.5) << " ms\n"
            << "window_cpu_time_p95: " << percentile(cpu, 0.95) << " ms\n"
            << "window_error_xy_median: " << percentile(err, 0.5) << " m\n";
}

}  // namespace

int main(int argc, char** argv) {
  int n = 1000, m = 3;
  std::string file = std::string(MRT_MUREA_DATA) + "/msl_field.yaml";
  CLI::App app{"MUREA benchmark: prints `metric: value unit` lines.", "murea_bench"};
  app.add_option("poses", n, "random poses localized (count), default 1000")->check(CLI::PositiveNumber);
  app.add_option("repeats", m, "repetitions (count), default 3")->check(CLI::PositiveNumber);
  app.add_option("world", file, "world file (YAML), default test/data/msl_field.yaml");
  double seconds = 300.0;
  app.add_option("tracking_s", seconds, "length of the tracking runs (s), default 300")->check(CLI::PositiveNumber);
  std::string laser_world = std::string(MRT_WORLD_WORLDS) + "/museum.yaml";
  int laser_trials = 50;
  bool laser_only = false;
  app.add_flag("--laser-only", laser_only, "run only the laser part (bench_laser.cpp)");
  bool ambiguous_only = false;
  app.add_flag("--ambiguous-only", ambiguous_only, "run only the ambiguity part (bench_ambiguous.cpp)");
  app.add_option("--laser-world", laser_world, "world of the laser runs (walls), default mrt_world's museum.yaml");
  app.add_option("--laser-trials", laser_trials, "random poses of the laser global fixes (count), default 50")
      ->check(CLI::NonNegativeNumber);
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  if (laser_only) {
    mrt::murea::bench::laser_benchmarks(laser_world, seconds, laser_trials);
    return 0;
  }
  mrt::sim::World world = mrt::sim::load_world(file);
  world.movers.clear();
  world.ball.enabled = false;
  const mrt::murea::FeatureMap map(world);
  const mrt::murea::Localizer loc(map, mrt::murea::SearchOptions{});  // 5 cm, 1 degree
  if (ambiguous_only) {
    mrt::murea::bench::ambiguous_benchmarks(world, map);
    return 0;
  }

  const std::vector<Frame> frames = run("global", world, loc, Noise{}, n);
  // The simulator's own default camera noise (2 % of the distance, 0.01
  // rad), its 6 m range, and 10 spurious points per frame.
  run("global_sim_noise", world, loc, Noise{6.0, 0.0, 0.02, 0.01, 10}, n);
  timeout_table(map, frames, false);
  timeout_table(map, frames, true);
  window_run(map, frames);
  tracking_benchmarks(world, map, seconds);
  mrt::murea::bench::laser_benchmarks(laser_world, seconds, laser_trials);
  mrt::murea::bench::ambiguous_benchmarks(world, map);

  double t_search = 0.0, t_exh = 0.0, c_search = 0.0, c_exh = 0.0;
  int identical = 0;
  const int checked = std::min(m, n);
  mrt::cli::Progress progress("murea_bench exhaustive", checked);
  for (int i = 0; i < checked; ++i) {
    progress.update(i);
    const double c0 = thread_cpu_ms();
    const mrt::murea::Result e = loc.exhaustive(frames[i].percepts);
    c_exh += thread_cpu_ms() - c0;
    t_exh += e.time_ms;
    t_search += frames[i].result.time_ms;
    c_search += frames[i].result.cpu_ms;
    if (e.best.evidence == frames[i].result.best.evidence) ++identical;
    else std::cerr << "NOT EXACT: frame " << i << " search " << frames[i].result.best.evidence << " exhaustive "
                   << e.best.evidence << '\n';
  }
  progress.finish();
  std::cout << "exhaustive_checked: " << checked << " count\n"
            << "exhaustive_identical_best_evidence: " << identical << " count\n"
            << "exhaustive_time_mean: " << t_exh / std::max(1, checked) << " ms\n"
            << "speedup_vs_exhaustive: " << (t_search > 0 ? t_exh / t_search : 0.0) << " x\n"
            << "exhaustive_cpu_time_mean: " << c_exh / std::max(1, checked) << " ms\n"
            << "speedup_vs_exhaustive_cpu: " << (c_search > 0 ? c_exh / c_search : 0.0) << " x\n";
  return identical == checked ? 0 : 1;
}
