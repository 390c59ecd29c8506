#include "mrt_spike/poses.h"

#include <cmath>

namespace mrt::spike {

std::vector<Pose> to_poses(const std::vector<Cell>& path, double spacing, const GridFrame& frame) {
  std::vector<Pose> out;
  if (path.empty()) return out;
  auto wx = [&](const Cell& c) { return frame.origin_x + frame.resolution * c.x; };
  auto wy = [&](const Cell& c) { return frame.origin_y + frame.resolution * c.y; };
  double yaw = 0.0;
  if (path.size() == 1) {
    out.push_back({wx(path[0]), wy(path[0]), 0.0});
    return out;
  }
  for (size_t k = 0; k + 1 < path.size(); ++k) {
    const double ax = wx(path[k]), ay = wy(path[k]), bx = wx(path[k + 1]), by = wy(path[k + 1]);
    const double len = std::hypot(bx - ax, by - ay);
    if (len <= 0.0) continue;
    yaw = std::atan2(by - ay, bx - ax);
    const int steps = spacing > 0.0 ? static_cast<int>(std::ceil(len / spacing - 1e-9)) : 1;
    for (int i = 0; i < steps; ++i) {
      const double t = static_cast<double>(i) / steps;
      out.push_back({ax + t * (bx - ax), ay + t * (by - ay), yaw});
    }
  }
  out.push_back({wx(path.back()), wy(path.back()), yaw});
  return out;
}

}  // namespace mrt::spike
