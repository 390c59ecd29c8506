#include "mrt_spike/moving_obstacles.h"

#include <algorithm>
#include <cmath>

#include "mrt_spike/line_of_sight.h"

namespace mrt::spike {

ObstacleLayer::ObstacleLayer(const OccupancyGrid& base, double inflation, double horizon)
    : base_(base), combined_(base), inflation_(inflation), horizon_(horizon),
      count_(static_cast<size_t>(base.width()) * base.height(), 0) {}

std::vector<Cell> ObstacleLayer::footprint(const MovingObstacle& o) const {
  const double ax = o.x, ay = o.y, bx = o.x + o.vx * horizon_, by = o.y + o.vy * horizon_;
  const double r = o.radius + inflation_, r2 = r * r;
  const double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min(ax, bx) - r)));
  const int x1 = std::min(base_.width() - 1, static_cast<int>(std::ceil(std::max(ax, bx) + r)));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min(ay, by) - r)));
  const int y1 = std::min(base_.height() - 1, static_cast<int>(std::ceil(std::max(ay, by) + r)));
  std::vector<Cell> cells;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      double t = len2 > 0.0 ? ((x - ax) * ex + (y - ay) * ey) / len2 : 0.0;
      t = std::clamp(t, 0.0, 1.0);
      const double dx = x - (ax + t * ex), dy = y - (ay + t * ey);
      if (dx * dx + dy * dy <= r2) cells.push_back({x, y});
    }
  return cells;
}

void ObstacleLayer::stamp(const std::vector<Cell>& cells, int delta) {
  for (const Cell& c : cells) {
    const size_t i = base_.index(c.x, c.y);
    count_[i] = static_cast<std::uint16_t>(count_[i] + delta);
    combined_.set_blocked(c.x, c.y, count_[i] > 0 || base_.blocked(c.x, c.y));
  }
}

void ObstacleLayer::set(int id, const MovingObstacle& o) {
  auto it = footprints_.find(id);
  if (it != footprints_.end()) stamp(it->second, -1);
  std::vector<Cell>& f = footprints_[id];
  f = footprint(o);
  stamp(f, +1);
}

void ObstacleLayer::remove(int id) {
  auto it = footprints_.find(id);
  if (it == footprints_.end()) return;
  stamp(it->second, -1);
  footprints_.erase(it);
}

void ObstacleLayer::clear() {
  for (const auto& kv : footprints_) stamp(kv.second, -1);
  footprints_.clear();
}

DynamicSpike::DynamicSpike(const OccupancyGrid& static_grid, double inflation, double horizon,
                           SpikeOptions options)
    : static_grid_(static_grid), layer_(static_grid_, inflation, horizon),
      static_(std::make_unique<SpikePlanner>(static_grid_, options)),
      search_(std::make_unique<JumpPointSearch>(layer_.grid())) {}

bool DynamicPlanner::still_valid(const std::vector<Cell>& path) const {
  const OccupancyGrid& g = obstacles().grid();
  if (path.empty()) return false;
  if (path.size() == 1) return g.free(path[0]);
  for (size_t k = 1; k < path.size(); ++k)
    if (!line_of_sight(g, path[k - 1], path[k])) return false;
  return true;
}

PlanResult DynamicSpike::plan(const Cell& start, const Cell& goal) {
  const OccupancyGrid& g = layer_.grid();
  if (g.blocked(start.x, start.y) || g.blocked(goal.x, goal.y)) return diagnose(g, start, goal);
  PlanResult r = static_->plan(start, goal);  // the unchanged structure first
  if (r.solved && still_valid(r.path)) {
    r.reason = "static";  // solved on the unchanged structure
    return r;
  }
  r = search_->plan(start, goal);
  if (!r.solved) return r;
  r.path = string_pull(g, r.path);
  r.length = path_length(r.path);
  return r;
}

}  // namespace mrt::spike
