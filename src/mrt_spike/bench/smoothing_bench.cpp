// spike_bench --smoothing: the same random queries planned by SPIKE, then
// smoothed into Dubins or Reeds-Shepp curves; lengths, curvature, times.
#include "smoothing_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <limits>
#include <random>
#include <stdexcept>

#include "mrt_spike/curvature_smoother.h"
#include "mrt_spike/world_planner.h"

namespace mrt::spike {

namespace {

double cpu_ms() {  // this thread's CPU time: what preemption on a shared machine does not inflate
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

double wall_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Times {
  std::vector<double> wall, cpu;
  void add(double w, double c) { wall.push_back(w), cpu.push_back(c); }
  void print(const std::string& p) const {
    auto median = [](std::vector<double> v) {
      if (v.empty()) return 0.0;
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    double mean = 0.0;
    for (double w : wall) mean += w / static_cast<double>(wall.size());
    std::cout << p << "median_time: " << median(wall) << " ms\n"
              << p << "mean_time: " << mean << " ms\n"
              << p << "median_cpu_time: " << median(cpu) << " ms\n";
  }
};

}  // namespace

void bench_smoothing(const SmoothingBenchOptions& o) {
  const std::string name = std::filesystem::path(o.world).stem().string();
  WorldPlanner planner(load_any_map(o.world, o.resolution), WorldPlannerOptions{});
  const OccupancyGrid& grid = planner.inflated();
  const GridFrame& f = planner.map().frame;
  SmoothingOptions so;
  so.model = smoothing_model(o.model);
  if (so.model == SmoothingOptions::Model::none) throw std::invalid_argument("--smoothing none: nothing to measure");
  so.turning_radius = o.turning_radius;
  so.step = f.resolution;
  const CurvatureSmoother smoother(grid, f, so);
  std::vector<Cell> free;
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x)
      if (grid.free(x, y)) free.push_back({x, y});
  if (free.empty()) throw std::runtime_error(o.world + ": no free cell");
  std::mt19937 rng(o.seed);
  std::uniform_int_distribution<size_t> pick(0, free.size() - 1);
  int solved = 0, fully = 0, kept = 0, corners = 0;
  double raw_length = 0, smooth_length = 0, k_all = 0, k_fully = 0;
  Times plan_t, total_t, smooth_t;
  for (int q = 0; q < o.queries; ++q) {
    const Cell a = free[pick(rng)], b = free[pick(rng)];
    const double w0 = wall_ms(), c0 = cpu_ms();
    const WorldPlan p = planner.plan(f.origin_x + f.resolution * a.x, f.origin_y + f.resolution * a.y,
                                     f.origin_x + f.resolution * b.x, f.origin_y + f.resolution * b.y);
    const double w1 = wall_ms(), c1 = cpu_ms();
    if (!p.solved) continue;
    const std::vector<Pose> corners_of_path = waypoint_poses(p.waypoints, f);
    const SmoothedPath s = smoother.smooth(corners_of_path, std::numeric_limits<double>::quiet_NaN());
    const double w2 = wall_ms(), c2 = cpu_ms();
    plan_t.add(w1 - w0, c1 - c0), total_t.add(w2 - w0, c2 - c0), smooth_t.add(w2 - w1, c2 - c1);
    ++solved;
    raw_length += p.length, smooth_length += s.length;
    corners += corner_count(corners_of_path);
    kept += s.kept_segments;
    k_all = std::max(k_all, s.max_curvature);
    if (s.fully_smoothed) ++fully, k_fully = std::max(k_fully, s.max_curvature);
  }
  const double n = std::max(1, solved);
  const std::string u = name + ".unsmoothed.", m = name + "." + o.model + ".";
  std::cout << name << ".smoothing.queries: " << o.queries << " count\n"
            << name << ".smoothing.solved: " << solved << " count\n"
            << name << ".smoothing.turning_radius: " << o.turning_radius << " m\n"
            << u << "mean_length: " << raw_length / n << " m\n"
            << u << "max_curvature: " << (corners > 0 ? "inf" : "0") << " 1/m\n"
            << u << "corners: " << corners << " count\n"
            << u << "mean_corners: " << corners / n << " count\n";
  plan_t.print(u);
  std::cout << m << "mean_length: " << smooth_length / n << " m\n"
            << m << "length_ratio: " << (raw_length > 0 ? smooth_length / raw_length : 0.0) << " ratio\n"
            << m << "max_curvature: " << k_all << " 1/m\n"
            << m << "max_curvature_fully_smoothed: " << k_fully << " 1/m\n"
            << m << "curvature_bound: " << 1.0 / o.turning_radius << " 1/m\n"
            << m << "fully_smoothed: " << 100.0 * fully / n << " %\n"
            << m << "kept_straight_segments: " << kept << " count\n";
  total_t.print(m);
  smooth_t.print(m + "smoothing_only.");
}

}  // namespace mrt::spike
