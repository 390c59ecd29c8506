#include "mrt_spike/subgoal_graph.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

namespace mrt::spike {

namespace {

// 0..3 straight (E, W, S, N), 4..7 diagonal.
const int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
const int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

int straight_of(int dx, int dy) {
  if (dy == 0) return dx > 0 ? 0 : 1;
  return dy > 0 ? 2 : 3;
}
int diagonal_of(int dx, int dy) { return dx > 0 ? (dy > 0 ? 4 : 5) : (dy > 0 ? 6 : 7); }
int sgn(int v) { return (v > 0) - (v < 0); }

}  // namespace

double octile(const Cell& a, const Cell& b) {
  const int dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
  return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
}

bool SubgoalGraph::move_ok(int x, int y, int d) const {
  const int nx = x + kDx[d], ny = y + kDy[d];
  if (grid_.blocked(nx, ny)) return false;
  return d < 4 || (grid_.free(nx, y) && grid_.free(x, ny));
}

SubgoalGraph::SubgoalGraph(const OccupancyGrid& grid, int landmarks)
    : grid_(grid), sub_id_(static_cast<size_t>(grid.width()) * grid.height(), -1) {
  const int w = grid.width(), h = grid.height();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (grid.blocked(x, y)) continue;
      for (int d = 4; d < 8; ++d)
        if (grid.blocked(x + kDx[d], y + kDy[d]) && grid.free(x + kDx[d], y) && grid.free(x, y + kDy[d])) {
          sub_id_[grid.index(x, y)] = static_cast<int>(subgoals_.size());
          subgoals_.push_back({x, y});
          break;
        }
    }
  // clearance: moves possible from a cell in a direction before a blocked
  // cell (or corner) or a subgoal; computed from the far end backwards
  for (int d = 0; d < 8; ++d) {
    clear_[d].assign(sub_id_.size(), 0);
    const bool xdesc = kDx[d] > 0, ydesc = kDy[d] > 0;
    for (int yi = 0; yi < h; ++yi) {
      const int y = ydesc ? h - 1 - yi : yi;
      for (int xi = 0; xi < w; ++xi) {
        const int x = xdesc ? w - 1 - xi : xi;
        if (grid.blocked(x, y) || !move_ok(x, y, d)) continue;
        const size_t n = grid.index(x + kDx[d], y + kDy[d]);
        if (sub_id_[n] >= 0) continue;
        clear_[d][grid.index(x, y)] =
            static_cast<std::uint16_t>(std::min<int>(clear_[d][n] + 1, std::numeric_limits<std::uint16_t>::max()));
      }
    }
  }
  adj_start_.assign(subgoals_.size() + 1, 0);
  for (size_t i = 0; i < subgoals_.size(); ++i) {
    direct_h_reachable(subgoals_[i], scratch_);
    for (int t : scratch_) {
      adj_.push_back(t);
      adj_cost_.push_back(static_cast<float>(octile(subgoals_[i], subgoals_[t])));
    }
    adj_start_[i + 1] = static_cast<int>(adj_.size());
  }
  const size_t n = subgoals_.size() + 2;
  g_.assign(n, 0.0);
  h_.assign(n, 0.0);
  parent_.assign(n, -1);
  stamp_.assign(n, 0);
  goal_mark_.assign(n, 0);
  closed_.assign(n, 0);
  build_landmarks(landmarks);
}

void SubgoalGraph::add_if_subgoal(int x, int y, int d, int k, std::vector<int>& out) const {
  const int ex = x + k * kDx[d], ey = y + k * kDy[d];
  if (!move_ok(ex, ey, d)) return;
  const int id = sub_id_[grid_.index(ex + kDx[d], ey + kDy[d])];
  if (id >= 0) out.push_back(id);
}

void SubgoalGraph::direct_h_reachable(const Cell& c, std::vector<int>& out) const {
  out.clear();
  if (grid_.blocked(c.x, c.y)) return;
  for (int d = 0; d < 8; ++d) add_if_subgoal(c.x, c.y, d, clearance(c.x, c.y, d), out);
  for (int d = 4; d < 8; ++d) {
    const int cs[2] = {straight_of(kDx[d], 0), straight_of(0, kDy[d])};
    int bound[2] = {clearance(c.x, c.y, cs[0]), clearance(c.x, c.y, cs[1])};
    const int diag = clearance(c.x, c.y, d);
    for (int i = 1; i <= diag; ++i) {
      const int rx = c.x + i * kDx[d], ry = c.y + i * kDy[d];
      for (int k = 0; k < 2; ++k) {
        int j = clearance(rx, ry, cs[k]);
        if (j <= bound[k]) {
          const size_t before = out.size();
          add_if_subgoal(rx, ry, cs[k], j, out);
          if (out.size() > before) --j;
        }
        if (j < bound[k]) bound[k] = j;
      }
    }
  }
}

bool SubgoalGraph::direct_octile(const Cell& a, const Cell& b, bool diagonal_first) const {
  const int dx = b.x - a.x, dy = b.y - a.y;
  const int m = std::min(std::abs(dx), std::abs(dy)), s = std::max(std::abs(dx), std::abs(dy)) - m;
  const int dd = (dx == 0 || dy == 0) ? -1 : diagonal_of(dx, dy);
  const int ds = s == 0 ? -1 : (std::abs(dx) > std::abs(dy) ? straight_of(sgn(dx), 0) : straight_of(0, sgn(dy)));
  int x = a.x, y = a.y;
  for (int phase = 0; phase < 2; ++phase) {
    const bool diag = (phase == 0) == diagonal_first;
    const int d = diag ? dd : ds, n = diag ? m : s;
    for (int k = 0; k < n; ++k, x += kDx[d], y += kDy[d])
      if (!move_ok(x, y, d)) return false;
  }
  return true;
}

std::vector<Cell> SubgoalGraph::plan(const Cell& start, const Cell& goal, double* cost, int* expansions) {
  if (grid_.blocked(start.x, start.y) || grid_.blocked(goal.x, goal.y)) return {};
  if (cost) *cost = octile(start, goal);
  if (start == goal) return {start};
  for (bool diagonal_first : {true, false})
    if (direct_octile(start, goal, diagonal_first)) return unfold({}, start, goal);
  const int n = static_cast<int>(subgoals_.size()), S = n, G = n + 1;
  ++run_;
  direct_h_reachable(goal, scratch_);
  for (int t : scratch_) goal_mark_[t] = run_;
  const int goal_sub = sub_id_[grid_.index(goal.x, goal.y)];
  if (goal_sub >= 0) goal_mark_[goal_sub] = run_;
  set_goal_bounds(goal, scratch_, goal_sub);
  auto point = [&](int v) { return v == S ? start : v == G ? goal : subgoals_[v]; };
  auto touch = [&](int v) {
    if (stamp_[v] == run_) return;
    stamp_[v] = run_;
    closed_[v] = 0;
    g_[v] = std::numeric_limits<double>::infinity();
    h_[v] = v == G ? 0.0 : heuristic(v == S ? -1 : v, point(v), goal);
    parent_[v] = -1;
  };
  heap_.clear();
  // min-heap on f, ties broken towards the larger g (deeper first)
  auto later = [](const Entry& a, const Entry& b) { return a.f > b.f; };
  auto relax = [&](int u, int v, double c) {
    touch(v);
    const double ng = g_[u] + c;
    if (closed_[v] || ng >= g_[v] - 1e-9 || std::isinf(h_[v])) return;
    g_[v] = ng;
    parent_[v] = u;
    heap_.push_back({static_cast<float>(ng + h_[v]), static_cast<float>(ng), v});
    std::push_heap(heap_.begin(), heap_.end(), later);
  };
  touch(S);
  g_[S] = 0.0;
  heap_.push_back({static_cast<float>(h_[S]), 0.0f, S});
  std::vector<int> start_edges;
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const int u = heap_.back().v;
    heap_.pop_back();
    if (closed_[u]) continue;
    closed_[u] = 1;
    if (expansions) ++*expansions;
    if (u == G) break;
    if (u == S) {
      direct_h_reachable(start, start_edges);
      for (int t : start_edges) relax(S, t, octile(start, subgoals_[t]));
      continue;
    }
    for (int k = adj_start_[u]; k < adj_start_[u + 1]; ++k) relax(u, adj_[k], adj_cost_[k]);
    if (goal_mark_[u] == run_) relax(u, G, octile(subgoals_[u], goal));
  }
  if (stamp_[G] != run_ || !closed_[G]) return {};
  if (cost) *cost = g_[G];
  std::vector<int> chain;
  for (int v = parent_[G]; v != S; v = parent_[v]) chain.push_back(v);
  std::reverse(chain.begin(), chain.end());
  return unfold(chain, start, goal);
}

// Waypoints of the chain start, subgoals..., goal: between two vertices the
// cell where the diagonal run turns straight (diagonal first, except into
// the goal, whose edges were found from the goal's side).
std::vector<Cell> SubgoalGraph::unfold(const std::vector<int>& chain, const Cell& start, const Cell& goal) const {
  std::vector<Cell> pts{start};
  for (int v : chain) pts.push_back(subgoals_[v]);
  pts.push_back(goal);
  std::vector<Cell> out{start};
  auto add = [&](const Cell& c) {
    if (out.back() != c) out.push_back(c);
  };
  for (size_t k = 1; k < pts.size(); ++k) {
    Cell a = pts[k - 1], b = pts[k];
    const bool into_goal = k + 1 == pts.size() && !chain.empty();
    bool diagonal_first = true;
    if (chain.empty()) diagonal_first = direct_octile(a, b, true);
    if (into_goal) std::swap(a, b);
    const int m = std::min(std::abs(b.x - a.x), std::abs(b.y - a.y));
    const Cell bend{a.x + m * sgn(b.x - a.x), a.y + m * sgn(b.y - a.y)};
    const Cell bend2{b.x - m * sgn(b.x - a.x), b.y - m * sgn(b.y - a.y)};
    add(diagonal_first ? bend : bend2);
    add(pts[k]);
  }
  return out;
}

}  // namespace mrt::spike
