#include "mrt_spike/map_sources.h"

#include <cmath>

#include "mrt_common/parse_error.h"

namespace mrt::spike {

Cell WorldGrid::cell_at(double x, double y) const {
  return {static_cast<int>(std::lround((x - frame.origin_x) / frame.resolution)),
          static_cast<int>(std::lround((y - frame.origin_y) / frame.resolution))};
}

WorldGrid to_world_grid(const mrt::world::OccupancyMap& m) {
  if (m.origin.theta != 0.0)
    throw mrt::common::ParseError(m.file, 0, 0, "expected an origin yaw of 0 (SPIKE plans on axis-aligned grids), got " +
                                                    std::to_string(m.origin.theta));
  WorldGrid g;
  g.frame.resolution = m.resolution;
  g.frame.origin_x = m.origin.x + m.resolution / 2;
  g.frame.origin_y = m.origin.y + m.resolution / 2;
  g.grid = OccupancyGrid(m.width, m.height);
  for (int r = 0; r < m.height; ++r)
    for (int c = 0; c < m.width; ++c) g.grid.set_blocked(c, r, !m.free(c, r));
  return g;
}

WorldGrid rasterize_world(const mrt::world::World& world, double resolution) {
  return to_world_grid(mrt::world::rasterize(world, resolution));
}

WorldGrid load_any_map(const std::string& path, double resolution) {
  return to_world_grid(mrt::world::load_map_grid(path, resolution));
}

}  // namespace mrt::spike
