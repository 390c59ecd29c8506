// SPIKE's grids from the stack's maps (mrt_world): world files rasterized
// and map_server maps, both in metres; Moving AI maps are movingai.h's.
#pragma once

#include <string>

#include "mrt_spike/grid.h"
#include "mrt_spike/poses.h"
#include "mrt_world/occupancy_map.h"
#include "mrt_world/world.h"

namespace mrt::spike {

/// A grid placed in the world: the centre of cell (c, r) is the point
/// frame.origin + frame.resolution * (c, r); rows grow with y.
struct WorldGrid {
  OccupancyGrid grid;
  GridFrame frame;
  /// Nearest cell to a world point (may be outside the grid).
  Cell cell_at(double x, double y) const;
};

/// SPIKE's grid of an occupancy map: a cell is free when the map's is (known
/// and below free_thresh), blocked otherwise (occupied and unknown alike).
/// Throws mrt::common::ParseError naming the map's file when its origin has
/// a yaw (SPIKE's grids are axis-aligned).
WorldGrid to_world_grid(const mrt::world::OccupancyMap& map);

/// The fixed objects of a world on a grid (mrt_world's rasterize: walls,
/// goal walls and posts block every cell they may touch; movers are moving
/// obstacles, not here).
WorldGrid rasterize_world(const mrt::world::World& world, double resolution);

/// A map_server YAML as it is, or a world file rasterized at `resolution`
/// (mrt_world's load_map_grid; its ParseErrors name file:line).
WorldGrid load_any_map(const std::string& path, double resolution);

}  // namespace mrt::spike
