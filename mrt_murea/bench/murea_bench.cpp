// murea_bench: global localization from one frame of simulated percepts
// (field-line points and unnamed goals) on the 18 x 12 m MSL field, over N
// random poses; then the first M of them by exhaustive evaluation of the
// lattice (identical best evidence asserted) for the speed-up.
// Usage: murea_bench [N=1000] [M=3] [world=<package>/test/data/msl_field.yaml] [tracking_s=300]
// Then tracking along a figure eight (tracking_run).
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
#include "mrt_murea/tracker.h"
#include "mrt_common/cli.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

using mrt::common::angle_diff;
using mrt::common::kPi;
using mrt::murea::FeatureClass;
using mrt::murea::Percept;

namespace {

// How the simulated camera errs.
struct Noise {
  double range = 5.0;        // m, vision range
  double sigma_d0 = 0.01;    // m, distance noise: sigma_d0 + sigma_d1 * distance
  double sigma_d1 = 0.01;
  double sigma_b = 0.01;     // rad, bearing noise
  int spurious = 2;          // random line points added per frame
};

// What the robot's camera would report at `pose`: the simulator's vision
// percepts (occlusion by goals included), only Line and Goal (colour
// removed), within noise.range; Gaussian distance and bearing noise;
// reliability falling with range; spurious line points at random.
std::vector<Percept> simulate(const mrt::sim::World& w, const mrt::common::Pose2D& pose, const Noise& nz,
                              std::mt19937_64& rng) {
  mrt::sim::SensorsConfig cfg;
  cfg.vision_range = nz.range;
  cfg.line_point_spacing = 0.25;
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<Percept> out;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, pose, cfg)) {
    const auto cls = mrt::murea::parse_feature_class(s.membership_class);
    if (!cls || (*cls != FeatureClass::Line && *cls != FeatureClass::Goal)) continue;
    const double r = std::max(0.0, s.distance + (nz.sigma_d0 + nz.sigma_d1 * s.distance) * n01(rng));
    const double rel = *cls == FeatureClass::Goal ? 0.8 : std::max(0.3, 1.0 - 0.1 * s.distance);
    out.push_back({*cls, "", r, s.bearing + nz.sigma_b * n01(rng), rel});
  }
  std::uniform_real_distribution<double> range(0.5, nz.range), bearing(-kPi, kPi);
  for (int i = 0; i < nz.spurious; ++i) out.push_back({FeatureClass::Line, "", range(rng), bearing(rng), 0.3});
  return out;
}

bool near(const mrt::common::Pose2D& a, const mrt::common::Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y) <= 0.3 && std::abs(angle_diff(a.theta, b.theta)) <= mrt::common::deg_to_rad(10);
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))];
}

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
  std::vector<double> times, cells, sizes, err_xy, err_t, est_xy, est_t;
  std::vector<Frame> frames;
  int correct = 0, flagged = 0, timeouts = 0;
  for (int i = 0; i < n; ++i) {
    Frame f;
    f.truth = mrt::common::Pose2D(ux(rng), uy(rng), ut(rng));
    const mrt::common::Pose2D mirror(-f.truth.x, -f.truth.y, f.truth.theta + kPi);
    f.percepts = simulate(world, f.truth, nz, rng);
    f.result = loc.localize(f.percepts);
    const mrt::murea::Result& r = f.result;
    times.push_back(r.time_ms);
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
  const double pct = 100.0 / std::max(1, n);
  std::cout << name << "_poses: " << n << " count\n"
            << name << "_correct_and_flagged_ambiguous: " << correct * pct << " %\n"
            << name << "_ambiguous_flagged: " << flagged * pct << " %\n"
            << name << "_timeouts: " << timeouts << " count\n"
            << name << "_percepts_per_frame_median: " << percentile(sizes, 0.5) << " count\n"
            << name << "_time_median: " << percentile(times, 0.5) << " ms\n"
            << name << "_time_p95: " << percentile(times, 0.95) << " ms\n"
            << name << "_time_max: " << percentile(times, 1.0) << " ms\n"
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
void timeout_table(const mrt::murea::FeatureMap& map, const std::vector<Frame>& frames) {
  const std::size_t count = std::min<std::size_t>(frames.size(), 200);
  for (const double ms : {1.0, 2.0, 5.0, 10.0, 20.0}) {
    mrt::murea::SearchOptions opt;
    opt.timeout = ms / 1000.0;
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
    std::cout << "timeout_" << ms << "ms_correct: " << correct * pct << " %\n"
              << "timeout_" << ms << "ms_complete: " << complete * pct << " %\n";
  }
}

// A preview of tracking's cost: the same frames searched only in a window
// of +-0.3 m and +-10 deg around a prediction off the truth by an odometry
// error (5 cm and 2 deg standard deviations).
void window_run(const mrt::murea::FeatureMap& map, const std::vector<Frame>& frames) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<double> times, err;
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
    err.push_back(std::hypot(r.estimate.mean.x - f.truth.x, r.estimate.mean.y - f.truth.y));
    correct += near(r.estimate.mean, f.truth) ? 1 : 0;
  }
  std::cout << "window_correct: " << 100.0 * correct / std::max<std::size_t>(1, count) << " %\n"
            << "window_time_median: " << percentile(times, 0.5) << " ms\n"
            << "window_time_p95: " << percentile(times, 0.95) << " ms\n"
            << "window_error_xy_median: " << percentile(err, 0.5) << " m\n";
}

}  // namespace

// Tracking: the robot runs a figure eight over the field (x = 6 sin(wt),
// y = 3 sin(2wt), w = 0.4 rad/s: up to 3.4 m/s), its heading the direction
// of travel plus 0.6 sin(1.3 t) (omnidirectional base, turns up to about
// 2 rad/s); 30 Hz percept frames with the simulator's noise; odometry = the
// true motion between frames with 3 % translation and 2 % + 0.01 rad/m
// heading noise; the tracker starts from the true pose (initialpose).
// Prints RMSE, worst error, update time (median, p95), global re-searches.
// `outliers`: that fraction of each frame's percepts replaced by the same
// class at a random distance (0.5 to 6 m) and bearing.
void tracking_run(const std::string& name, const mrt::sim::World& world, const mrt::murea::FeatureMap& map,
                  double seconds, double outliers) {
  std::mt19937_64 rng(15);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double w = 0.4, dt = 1.0 / 30.0;
  auto truth_at = [&](double t) {
    const double vx = 6 * w * std::cos(w * t), vy = 6 * w * std::cos(2 * w * t);
    return mrt::common::Pose2D(6 * std::sin(w * t), 3 * std::sin(2 * w * t), std::atan2(vy, vx) + 0.6 * std::sin(1.3 * t));
  };
  mrt::murea::TrackerOptions opt;
  mrt::murea::Tracker tracker(map, opt);
  mrt::common::Pose2D prev = truth_at(0.0);
  tracker.set_pose(prev, {1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4});
  std::vector<double> ms, err;
  double sum_d2 = 0, sum_t2 = 0, worst = 0, max_speed = 0, max_turn = 0;
  int globals = 0;
  const int frames = static_cast<int>(seconds / dt);
  for (int i = 1; i <= frames; ++i) {
    const mrt::common::Pose2D truth = truth_at(i * dt);
    const mrt::common::Pose2D d = prev.inverse() * truth;
    max_speed = std::max(max_speed, std::hypot(d.x, d.y) / dt);
    max_turn = std::max(max_turn, std::abs(d.theta) / dt);
    const double dist = std::hypot(d.x, d.y), st = 0.02 * std::abs(d.theta) + 0.01 * dist;
    const mrt::common::Pose2D odo(d.x * (1 + 0.03 * n01(rng)), d.y * (1 + 0.03 * n01(rng)), d.theta + st * n01(rng));
    const double sxy = 0.03 * dist + 1e-4;
    tracker.predict(odo, {sxy * sxy, 0, 0, 0, sxy * sxy, 0, 0, 0, st * st + 1e-8});
    prev = truth;
    std::vector<Percept> ps = simulate(world, truth, Noise{6.0, 0.0, 0.02, 0.01, 10}, rng);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (Percept& p : ps)
      if (u01(rng) < outliers) {
        p.distance = 0.5 + 5.5 * u01(rng);
        p.bearing = kPi * (2 * u01(rng) - 1);
      }
    const auto t0 = std::chrono::steady_clock::now();
    const mrt::murea::TrackResult r = tracker.update(ps);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (r.mode == mrt::murea::TrackMode::Global) ++globals;
    const double e = std::hypot(r.pose.x - truth.x, r.pose.y - truth.y), et = angle_diff(r.pose.theta, truth.theta);
    sum_d2 += e * e;
    sum_t2 += et * et;
    worst = std::max(worst, e);
  }
  std::cout << name << "_frames: " << frames << " count\n"
            << name << "_max_speed: " << max_speed << " m/s\n"
            << name << "_max_turn_rate: " << max_turn << " rad/s\n"
            << name << "_rmse_xy: " << 100 * std::sqrt(sum_d2 / frames) << " cm\n"
            << name << "_rmse_theta: " << std::sqrt(sum_t2 / frames) * 180 / kPi << " deg\n"
            << name << "_worst_xy: " << 100 * worst << " cm\n"
            << name << "_update_median: " << percentile(ms, 0.5) << " ms\n"
            << name << "_update_p95: " << percentile(ms, 0.95) << " ms\n"
            << name << "_global_searches: " << globals << " count\n";
}

// Kidnapping: 100 trials; tracking at a random pose, the robot is carried
// to another random pose (no odometry); 30 Hz frames of the simulator's
// percepts with their colours (named goals, coloured corner posts) and its
// noise; recovered = the estimate within 0.3 m / 10 deg of the new pose
// within 30 frames (1 s).
void kidnap_run(const mrt::sim::World& world, const mrt::murea::FeatureMap& map) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> ux(-8.5, 8.5), uy(-5.5, 5.5), ut(-kPi, kPi);
  std::normal_distribution<double> n01(0.0, 1.0);
  mrt::sim::SensorsConfig cfg;
  cfg.vision_range = 6.0;
  cfg.line_point_spacing = 0.25;
  auto frame = [&](const mrt::common::Pose2D& pose) {
    std::vector<Percept> out;
    for (const auto& s : mrt::sim::vision_percepts(world, {}, pose, cfg)) {
      const auto cls = mrt::murea::parse_feature_class(s.membership_class);
      if (cls) out.push_back({*cls, s.color, s.distance * (1 + 0.02 * n01(rng)), s.bearing + 0.01 * n01(rng), 1.0});
    }
    return out;
  };
  int recovered = 0, lost = 0, wrong = 0, ambiguous = 0;
  std::vector<double> frames_needed;
  for (int trial = 0; trial < 100; ++trial) {
    mrt::murea::Tracker t(map, mrt::murea::TrackerOptions{});
    const mrt::common::Pose2D a(ux(rng), uy(rng), ut(rng)), b(ux(rng), uy(rng), ut(rng));
    t.set_pose(a, {1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4});
    mrt::murea::TrackResult r;
    for (int i = 0; i < 30; ++i) {
      r = t.update(frame(b));
      if (!r.lost && near(r.pose, b)) {
        ++recovered;
        frames_needed.push_back(i + 1);
        break;
      }
    }
    if (r.lost || near(r.pose, b)) {
      lost += r.lost;
      // Ambiguous with the new pose among the two modes reported.
      ambiguous += r.lost && r.search.ambiguous &&
                   (near(r.search.best.pose, b) || (r.search.alternative && near(r.search.alternative->pose, b)));
    } else {
      ++wrong;
    }
  }
  std::cout << "kidnap_recovered_within_1s: " << recovered << " %\n"
            << "kidnap_still_lost_after_1s: " << lost << " % (" << ambiguous << " % ambiguous, the pose one of the two modes)\n"
            << "kidnap_tracking_a_wrong_pose_after_1s: " << wrong << " %\n"
            << "kidnap_frames_median: " << percentile(frames_needed, 0.5) << " frames\n"
            << "kidnap_frames_p95: " << percentile(frames_needed, 0.95) << " frames\n";
}

int main(int argc, char** argv) {
  int n = 1000, m = 3;
  std::string file = std::string(MRT_MUREA_DATA) + "/msl_field.yaml";
  CLI::App app{"MUREA benchmark: prints `metric: value unit` lines.", "murea_bench"};
  app.add_option("poses", n, "random poses localized (count), default 1000")->check(CLI::PositiveNumber);
  app.add_option("repeats", m, "repetitions (count), default 3")->check(CLI::PositiveNumber);
  app.add_option("world", file, "world file (YAML), default test/data/msl_field.yaml");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  mrt::sim::World world = mrt::sim::load_world(file);
  world.movers.clear();
  world.ball.enabled = false;
  const mrt::murea::FeatureMap map(world);
  const mrt::murea::Localizer loc(map, mrt::murea::SearchOptions{});  // 5 cm, 1 degree

  const std::vector<Frame> frames = run("global", world, loc, Noise{}, n);
  // The simulator's own default camera noise (2 % of the distance, 0.01
  // rad), its 6 m range, and 10 spurious points per frame.
  run("global_sim_noise", world, loc, Noise{6.0, 0.0, 0.02, 0.01, 10}, n);
  timeout_table(map, frames);
  window_run(map, frames);
  const double seconds = argc > 4 ? std::atof(argv[4]) : 300.0;
  tracking_run("tracking", world, map, seconds, 0.0);
  tracking_run("tracking_outliers30", world, map, seconds, 0.3);
  kidnap_run(world, map);

  double t_search = 0.0, t_exh = 0.0;
  int identical = 0;
  const int checked = std::min(m, n);
  for (int i = 0; i < checked; ++i) {
    const mrt::murea::Result e = loc.exhaustive(frames[i].percepts);
    t_exh += e.time_ms;
    t_search += frames[i].result.time_ms;
    if (e.best.evidence == frames[i].result.best.evidence) ++identical;
    else std::cerr << "NOT EXACT: frame " << i << " search " << frames[i].result.best.evidence << " exhaustive "
                   << e.best.evidence << '\n';
  }
  std::cout << "exhaustive_checked: " << checked << " count\n"
            << "exhaustive_identical_best_evidence: " << identical << " count\n"
            << "exhaustive_time_mean: " << t_exh / std::max(1, checked) << " ms\n"
            << "speedup_vs_exhaustive: " << (t_search > 0 ? t_exh / t_search : 0.0) << " x\n";
  return identical == checked ? 0 : 1;
}
