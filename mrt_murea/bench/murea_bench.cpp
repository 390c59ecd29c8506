// murea_bench: global localization from one frame of simulated percepts
// (field-line points and unnamed goals) on the 18 x 12 m MSL field, over N
// random poses; then the first M of them by exhaustive evaluation of the
// lattice (identical best evidence asserted) for the speed-up.
// Usage: murea_bench [N=1000] [M=3] [world=<package>/test/data/msl_field.yaml]
// Prints `name: value unit` lines.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_murea/localizer.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

using mrt::common::angle_diff;
using mrt::common::kPi;
using mrt::murea::FeatureClass;
using mrt::murea::Percept;

namespace {

// What the robot's camera would report at `pose`: the simulator's vision
// percepts (occlusion by goals included), only Line and Goal (colour
// removed), within 5 m; distance noise 1 cm + 1 %, bearing noise 0.01 rad;
// reliability falling with range; two spurious line points per frame.
std::vector<Percept> simulate(const mrt::sim::World& w, const mrt::common::Pose2D& pose, std::mt19937_64& rng) {
  mrt::sim::SensorsConfig cfg;
  cfg.vision_range = 5.0;
  cfg.line_point_spacing = 0.25;
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<Percept> out;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, pose, cfg)) {
    const auto cls = mrt::murea::parse_feature_class(s.membership_class);
    if (!cls || (*cls != FeatureClass::Line && *cls != FeatureClass::Goal)) continue;
    const double r = std::max(0.0, s.distance + (0.01 + 0.01 * s.distance) * n01(rng));
    const double rel = *cls == FeatureClass::Goal ? 0.8 : std::max(0.3, 1.0 - 0.1 * s.distance);
    out.push_back({*cls, "", r, s.bearing + 0.01 * n01(rng), rel});
  }
  std::uniform_real_distribution<double> range(0.5, 5.0), bearing(-kPi, kPi);
  for (int i = 0; i < 2; ++i) out.push_back({FeatureClass::Line, "", range(rng), bearing(rng), 0.3});
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

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int m = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::string file = argc > 3 ? argv[3] : std::string(MRT_MUREA_DATA) + "/msl_field.yaml";
  mrt::sim::World world = mrt::sim::load_world(file);
  world.movers.clear();
  world.ball.enabled = false;
  const mrt::murea::FeatureMap map(world);
  mrt::murea::SearchOptions opt;  // 5 cm, 1 degree
  const mrt::murea::Localizer loc(map, opt);

  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> ux(-9.0, 9.0), uy(-6.0, 6.0), ut(-kPi, kPi);
  std::vector<double> times, cells;
  std::vector<std::vector<Percept>> frames;
  std::vector<mrt::murea::Result> results;
  int correct = 0, flagged = 0, timeouts = 0;
  for (int i = 0; i < n; ++i) {
    const mrt::common::Pose2D truth(ux(rng), uy(rng), ut(rng));
    const mrt::common::Pose2D mirror(-truth.x, -truth.y, truth.theta + kPi);
    frames.push_back(simulate(world, truth, rng));
    const mrt::murea::Result r = loc.localize(frames.back());
    results.push_back(r);
    times.push_back(r.time_ms);
    cells.push_back(static_cast<double>(r.cells));
    timeouts += r.complete ? 0 : 1;
    flagged += r.ambiguous ? 1 : 0;
    const bool best_ok = near(r.best.pose, truth) || near(r.best.pose, mirror);
    const bool alt_ok = r.alternative && (near(r.best.pose, truth) ? near(r.alternative->pose, mirror)
                                                                     : near(r.alternative->pose, truth));
    if (best_ok && alt_ok) ++correct;
    else std::cerr << "miss: truth " << truth.x << ' ' << truth.y << ' ' << truth.theta << " best "
                   << r.best.pose.x << ' ' << r.best.pose.y << ' ' << r.best.pose.theta << " ev " << r.best.evidence
                   << " amb " << r.ambiguous << '\n';
  }
  std::cout << "poses: " << n << " count\n"
            << "correct_and_flagged_ambiguous: " << 100.0 * correct / std::max(1, n) << " %\n"
            << "ambiguous_flagged: " << 100.0 * flagged / std::max(1, n) << " %\n"
            << "timeouts: " << timeouts << " count\n"
            << "percepts_per_frame_median: " << percentile([&] {
                 std::vector<double> v;
                 for (const auto& f : frames) v.push_back(static_cast<double>(f.size()));
                 return v;
               }(), 0.5) << " count\n"
            << "time_median: " << percentile(times, 0.5) << " ms\n"
            << "time_p95: " << percentile(times, 0.95) << " ms\n"
            << "time_max: " << percentile(times, 1.0) << " ms\n"
            << "cells_median: " << percentile(cells, 0.5) << " count\n";
  double t_search = 0.0, t_exh = 0.0;
  int identical = 0;
  for (int i = 0; i < std::min(m, n); ++i) {
    const mrt::murea::Result e = loc.exhaustive(frames[i]);
    t_exh += e.time_ms;
    t_search += results[i].time_ms;
    if (std::abs(e.best.evidence - results[i].best.evidence) <= 1e-9) ++identical;
    else std::cerr << "NOT EXACT: frame " << i << " search " << results[i].best.evidence << " exhaustive " << e.best.evidence << '\n';
  }
  std::cout << "exhaustive_checked: " << std::min(m, n) << " count\n"
            << "exhaustive_identical_best_evidence: " << identical << " count\n"
            << "exhaustive_time_mean: " << t_exh / std::max(1, std::min(m, n)) << " ms\n"
            << "speedup_vs_exhaustive: " << (t_search > 0 ? t_exh / t_search : 0.0) << " x\n";
  return identical == std::min(m, n) ? 0 : 1;
}
