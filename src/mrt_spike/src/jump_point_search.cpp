#include "mrt_spike/jump_point_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "mrt_spike/subgoal_graph.h"

namespace mrt::spike {

namespace {
int sgn(int v) { return (v > 0) - (v < 0); }
}  // namespace

JumpPointSearch::JumpPointSearch(const OccupancyGrid& grid)
    : grid_(grid), g_(static_cast<size_t>(grid.width()) * grid.height()), parent_(g_.size()),
      stamp_(g_.size(), 0), closed_(g_.size(), 0) {}

bool JumpPointSearch::move_ok(int x, int y, int dx, int dy) const {
  if (grid_.blocked(x + dx, y + dy)) return false;
  return dx == 0 || dy == 0 || (grid_.free(x + dx, y) && grid_.free(x, y + dy));
}

// A straight move arriving at (x, y) has a forced neighbour when a side cell
// is free but the one behind it was blocked (the way around an obstacle's end).
bool JumpPointSearch::forced(int x, int y, int dx, int dy) const {
  if (dy == 0)
    return (grid_.free(x, y + 1) && grid_.blocked(x - dx, y + 1)) ||
           (grid_.free(x, y - 1) && grid_.blocked(x - dx, y - 1));
  return (grid_.free(x + 1, y) && grid_.blocked(x + 1, y - dy)) ||
         (grid_.free(x - 1, y) && grid_.blocked(x - 1, y - dy));
}

bool JumpPointSearch::jump(int x, int y, int dx, int dy, const Cell& goal, Cell& out) const {
  while (move_ok(x, y, dx, dy)) {
    x += dx, y += dy;
    if (x == goal.x && y == goal.y) return out = {x, y}, true;
    if (dx != 0 && dy != 0) {
      Cell tmp;
      if (jump(x, y, dx, 0, goal, tmp) || jump(x, y, 0, dy, goal, tmp)) return out = {x, y}, true;
    } else if (forced(x, y, dx, dy)) {
      return out = {x, y}, true;
    }
  }
  return false;
}

PlanResult JumpPointSearch::plan(const Cell& start, const Cell& goal) {
  PlanResult r;
  if (grid_.blocked(start.x, start.y) || grid_.blocked(goal.x, goal.y)) return diagnose(grid_, start, goal);
  ++run_;
  const int w = grid_.width();
  auto idx = [&](const Cell& c) { return static_cast<int>(grid_.index(c.x, c.y)); };
  using Entry = std::pair<double, int>;
  std::vector<Entry> heap;
  const int si = idx(start), gi = idx(goal);
  stamp_[si] = run_, closed_[si] = 0, g_[si] = 0.0, parent_[si] = -1;
  heap.emplace_back(-octile(start, goal), si);
  bool found = false;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end());
    const int i = heap.back().second;
    heap.pop_back();
    if (closed_[i]) continue;
    closed_[i] = 1;
    ++r.expansions;
    if (i == gi) { found = true; break; }
    const Cell c{i % w, i / w};
    int pdx = 0, pdy = 0;
    if (parent_[i] >= 0) pdx = sgn(c.x - parent_[i] % w), pdy = sgn(c.y - parent_[i] / w);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        if (parent_[i] >= 0) {  // pruning: natural and forced directions only
          const bool natural = (dx == pdx && dy == pdy) || (pdx && pdy && ((dx == pdx && dy == 0) || (dx == 0 && dy == pdy)));
          bool force = false;
          if (!pdx || !pdy) {  // straight arrival: turn around the end of a blocked side
            const bool horizontal = pdx != 0;
            const int px = horizontal ? 0 : dx, py = horizontal ? dy : 0;  // perpendicular part
            const bool ok = horizontal ? (dy != 0 && (dx == 0 || dx == pdx)) : (dx != 0 && (dy == 0 || dy == pdy));
            if (ok) force = grid_.free(c.x + px, c.y + py) && grid_.blocked(c.x + px - pdx, c.y + py - pdy);
          }
          if (!natural && !force) continue;
        }
        Cell j;
        if (!jump(c.x, c.y, dx, dy, goal, j)) continue;
        const int ji = idx(j);
        const double ng = g_[i] + octile(c, j);
        if (stamp_[ji] != run_) {
          stamp_[ji] = run_, closed_[ji] = 0;
        } else if (closed_[ji] || ng >= g_[ji] - 1e-9) {
          continue;
        }
        g_[ji] = ng, parent_[ji] = i;
        heap.emplace_back(-(ng + octile(j, goal)), ji);
        std::push_heap(heap.begin(), heap.end());
      }
  }
  if (!found) return diagnose(grid_, start, goal);
  for (int i = gi; i >= 0; i = parent_[i]) r.path.push_back({i % w, i / w});
  std::reverse(r.path.begin(), r.path.end());
  r.solved = true;
  r.length = g_[gi];
  return r;
}

}  // namespace mrt::spike
