// A planned polyline to a sequence of poses (the manual's output of SPIKE).
#pragma once

#include <vector>

#include "mrt_spike/grid.h"

namespace mrt::spike {

struct Pose {
  double x = 0.0;    ///< metres (or cells when resolution = 1, origin = 0)
  double y = 0.0;
  double yaw = 0.0;  ///< radians, heading of the segment being followed
};

/// Where the grid sits in the world: world = origin + resolution * cell.
struct GridFrame {
  double resolution = 1.0;
  double origin_x = 0.0;
  double origin_y = 0.0;
};

/// Poses along the path every `spacing` (same unit as the frame), the
/// waypoints' corners kept, the last pose exactly at the goal; each pose's
/// heading is the direction of the segment it lies on (the last one keeps the
/// last segment's heading). spacing <= 0 gives the waypoints only.
std::vector<Pose> to_poses(const std::vector<Cell>& path, double spacing, const GridFrame& frame = {});

}  // namespace mrt::spike
