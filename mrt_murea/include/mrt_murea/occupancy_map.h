// Maps from map_server occupancy images (YAML + PNG/PGM), ROS-free: the
// occupied pixels become wall features of an mrt_sim world that
// FeatureMap then takes like any other (percepts of class Wall match them).
#pragma once

#include <cstddef>
#include <string>

#include "mrt_sim/world.h"

namespace mrt::murea {

/// What the map_server YAML said, and what the image held.
struct OccupancyInfo {
  std::string image;             // path of the image (relative to the YAML's folder resolved)
  double resolution = 0.0;       // m per pixel
  double origin[3] = {0, 0, 0};  // pose of the lower-left pixel's corner (x, y, yaw)
  bool negate = false;
  double occupied_thresh = 0.65, free_thresh = 0.196;
  int width = 0, height = 0;     // pixels
  std::size_t occupied = 0;      // occupied pixels
  std::size_t segments = 0;      // wall segments they became
};

/// Loads a map_server map: YAML keys `image` (relative to the YAML's
/// folder), `resolution`, `origin` [x, y, yaw], `occupied_thresh`,
/// `free_thresh`, optional `negate` (0) and `mode` (trinary or scale). A
/// pixel is occupied when its occupancy p = (255 - v) / 255 (v / 255 with
/// negate) exceeds occupied_thresh. Occupied pixels become walls through
/// their centres: each horizontal run of two or more pixels one segment,
/// the remaining pixels vertical runs (a single pixel: a point). Bounds:
/// the image's extent. Throws mrt::common::ParseError naming the YAML
/// file, line and column (a malformed file, a missing or bad key, an
/// unreadable image).
mrt::sim::World load_occupancy_map(const std::string& yaml_path, OccupancyInfo* info = nullptr);

/// A map for MUREA: a map_server YAML (it has an `image` key) or else an
/// mrt_sim world file.
mrt::sim::World load_map(const std::string& path);

}  // namespace mrt::murea
