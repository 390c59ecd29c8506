#include "mrt_map/assignment.h"

#include <numeric>

namespace mrt::map {

std::vector<int> hungarian(const std::vector<std::vector<double>>& a) {
  // Shortest augmenting paths with dual potentials u (rows), v (columns);
  // indices are 1-based, column 0 is the virtual start.
  const int n = static_cast<int>(a.size());
  const double inf = std::numeric_limits<double>::max();
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0);
  std::vector<int> p(n + 1, 0), way(n + 1, 0);
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::vector<double> minv(n + 1, inf);
    std::vector<char> used(n + 1, 0);
    do {
      used[j0] = 1;
      const int i0 = p[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double cur = a[i0 - 1][j - 1] - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const int j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> row_to_col(n, -1);
  for (int j = 1; j <= n; ++j)
    if (p[j] > 0) row_to_col[p[j] - 1] = j - 1;
  return row_to_col;
}

namespace {
int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}
}  // namespace

std::vector<int> assign(const std::vector<std::vector<double>>& cost, double miss) {
  const int R = static_cast<int>(cost.size());
  const int C = R > 0 ? static_cast<int>(cost[0].size()) : 0;
  std::vector<int> out(R, -1);
  // Connected components of the gating graph over rows 0..R-1, columns R..R+C-1.
  std::vector<int> parent(R + C);
  std::iota(parent.begin(), parent.end(), 0);
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c)
      if (cost[r][c] <= miss) parent[root(parent, r)] = root(parent, R + c);
  std::vector<std::vector<int>> rows(R + C), cols(R + C);
  for (int r = 0; r < R; ++r) rows[root(parent, r)].push_back(r);
  for (int c = 0; c < C; ++c) cols[root(parent, R + c)].push_back(c);
  const double big = 2.0 * miss + 1.0;  // never cheaper than leaving both free
  for (int k = 0; k < R + C; ++k) {
    const auto& rs = rows[k];
    const auto& cs = cols[k];
    if (rs.empty() || cs.empty()) continue;
    if (rs.size() == 1 && cs.size() == 1) {
      out[rs[0]] = cs[0];  // gated, so cost <= miss
      continue;
    }
    // Augmented matrix [cost, miss/2 on the diagonal; miss/2 on the diagonal, 0]:
    // leaving a row and a column free costs miss, so any gated pair is preferred.
    const int nr = static_cast<int>(rs.size()), nc = static_cast<int>(cs.size()), n = nr + nc;
    std::vector<std::vector<double>> m(n, std::vector<double>(n, big));
    for (int i = 0; i < nr; ++i) {
      for (int j = 0; j < nc; ++j) {
        const double c = cost[rs[i]][cs[j]];
        if (c <= miss) m[i][j] = c;
      }
      m[i][nc + i] = 0.5 * miss;
    }
    for (int j = 0; j < nc; ++j) {
      m[nr + j][j] = 0.5 * miss;
      for (int i = 0; i < nr; ++i) m[nr + j][nc + i] = 0.0;
    }
    const std::vector<int> a = hungarian(m);
    for (int i = 0; i < nr; ++i)
      if (a[i] < nc && cost[rs[i]][cs[a[i]]] <= miss) out[rs[i]] = cs[a[i]];
  }
  return out;
}

}  // namespace mrt::map
