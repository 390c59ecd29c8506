// Occupancy maps (ROS-free): map_server maps (a YAML file and its image)
// and worlds rasterized onto a grid, laid out as nav_msgs/OccupancyGrid
// (row 0 at the bottom, origin at the lower-left corner of cell (0, 0)).
// The one loader of the map_server format in the stack: MUREA turns the
// occupied cells into walls, SPIKE plans on the free ones.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_world/world.h"

namespace mrt::world {

struct OccupancyMap {
  enum class Mode { kTrinary, kScale, kRaw };

  std::string file;          // the YAML (or world file) it came from
  std::string image;         // the image, resolved against the YAML's folder ("" when rasterized)
  double resolution = 0.05;  // m per cell
  Pose2D origin;             // lower-left corner of cell (0, 0) and the grid's yaw
  int width = 0, height = 0;
  double occupied_thresh = 0.65, free_thresh = 0.196;
  bool negate = false;
  Mode mode = Mode::kTrinary;
  /// Occupancy probability per cell in [0, 1], -1 unknown; index
  /// row * width + col, row 0 at the bottom.
  std::vector<float> occupancy;

  bool inside(int col, int row) const { return col >= 0 && row >= 0 && col < width && row < height; }
  float at(int col, int row) const { return occupancy[static_cast<std::size_t>(row) * width + col]; }
  /// Known and below free_thresh.
  bool free(int col, int row) const { const float p = at(col, row); return p >= 0.0f && p < free_thresh; }
  /// Above occupied_thresh.
  bool occupied(int col, int row) const { return at(col, row) > occupied_thresh; }
  /// The nav_msgs/OccupancyGrid value of a cell, as map_server gives it for
  /// the mode: trinary 0 / 100 / -1 (between the thresholds: unknown);
  /// scale 0 / 100 and 1..99 in between; raw the occupancy in percent.
  std::int8_t value(int col, int row) const;
  /// Every cell's value(), row by row (nav_msgs/OccupancyGrid's data).
  std::vector<std::int8_t> values() const;
  /// Centre of cell (col, row) in the world frame.
  Point2D cell_center(int col, int row) const;
  std::size_t count_occupied() const;
};

/// Reads a map_server map: YAML keys `image` (relative to the YAML's
/// folder), `resolution`, `origin` [x, y, yaw], `occupied_thresh`,
/// `free_thresh` (required, as map_server requires them), optional `negate`
/// (0 or 1, default 0) and `mode` (trinary, scale or raw; default trinary).
/// A pixel of grey level v has occupancy p = (255 - v) / 255 (v / 255 with
/// negate); raw: p = v / 100, v > 100 unknown. The image's bottom row is
/// row 0. Throws mrt::common::ParseError naming the YAML file, line and
/// column (a malformed file, a missing or bad key, an unreadable image, an
/// image over 20000 pixels a side).
OccupancyMap load_occupancy_map(const std::string& yaml_path);

/// True when the YAML file at `path` is a map_server map (its top level has
/// an `image` key), false for a world file. Throws ParseError when it does
/// not parse.
bool is_occupancy_map(const std::string& path);

/// The world on a grid of `resolution` over its bounds: a cell is occupied
/// (1) when any part of it may touch a fixed object (its centre within
/// resolution/sqrt(2) of a wall or goal wall, within radius +
/// resolution/sqrt(2) of a post), so no wall leaks between cells; free (0)
/// otherwise. Doors are open. What moves is not there.
OccupancyMap rasterize(const World& world, double resolution);

/// The occupied cells of a map as walls through their centres: each
/// horizontal run of two or more cells one segment, the remaining cells
/// vertical runs (a single cell: a point). In a World whose bounds are the
/// grid's extent (rotated by the origin's yaw).
World occupied_walls(const OccupancyMap& map);

/// A map for localization: a world file as it is, or a map_server map as
/// its occupied_walls().
World load_map_world(const std::string& path);

/// A map for planning: a map_server map as it is, or a world file
/// rasterized at `resolution`.
OccupancyMap load_map_grid(const std::string& path, double resolution);

}  // namespace mrt::world
