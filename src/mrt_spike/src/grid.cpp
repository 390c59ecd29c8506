#include "mrt_spike/grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrt::spike {

int OccupancyGrid::count_free() const {
  return static_cast<int>(std::count(cells_.begin(), cells_.end(), 0));
}

namespace {

// 1-D squared distance transform of f (lower envelope of parabolas).
void dt_1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
           std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  const double inf = std::numeric_limits<double>::infinity();
  int k = 0;
  v[0] = 0;
  z[0] = -inf;
  z[1] = inf;
  for (int q = 1; q < n; ++q) {
    if (f[q] == inf) continue;
    if (f[v[k]] == inf) {  // only infinite parabolas so far: replace
      v[k] = q;
      continue;
    }
    double s = ((f[q] + q * q) - (f[v[k]] + v[k] * v[k])) / (2.0 * q - 2.0 * v[k]);
    while (s <= z[k]) {
      --k;
      s = ((f[q] + q * q) - (f[v[k]] + v[k] * v[k])) / (2.0 * q - 2.0 * v[k]);
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = inf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    d[q] = (f[v[k]] == inf) ? inf : dq * dq + f[v[k]];
  }
}

}  // namespace

std::vector<double> squared_distance_transform(const OccupancyGrid& grid) {
  const int w = grid.width(), h = grid.height();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> out(static_cast<size_t>(w) * h, inf);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (grid.blocked(x, y)) out[grid.index(x, y)] = 0.0;
  const int n = std::max(w, h);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  for (int x = 0; x < w; ++x) {  // columns
    f.resize(h); d.resize(h);
    for (int y = 0; y < h; ++y) f[y] = out[grid.index(x, y)];
    dt_1d(f, d, v, z);
    for (int y = 0; y < h; ++y) out[grid.index(x, y)] = d[y];
  }
  for (int y = 0; y < h; ++y) {  // rows
    f.resize(w); d.resize(w);
    for (int x = 0; x < w; ++x) f[x] = out[grid.index(x, y)];
    dt_1d(f, d, v, z);
    for (int x = 0; x < w; ++x) out[grid.index(x, y)] = d[x];
  }
  return out;
}

OccupancyGrid inflate(const OccupancyGrid& grid, double radius_cells) {
  if (radius_cells <= 0.0) return grid;
  const std::vector<double> d2 = squared_distance_transform(grid);
  OccupancyGrid out = grid;
  const double r2 = radius_cells * radius_cells;
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x)
      if (d2[grid.index(x, y)] <= r2) out.set_blocked(x, y, true);
  return out;
}

void stamp_disc(OccupancyGrid& grid, double cx, double cy, double radius, bool blocked) {
  const int x0 = static_cast<int>(std::floor(cx - radius)), x1 = static_cast<int>(std::ceil(cx + radius));
  const int y0 = static_cast<int>(std::floor(cy - radius)), y1 = static_cast<int>(std::ceil(cy + radius));
  for (int y = std::max(0, y0); y <= std::min(grid.height() - 1, y1); ++y)
    for (int x = std::max(0, x0); x <= std::min(grid.width() - 1, x1); ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= radius * radius) grid.set_blocked(x, y, blocked);
}

}  // namespace mrt::spike
