// Shared by murea_bench's parts: the simulated camera, the correctness
// test and percentiles.
#pragma once

#include <algorithm>
#include <cmath>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "mrt_common/angle.h"
#include "mcl.h"
#include "mrt_murea/localizer.h"
#include "mrt_murea/tracker.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

namespace mrt::murea::bench {

// How the simulated camera errs.
struct Noise {
  double range = 5.0;        // m, vision range
  double sigma_d0 = 0.01;    // m, distance noise: sigma_d0 + sigma_d1 * distance
  double sigma_d1 = 0.01;
  double sigma_b = 0.01;     // rad, bearing noise
  int spurious = 2;          // random line points added per frame
  bool colours = false;      // keep every class with its colour (else Line and unnamed Goal only)
};

// What the robot's camera would report at `pose`: the simulator's vision
// percepts (occlusion by goals included) within noise.range, either only
// Line and Goal (colour removed) or all classes with their colours;
// Gaussian distance and bearing noise; reliability falling with range for
// lines (1 - 0.1 r, at least 0.3), 0.8 for the others; spurious line points
// at random.
inline std::vector<Percept> simulate(const mrt::sim::World& w, const Pose2D& pose, const Noise& nz,
                                     std::mt19937_64& rng) {
  mrt::sim::SensorsConfig cfg;
  cfg.vision_range = nz.range;
  cfg.line_point_spacing = 0.25;
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<Percept> out;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, pose, cfg)) {
    const auto cls = parse_feature_class(s.membership_class);
    if (!cls || (!nz.colours && *cls != FeatureClass::Line && *cls != FeatureClass::Goal)) continue;
    const double r = std::max(0.0, s.distance + (nz.sigma_d0 + nz.sigma_d1 * s.distance) * n01(rng));
    const double rel = *cls == FeatureClass::Line ? std::max(0.3, 1.0 - 0.1 * s.distance) : 0.8;
    out.push_back({*cls, nz.colours ? s.color : "", r, s.bearing + nz.sigma_b * n01(rng), rel});
  }
  std::uniform_real_distribution<double> range(0.5, nz.range), bearing(-mrt::common::kPi, mrt::common::kPi);
  for (int i = 0; i < nz.spurious; ++i) out.push_back({FeatureClass::Line, "", range(rng), bearing(rng), 0.3});
  return out;
}

// CPU time of the calling thread (ms): what one core spends, whatever
// else the machine runs.
inline double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

// Correct: within 0.3 m and 10 degrees.
inline bool near(const Pose2D& a, const Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y) <= 0.3 &&
         std::abs(mrt::common::angle_diff(a.theta, b.theta)) <= mrt::common::deg_to_rad(10);
}

inline double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (const double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

inline double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))];
}

// One recorded run: the true pose, odometry's motion from the previous
// frame (robot frame) with its covariance, and the frame's percepts.
struct Recording {
  double dt = 1.0 / 30.0;
  std::vector<Pose2D> truth;
  std::vector<Pose2D> odom;
  std::vector<Covariance3> odom_cov;
  std::vector<std::vector<Percept>> percepts;
  double max_speed = 0, max_turn = 0;
};

struct Stats {
  double rmse_xy = 0, rmse_theta = 0, worst = 0;  // over frames from convergence on
  std::vector<double> ms;                         // cost of every frame (wall clock)
  std::vector<double> cpu_ms;                     // the same in the thread's CPU time
  std::vector<double> search_ms;                  // MUREA: the search's part; MCL: frames the filter ran
  int globals = 0;
  double converged_s = -1;  // first time from which 1 s of estimates are all correct
  double on_mirror = 0;     // fraction of frames on the field's half-turn mirror of the truth
};

/// Accumulates the errors of a run of estimates (from the first second
/// of correct estimates on) into *s.
void finish(const Recording& rec, const std::vector<Pose2D>& est, const std::vector<bool>& valid, Stats* s);

/// MUREA's tracker over a recording, from the true pose or from no prior.
Stats run_murea(const FeatureMap& map, const Recording& rec, bool from_truth, bool refine, TrackerOptions opt = {});

/// The MCL baseline over the same recording (amcl's initial covariance
/// around the true pose, or global_localization's uniform particles).
Stats run_mcl(const FeatureMap& map, const Recording& rec, bool from_truth, const MclOptions& options = {});

/// Tracking, kidnapping and the MCL comparison (bench_tracking.cpp).
void tracking_benchmarks(const mrt::sim::World& world, const FeatureMap& map, double seconds);

/// A laser robot in a world of walls (bench_laser.cpp): MUREA and the MCL
/// baseline on the same scans.
void laser_benchmarks(const std::string& world_file, double seconds, int trials);

/// The cost of staying ambiguous on the symmetric field, before and after
/// carrying the modes (bench_ambiguous.cpp).
void ambiguous_benchmarks(const mrt::sim::World& world, const FeatureMap& map);

}  // namespace mrt::murea::bench
