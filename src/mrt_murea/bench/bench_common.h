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
#include "mrt_murea/localizer.h"
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

inline double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))];
}

/// Tracking, kidnapping and the MCL comparison (bench_tracking.cpp).
void tracking_benchmarks(const mrt::sim::World& world, const FeatureMap& map, double seconds);

}  // namespace mrt::murea::bench
