#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "mrt_spike/line_of_sight.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

namespace {
double dist(const Cell& a, const Cell& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

namespace {
template <typename Los>
std::vector<Cell> pull(const std::vector<Cell>& path, Los los) {
  if (path.size() < 3) return path;
  std::vector<Cell> out{path.front()};
  size_t anchor = 0;
  for (size_t k = 2; k < path.size(); ++k) {
    if (!los(path[anchor], path[k])) {
      out.push_back(path[k - 1]);
      anchor = k - 1;
    }
  }
  out.push_back(path.back());
  return out;
}
}  // namespace

std::vector<Cell> string_pull(const OccupancyGrid& grid, const std::vector<Cell>& path) {
  return pull(path, [&](const Cell& a, const Cell& b) { return line_of_sight(grid, a, b); });
}

std::vector<Cell> string_pull(const Quadtree& tree, const std::vector<Cell>& path) {
  return pull(path, [&](const Cell& a, const Cell& b) { return tree.line_of_sight(a, b); });
}

SpikePlanner::SpikePlanner(const OccupancyGrid& grid, SpikeOptions options)
    : grid_(grid), options_(options), tree_(new Quadtree(grid, options.quadtree)),
      fallback_(new GridAstar(grid)) {
  if (options_.graph == SpikeOptions::Graph::subgoal) subgoals_ = std::make_unique<SubgoalGraph>(grid, options_.landmarks);
  const size_t n = tree_->vertices().size() + 2;
  g_.assign(n, 0.0);
  parent_.assign(n, -1);
  stamp_.assign(n, 0);
  closed_.assign(n, 0);
  point_.resize(n);
  for (size_t i = 0; i + 2 < n; ++i) point_[i] = tree_->vertices()[i];
}

PlanResult SpikePlanner::plan(const Cell& start, const Cell& goal) {
  PlanResult r;
  if (grid_.blocked(start.x, start.y) || grid_.blocked(goal.x, goal.y)) return diagnose(grid_, start, goal);
  if (subgoals_) {
    if (tree_->line_of_sight(start, goal)) {
      r.path = {start, goal};
      if (start == goal) r.path.pop_back();
    } else {
      r.path = subgoals_->plan(start, goal, nullptr, &r.expansions);
      if (r.path.empty()) return diagnose(grid_, start, goal);
      if (options_.smooth) r.path = string_pull(*tree_, r.path);
    }
    r.length = path_length(r.path);
    r.solved = true;
    return r;
  }
  std::vector<Cell> path;
  const double len = search(start, goal, path, r.expansions);
  if (len < 0.0) {  // not connected in the quadtree graph: ask the grid
    PlanResult f = fallback_->plan(start, goal);
    f.fallback = f.solved;
    if (f.solved) f.path = string_pull(*tree_, f.path);
    f.length = path_length(f.path);
    return f;
  }
  r.path = options_.smooth ? string_pull(*tree_, path) : path;
  if (options_.refine && r.path.size() > 2) {
    std::vector<Cell> better = refine(r.path);
    if (!better.empty() && path_length(better) < path_length(r.path)) r.path = std::move(better);
  }
  r.length = path_length(r.path);
  r.solved = true;
  return r;
}

// Marks the leaves the path crosses and their neighbours, then runs octile
// A* inside them and pulls the string: the coarse search picks the corridor,
// the fine search makes the path near-optimal inside it.
std::vector<Cell> SpikePlanner::refine(const std::vector<Cell>& path) {
  if (leaf_mark_.empty()) {
    leaf_mark_.assign(tree_->leaves().size(), 0);
    cell_mark_.assign(static_cast<size_t>(grid_.width()) * grid_.height(), 0);
  }
  ++mark_;
  std::vector<int> seeds;
  auto mark_leaf = [&](int l) {
    if (l < 0 || leaf_mark_[l] == mark_) return;
    leaf_mark_[l] = mark_;
    seeds.push_back(l);
  };
  for (size_t k = 1; k < path.size(); ++k) {
    const Cell a = path[k - 1], b = path[k];
    const int steps = 2 * std::max(std::abs(b.x - a.x), std::abs(b.y - a.y));
    for (int t = 0; t <= steps; ++t) {
      const double f = steps ? static_cast<double>(t) / steps : 0.0;
      const int x = static_cast<int>(std::lround(a.x + f * (b.x - a.x)));
      const int y = static_cast<int>(std::lround(a.y + f * (b.y - a.y)));
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) mark_leaf(tree_->leaf_at(x + dx, y + dy));
    }
  }
  const size_t core = seeds.size();
  for (size_t i = 0; i < core; ++i) {  // one ring of neighbouring leaves
    const QuadLeaf L = tree_->leaves()[seeds[i]];
    for (int cx = L.x - 1; cx <= L.x + L.size; ++cx) {
      mark_leaf(tree_->leaf_at(cx, L.y - 1));
      mark_leaf(tree_->leaf_at(cx, L.y + L.size));
    }
    for (int cy = L.y; cy < L.y + L.size; ++cy) {
      mark_leaf(tree_->leaf_at(L.x - 1, cy));
      mark_leaf(tree_->leaf_at(L.x + L.size, cy));
    }
  }
  for (int l : seeds) {
    const QuadLeaf& L = tree_->leaves()[l];
    for (int y = L.y; y < L.y + L.size; ++y)
      std::fill(cell_mark_.begin() + grid_.index(L.x, y), cell_mark_.begin() + grid_.index(L.x + L.size, y),
                mark_);
  }
  PlanResult r = fallback_->plan_within(path.front(), path.back(), cell_mark_, mark_);
  if (!r.solved) return {};
  return string_pull(*tree_, r.path);
}

// Lazy Theta*'s SetVertex: when the assumed parent is not in line of sight,
// take the best closed neighbour instead (edges of the graph are valid).
int SpikePlanner::set_vertex(int s, int n) {
  const int p = parent_[s];
  if (p < 0 || tree_->line_of_sight(point_[p], point_[s])) return p;
  double best = std::numeric_limits<double>::infinity();
  int arg = -1;
  auto consider = [&](int q, double c) {
    if (q >= 0 && stamp_[q] == run_ && closed_[q] && g_[q] + c < best) best = g_[q] + c, arg = q;
  };
  if (s < n) {
    for (int k = tree_->adj_begin(s); k < tree_->adj_end(s); ++k) consider(tree_->neighbour(k), tree_->cost(k));
  }
  // the start vertex (n) and the goal vertex (n+1) join their leaf's corners
  const QuadLeaf& ls = tree_->leaves()[tree_->leaf_at(point_[n].x, point_[n].y)];
  const QuadLeaf& lg = tree_->leaves()[tree_->leaf_at(point_[n + 1].x, point_[n + 1].y)];
  for (int c : ls.corners)
    if (c == s) consider(n, dist(point_[n], point_[s]));
  if (s == n + 1)
    for (int c : lg.corners) consider(c, dist(point_[c < 0 ? s : c], point_[s]));
  parent_[s] = arg;
  g_[s] = best;
  return arg;
}

double SpikePlanner::search(const Cell& start, const Cell& goal, std::vector<Cell>& path, int& expansions) {
  path.clear();
  if (tree_->line_of_sight(start, goal)) {
    path = {start, goal};
    if (start == goal) path.pop_back();
    return dist(start, goal);
  }
  const int n = static_cast<int>(tree_->vertices().size());
  const int S = n, G = n + 1;
  const int ls = tree_->leaf_at(start.x, start.y), lg = tree_->leaf_at(goal.x, goal.y);
  if (ls < 0 || lg < 0) return -1.0;
  ++run_;
  point_[S] = start;
  point_[G] = goal;
  using Entry = std::pair<double, int>;
  std::vector<Entry> heap;
  auto touch = [&](int v) {
    if (stamp_[v] != run_) {
      stamp_[v] = run_;
      closed_[v] = 0;
      g_[v] = std::numeric_limits<double>::infinity();
      parent_[v] = -1;
    }
  };
  touch(S);
  g_[S] = 0.0;
  heap.emplace_back(-dist(start, goal), S);
  // Path 2 of Theta*: connect v to the parent of u (lazily assumed visible).
  auto relax = [&](int u, int v) {
    touch(v);
    if (closed_[v]) return;
    const int pu = parent_[u] >= 0 ? parent_[u] : u;
    const double ng = g_[pu] + dist(point_[pu], point_[v]);
    if (ng < g_[v]) {
      g_[v] = ng;
      parent_[v] = pu;
      heap.emplace_back(-(ng + dist(point_[v], goal)), v);
      std::push_heap(heap.begin(), heap.end());
    }
  };
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end());
    const auto [negf, u] = heap.back();
    heap.pop_back();
    if (closed_[u] || -negf > g_[u] + dist(point_[u], goal) + 1e-9) continue;  // stale
    const int assumed = parent_[u];
    const int p = set_vertex(u, n);
    if (p != assumed) {  // the assumed parent was not visible: g grew, queue again
      if (p < 0) {
        g_[u] = std::numeric_limits<double>::infinity();
        parent_[u] = -1;
      } else {
        heap.emplace_back(-(g_[u] + dist(point_[u], goal)), u);
        std::push_heap(heap.begin(), heap.end());
      }
      continue;
    }
    closed_[u] = 1;
    ++expansions;
    if (u == G) break;
    if (u == S) {
      for (int c : tree_->leaves()[ls].corners)
        if (c >= 0) relax(S, c);
      continue;
    }
    for (int k = tree_->adj_begin(u); k < tree_->adj_end(u); ++k) relax(u, tree_->neighbour(k));
    for (int c : tree_->leaves()[lg].corners)
      if (c == u) relax(u, G);
  }
  if (stamp_[G] != run_ || !closed_[G]) return -1.0;
  for (int v = G; v >= 0; v = parent_[v]) path.push_back(point_[v]);
  std::reverse(path.begin(), path.end());
  return g_[G];
}

}  // namespace mrt::spike
