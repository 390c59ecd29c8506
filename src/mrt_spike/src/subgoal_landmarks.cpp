// Differential heuristic over the subgoal graph (ALT: Goldberg & Harrelson
// 2005; Sturtevant et al. 2009 on grids). For a landmark L, the triangle
// inequality gives d(v, goal) >= |d(L, v) - d(L, goal)|; the search takes the
// largest of these bounds and the octile distance. d(L, .) are exact graph
// distances (Dijkstra at preprocessing), and d(L, goal) is exact too: every
// shortest path into the goal enters it from a subgoal that reaches it
// directly (the property the subgoal search already relies on), so the
// heuristic is consistent and the search stays octile-optimal. A vertex
// connected to a landmark the goal is not connected to (or the reverse) cannot
// reach the goal: infinite bound, never queued.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "mrt_spike/subgoal_graph.h"

namespace mrt::spike {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

void SubgoalGraph::dijkstra(int source, std::vector<double>& dist) const {
  dist.assign(subgoals_.size(), kInf);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[source] = 0.0;
  open.push({0.0, source});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    for (int k = adj_start_[u]; k < adj_start_[u + 1]; ++k) {
      const double nd = d + adj_cost_[k];
      if (nd < dist[adj_[k]]) {
        dist[adj_[k]] = nd;
        open.push({nd, adj_[k]});
      }
    }
  }
}

// Landmarks by farthest-point selection in the largest connected component:
// the first is the subgoal farthest from an arbitrary one of that component,
// each next one the subgoal farthest from all the chosen ones.
void SubgoalGraph::build_landmarks(int count) {
  const int n = static_cast<int>(subgoals_.size());
  landmarks_ = 0;
  if (count <= 0 || n == 0) return;
  std::vector<double> dist, nearest;
  // the largest component: label by graph traversal
  std::vector<int> comp(n, -1), size;
  for (int s = 0; s < n; ++s) {
    if (comp[s] >= 0) continue;
    const int c = static_cast<int>(size.size());
    size.push_back(0);
    std::vector<int> stack{s};
    comp[s] = c;
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      ++size[c];
      for (int k = adj_start_[u]; k < adj_start_[u + 1]; ++k)
        if (comp[adj_[k]] < 0) comp[adj_[k]] = c, stack.push_back(adj_[k]);
    }
  }
  const int big = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
  const int seed = static_cast<int>(std::find(comp.begin(), comp.end(), big) - comp.begin());
  dijkstra(seed, nearest);
  count = std::min(count, size[big]);
  lm_dist_.assign(static_cast<size_t>(n) * count, kInf);
  for (int l = 0; l < count; ++l) {
    int far = seed;
    for (int v = 0; v < n; ++v)
      if (comp[v] == big && nearest[v] > nearest[far]) far = v;
    dijkstra(far, dist);
    for (int v = 0; v < n; ++v) {
      lm_dist_[static_cast<size_t>(v) * count + l] = dist[v];
      if (l == 0) nearest[v] = dist[v];
      else nearest[v] = std::min(nearest[v], dist[v]);
    }
  }
  landmarks_ = count;
  goal_lm_.assign(count, kInf);
}

void SubgoalGraph::set_goal_bounds(const Cell& goal, const std::vector<int>& near, int goal_sub) {
  for (int l = 0; l < landmarks_; ++l) {
    double best = goal_sub >= 0 ? lm_dist_[static_cast<size_t>(goal_sub) * landmarks_ + l] : kInf;
    for (int t : near) best = std::min(best, lm_dist_[static_cast<size_t>(t) * landmarks_ + l] + octile(subgoals_[t], goal));
    goal_lm_[l] = best;
  }
}

// v: a subgoal id, or -1 for the start (octile only: its bound is used once).
double SubgoalGraph::heuristic(int v, const Cell& p, const Cell& goal) const {
  double h = octile(p, goal);
  if (v < 0) return h;
  const double* d = lm_dist_.data() + static_cast<size_t>(v) * landmarks_;
  for (int l = 0; l < landmarks_; ++l) {
    const bool fv = !std::isinf(d[l]), fg = !std::isinf(goal_lm_[l]);
    if (fv != fg) return kInf;
    if (fv) h = std::max(h, std::abs(d[l] - goal_lm_[l]));
  }
  return h;
}

}  // namespace mrt::spike
