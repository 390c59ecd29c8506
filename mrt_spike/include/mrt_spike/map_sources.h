// Maps for SPIKE from the stack's world files (mrt_sim) and from
// map_server occupancy images (YAML + PNG/PGM), both in metres.
#pragma once

#include <string>

#include "mrt_spike/grid.h"
#include "mrt_spike/poses.h"

namespace mrt::sim {
struct World;
}

namespace mrt::spike {

/// A grid placed in the world: the centre of cell (c, r) is the point
/// frame.origin + frame.resolution * (c, r); rows grow with y.
struct WorldGrid {
  OccupancyGrid grid;
  GridFrame frame;
  /// Nearest cell to a world point (may be outside the grid).
  Cell cell_at(double x, double y) const;
};

/// Rasterizes the fixed objects of an mrt_sim world (walls, goal walls,
/// posts: buildings and polygons are walls in that format) over its bounds:
/// a cell is blocked when any part of it may touch an object (its centre
/// within resolution/sqrt(2) of a wall, within radius + resolution/sqrt(2)
/// of a post), so no wall leaks between cells. Movers are not included (they
/// are moving obstacles).
WorldGrid rasterize_world(const mrt::sim::World& world, double resolution);
/// Loads the world file (mrt_sim's loader; its ParseErrors name file:line).
WorldGrid load_world_map(const std::string& path, double resolution);

/// Reads a map_server map: the YAML (`image`, `resolution`, `origin`,
/// `negate`, `occupied_thresh`, `free_thresh`, `mode` trinary|scale|raw)
/// and its image (OpenCV imread, relative to the YAML). Occupancy of a pixel
/// p = (255 - v) / 255 (v itself when negate); free when p < free_thresh,
/// else blocked (occupied and unknown alike). The image's bottom row is row
/// 0, as map_server does. Errors are ParseErrors naming file:line.
WorldGrid load_occupancy_map(const std::string& yaml_path);

}  // namespace mrt::spike
