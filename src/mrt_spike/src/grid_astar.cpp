#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <utility>

#include "mrt_spike/line_of_sight.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

namespace {

const int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
const int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

bool move_ok(const OccupancyGrid& g, int x, int y, int k) {
  const int nx = x + kDx[k], ny = y + kDy[k];
  if (g.blocked(nx, ny)) return false;
  return k < 4 || (g.free(nx, y) && g.free(x, ny));
}

std::string at(const Cell& c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

Cell nearest_to(const OccupancyGrid& g, const Cell& target, const std::vector<unsigned char>* mask) {
  Cell best{-1, -1};
  long best_d = std::numeric_limits<long>::max();
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) {
      if (mask ? !(*mask)[g.index(x, y)] : g.blocked(x, y)) continue;
      const long d = static_cast<long>(x - target.x) * (x - target.x) +
                     static_cast<long>(y - target.y) * (y - target.y);
      if (d < best_d) best_d = d, best = {x, y};
    }
  return best;
}

}  // namespace

PlanResult diagnose(const OccupancyGrid& grid, const Cell& start, const Cell& goal) {
  PlanResult r;
  if (grid.blocked(start.x, start.y)) {
    r.reason = grid.inside(start.x, start.y) ? "start " + at(start) + " is inside an obstacle"
                                             : "start " + at(start) + " is outside the map";
    r.nearest = nearest_to(grid, start, nullptr);
    return r;
  }
  std::vector<unsigned char> seen(static_cast<size_t>(grid.width()) * grid.height(), 0);
  std::deque<Cell> open{start};
  seen[grid.index(start.x, start.y)] = 1;
  while (!open.empty()) {
    const Cell c = open.front();
    open.pop_front();
    for (int k = 0; k < 8; ++k)
      if (move_ok(grid, c.x, c.y, k) && !seen[grid.index(c.x + kDx[k], c.y + kDy[k])]) {
        seen[grid.index(c.x + kDx[k], c.y + kDy[k])] = 1;
        open.push_back({c.x + kDx[k], c.y + kDy[k]});
      }
  }
  if (grid.inside(goal.x, goal.y) && seen[grid.index(goal.x, goal.y)]) return r;  // reachable
  if (!grid.inside(goal.x, goal.y)) r.reason = "goal " + at(goal) + " is outside the map";
  else if (grid.blocked(goal.x, goal.y)) r.reason = "goal " + at(goal) + " is inside an obstacle";
  else r.reason = "goal " + at(goal) + " is not reachable from the start";
  r.nearest = nearest_to(grid, goal, &seen);
  return r;
}

GridAstar::GridAstar(const OccupancyGrid& grid)
    : grid_(grid), g_(static_cast<size_t>(grid.width()) * grid.height()),
      parent_(g_.size()), stamp_(g_.size(), 0), closed_(g_.size(), 0) {}

PlanResult GridAstar::plan(const Cell& start, const Cell& goal) { return run(start, goal, nullptr, 0); }

PlanResult GridAstar::plan_within(const Cell& start, const Cell& goal, const std::vector<unsigned>& mask,
                                  unsigned stamp) {
  return run(start, goal, &mask, stamp);
}

PlanResult GridAstar::run(const Cell& start, const Cell& goal, const std::vector<unsigned>* mask,
                          unsigned stamp) {
  PlanResult r;
  if (grid_.blocked(start.x, start.y) || grid_.blocked(goal.x, goal.y)) return diagnose(grid_, start, goal);
  ++run_;
  const double s2 = std::sqrt(2.0);
  auto h = [&](int x, int y) {
    const int dx = std::abs(x - goal.x), dy = std::abs(y - goal.y);
    return (s2 - 1.0) * std::min(dx, dy) + std::max(dx, dy);
  };
  using Entry = std::pair<double, int>;  // (f, index)
  std::vector<Entry> heap;
  auto push = [&](double f, int i) {
    heap.emplace_back(-f, i);
    std::push_heap(heap.begin(), heap.end());
  };
  const int w = grid_.width();
  const int si = static_cast<int>(grid_.index(start.x, start.y));
  const int gi = static_cast<int>(grid_.index(goal.x, goal.y));
  g_[si] = 0.0;
  parent_[si] = -1;
  stamp_[si] = run_;
  closed_[si] = 0;
  push(h(start.x, start.y), si);
  bool found = false;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end());
    const int i = heap.back().second;
    heap.pop_back();
    if (closed_[i]) continue;
    closed_[i] = 1;
    ++r.expansions;
    if (i == gi) { found = true; break; }
    const int x = i % w, y = i / w;
    for (int k = 0; k < 8; ++k) {
      if (!move_ok(grid_, x, y, k)) continue;
      const int j = i + kDy[k] * w + kDx[k];
      if (mask && (*mask)[j] != stamp) continue;
      const double ng = g_[i] + (k < 4 ? 1.0 : s2);
      if (stamp_[j] != run_) {
        stamp_[j] = run_;
        closed_[j] = 0;
      } else if (closed_[j] || ng >= g_[j]) {
        continue;
      }
      g_[j] = ng;
      parent_[j] = i;
      push(ng + h(x + kDx[k], y + kDy[k]), j);
    }
  }
  if (!found) return mask ? r : diagnose(grid_, start, goal);
  std::vector<Cell> cells;
  for (int i = gi; i >= 0; i = parent_[i]) cells.push_back({i % w, i / w});
  std::reverse(cells.begin(), cells.end());
  // keep only the turning points
  r.path.push_back(cells.front());
  for (size_t k = 1; k + 1 < cells.size(); ++k) {
    const int ax = cells[k].x - cells[k - 1].x, ay = cells[k].y - cells[k - 1].y;
    const int bx = cells[k + 1].x - cells[k].x, by = cells[k + 1].y - cells[k].y;
    if (ax != bx || ay != by) r.path.push_back(cells[k]);
  }
  if (cells.size() > 1) r.path.push_back(cells.back());
  r.solved = true;
  r.length = g_[gi];
  return r;
}

}  // namespace mrt::spike
