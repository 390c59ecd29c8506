// A long route on a building-sized map (an 80 x 50 m office floor at 5 cm:
// rooms either side of a corridor, doors 1.2 m wide), timed beside the
// figures Nav2 publishes for a 75 m route (navfn 146 ms, Smac 2D 243 ms).
#include "building_route.h"

#include <chrono>
#include <iostream>

#include "mrt_world/world.h"
#include "mrt_spike/map_sources.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

namespace {

void wall(mrt::world::World& w, double x0, double y0, double x1, double y1) { w.walls.push_back({{x0, y0}, {x1, y1}}); }

mrt::world::World office() {
  mrt::world::World w;
  w.min_x = 0, w.min_y = 0, w.max_x = 80, w.max_y = 50;
  wall(w, 0, 0, 80, 0), wall(w, 80, 0, 80, 50), wall(w, 80, 50, 0, 50), wall(w, 0, 50, 0, 0);
  for (int k = 1; k < 8; ++k) {  // walls between rooms, a door in each
    const double x = 10.0 * k;
    wall(w, x, 0, x, 10), wall(w, x, 11.2, x, 22);
    wall(w, x, 28, x, 38), wall(w, x, 39.2, x, 50);
  }
  for (int k = 0; k < 8; ++k) {  // corridor walls, a door into every room
    const double x = 10.0 * k;
    wall(w, x, 22, x + 5, 22), wall(w, x + 6.2, 22, x + 10, 22);
    wall(w, x, 28, x + 5, 28), wall(w, x + 6.2, 28, x + 10, 28);
  }
  return w;
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

void bench_building() {
  const double res = 0.05, inflation = (0.3 + 0.1) / res;  // robot 0.3 m + safety 0.1 m
  auto t = std::chrono::steady_clock::now();
  const WorldGrid map = rasterize_world(office(), res);
  const OccupancyGrid grid = inflate(map.grid, inflation);
  const double raster_ms = ms_since(t);
  t = std::chrono::steady_clock::now();
  SpikePlanner spike(grid);
  const double pre_ms = ms_since(t);
  // from the first room's corner to a room across the corridor
  const Cell s = map.cell_at(3, 3), g = map.cell_at(56, 45);
  t = std::chrono::steady_clock::now();
  const PlanResult r = spike.plan(s, g);
  const double spike_ms = ms_since(t);
  GridAstar astar(grid);
  t = std::chrono::steady_clock::now();
  const PlanResult a = astar.plan(s, g);
  const double astar_ms = ms_since(t);
  const std::string p = "building";
  std::cout << p << ".cells: " << grid.width() << "x" << grid.height() << " cells\n"
            << p << ".rasterize_and_inflate: " << raster_ms << " ms\n"
            << p << ".spike.preprocessing: " << pre_ms << " ms\n"
            << p << ".spike.solved: " << r.solved << " bool\n"
            << p << ".spike.route_length: " << r.length * res << " m\n"
            << p << ".spike.time: " << spike_ms << " ms\n"
            << p << ".astar.route_length: " << a.length * res << " m\n"
            << p << ".astar.time: " << astar_ms << " ms\n"
            << p << ".navfn_published: 146 ms\n"
            << p << ".smac2d_published: 243 ms\n";
}

}  // namespace mrt::spike
