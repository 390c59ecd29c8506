// A range scan (a laser's) as MUREA's percepts (ROS-free): each valid beam
// is a point at the foot of a wall, class Wall, the class occupancy maps'
// occupied cells become (feature_map.h).
#pragma once

#include <cstddef>
#include <vector>

#include "mrt_murea/localizer.h"

namespace mrt::murea {

/// The geometry of a scan, as sensor_msgs/LaserScan gives it: beam i at
/// angle_min + i * angle_increment (rad, counter-clockwise), valid ranges
/// finite and strictly between range_min and range_max (m).
struct ScanGeometry {
  double angle_min = 0.0, angle_increment = 0.0;
  double range_min = 0.0, range_max = 0.0;
};

/// The wall points a scan sees, in the scan's frame: each valid range r of
/// beam i a `Wall` percept at distance r, bearing of beam i, reliability 1;
/// at most `max_beams` (>= 1) of them, evenly spaced over the valid beams
/// (the k-th of n valid beams kept when k = floor(j n / max_beams)), in
/// beam order. `*invalid` (when given) grows by the beams not valid.
std::vector<Percept> scan_percepts(const std::vector<float>& ranges, const ScanGeometry& g, int max_beams,
                                   std::size_t* invalid = nullptr);

}  // namespace mrt::murea
