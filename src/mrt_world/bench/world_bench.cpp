// world_bench: the world loader and the rasterizer on the shipped worlds
// (the maps MUREA and SPIKE load at start-up), the rasterizer against the
// brute-force baseline (every cell against every wall and post) on the
// same worlds. Prints `name: value unit` lines.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "mrt_world/occupancy_map.h"
#include "mrt_world/world_loader.h"

using namespace mrt::world;
using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Every cell against every object: the baseline.
std::size_t brute_force(const World& w, double res) {
  World bounds_only;
  bounds_only.min_x = w.min_x, bounds_only.min_y = w.min_y, bounds_only.max_x = w.max_x, bounds_only.max_y = w.max_y;
  const OccupancyMap shape = rasterize(bounds_only, res);
  const double half_diag = res / std::sqrt(2.0);
  const auto solid = solid_segments(w);
  std::size_t occupied = 0;
  for (int r = 0; r < shape.height; ++r)
    for (int c = 0; c < shape.width; ++c) {
      const Point2D p = shape.cell_center(c, r);
      bool hit = false;
      for (const Segment& s : solid) hit = hit || distance_to_segment(p, s) <= half_diag;
      for (const Post& q : w.posts) hit = hit || distance_to_segment(p, {q.center, q.center}) <= q.radius + half_diag;
      occupied += hit;
    }
  return occupied;
}

}  // namespace

int main() {
  const std::string dir = MRT_WORLDS_DIR;
  for (const char* name : {"msl_field", "museum", "roby_outdoor"}) {
    const std::string path = dir + "/" + name + ".yaml";
    auto t0 = Clock::now();
    const int loads = 20;
    World w;
    for (int i = 0; i < loads; ++i) w = load_world(path);
    std::printf("%s_load: %.3f ms\n", name, ms_since(t0) / loads);
    const double res = 0.05;
    t0 = Clock::now();
    const OccupancyMap m = rasterize(w, res);
    const double ours = ms_since(t0);
    t0 = Clock::now();
    const std::size_t base = brute_force(w, res);
    const double brute = ms_since(t0);
    std::printf("%s_rasterize_5cm: %.3f ms\n%s_rasterize_brute_force: %.3f ms\n%s_rasterize_speedup: %.1f x\n", name,
                ours, name, brute, name, brute / ours);
    std::printf("%s_cells_occupied: %zu cells\n%s_cells_agree: %d bool\n", name, m.count_occupied(), name,
                m.count_occupied() == base ? 1 : 0);
  }
  return 0;
}
