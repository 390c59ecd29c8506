#include "mrt_spike/quadtree.h"

#include <algorithm>
#include <cmath>

#include "mrt_spike/line_of_sight.h"

namespace mrt::spike {

namespace {

// Summed-area table of blocked cells, (w+1) x (h+1).
std::vector<int> blocked_sat(const OccupancyGrid& g) {
  const int w = g.width(), h = g.height();
  std::vector<int> s(static_cast<size_t>(w + 1) * (h + 1), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      s[(y + 1) * (w + 1) + x + 1] = (g.blocked(x, y) ? 1 : 0) + s[y * (w + 1) + x + 1] +
                                     s[(y + 1) * (w + 1) + x] - s[y * (w + 1) + x];
  return s;
}

}  // namespace

Quadtree::Quadtree(const OccupancyGrid& grid, QuadtreeOptions options)
    : grid_(&grid), options_(options),
      leaf_of_cell_(static_cast<size_t>(grid.width()) * grid.height(), -1) {
  int root = 1;
  while (root < std::max(grid.width(), grid.height())) root *= 2;
  if (grid.width() > 0 && grid.height() > 0) build(0, 0, root, blocked_sat(grid));
  build_adjacency();
}

void Quadtree::build(int x, int y, int size, const std::vector<int>& sat) {
  const OccupancyGrid& g = *grid_;
  if (x >= g.width() || y >= g.height()) return;  // entirely outside
  const int x1 = std::min(x + size, g.width()), y1 = std::min(y + size, g.height());
  const int w1 = g.width() + 1;
  const int blocked = sat[y1 * w1 + x1] - sat[y * w1 + x1] - sat[y1 * w1 + x] + sat[y * w1 + x];
  const int area = (x1 - x) * (y1 - y);
  if (blocked == area) return;  // all blocked
  const bool whole = x1 - x == size && y1 - y == size;
  if (blocked == 0 && whole && size <= options_.max_leaf_size) {
    QuadLeaf leaf;
    leaf.x = x;
    leaf.y = y;
    leaf.size = size;
    const int id = static_cast<int>(leaves_.size());
    leaves_.push_back(leaf);
    for (int cy = y; cy < y1; ++cy)
      std::fill(leaf_of_cell_.begin() + g.index(x, cy), leaf_of_cell_.begin() + g.index(x1, cy) - 0,
                id);
    return;
  }
  const int h = size / 2;
  build(x, y, h, sat);
  build(x + h, y, h, sat);
  build(x, y + h, h, sat);
  build(x + h, y + h, h, sat);
}

bool Quadtree::line_of_sight(const Cell& a, const Cell& b) const {
  const OccupancyGrid& g = *grid_;
  int x = a.x, y = a.y;
  if (g.blocked(x, y) || g.blocked(b.x, b.y)) return false;
  const long dx = std::abs(b.x - a.x), dy = std::abs(b.y - a.y);
  const int sx = b.x > a.x ? 1 : -1, sy = b.y > a.y ? 1 : -1;
  long i = 0, j = 0;  // vertical / horizontal grid lines crossed so far
  // number of crossings m >= 1 of the other family with (2m-1)*d_other < k
  auto crossings_before = [](long k, long d_other) { return d_other == 0 ? 0 : ((k - 1) / d_other + 1) / 2; };
  while (i < dx || j < dy) {
    const int l = leaf_of_cell_[g.index(x, y)];
    if (l >= 0 && leaves_[l].size >= 4) {  // jump to the last cell of this leaf on the segment
      const QuadLeaf& L = leaves_[l];
      const long ix = sx > 0 ? L.x + L.size - a.x : a.x - L.x + 1;  // crossing that leaves in x
      const long jy = sy > 0 ? L.y + L.size - a.y : a.y - L.y + 1;
      const bool out_x = ix <= dx, out_y = jy <= dy;
      if (!out_x && !out_y) return true;  // the rest of the segment is inside the leaf
      // compare parameters (2ix-1)/(2dx) and (2jy-1)/(2dy)
      const long kx = (2 * ix - 1) * dy, ky = (2 * jy - 1) * dx;
      long ni, nj;
      if (out_x && (!out_y || kx < ky)) {
        ni = ix - 1;
        nj = std::min(dy, crossings_before(kx, dx));
      } else if (out_y && (!out_x || ky < kx)) {
        nj = jy - 1;
        ni = std::min(dx, crossings_before(ky, dy));
      } else {
        ni = ix - 1;
        nj = jy - 1;
      }
      if (ni > i || nj > j) {
        i = std::max(i, ni);
        j = std::max(j, nj);
        x = a.x + sx * static_cast<int>(i);
        y = a.y + sy * static_cast<int>(j);
      }
    }
    if (i >= dx && j >= dy) break;
    const long tx = (2 * i + 1) * dy, ty = (2 * j + 1) * dx;
    if (i < dx && (j >= dy || tx < ty)) {
      x += sx;
      ++i;
    } else if (j < dy && (i >= dx || ty < tx)) {
      y += sy;
      ++j;
    } else {
      if (g.blocked(x + sx, y) && g.blocked(x, y + sy)) return false;
      x += sx;
      y += sy;
      ++i;
      ++j;
    }
    if (g.blocked(x, y)) return false;
  }
  return true;
}

void Quadtree::build_adjacency() {
  // vertices: the distinct corner cells of every leaf
  for (QuadLeaf& L : leaves_) {
    const int s = L.size - 1;
    const Cell c[5] = {{L.x, L.y}, {L.x + s, L.y}, {L.x, L.y + s}, {L.x + s, L.y + s},
                       {L.x + s / 2, L.y + s / 2}};
    if (options_.centre_only) {
      L.corners[0] = static_cast<int>(vertices_.size());
      vertices_.push_back(c[4]);
      continue;
    }
    for (int k = 0; k < 5; ++k) {
      if (k > 0 && s == 0) break;
      if (k == 4 && s < 2) break;
      L.corners[k] = static_cast<int>(vertices_.size());
      vertices_.push_back(c[k]);
    }
  }
  const int nv = static_cast<int>(vertices_.size());
  std::vector<std::vector<int>> nb(nv);
  auto link = [&](int a, int b) {
    nb[a].push_back(b);
    nb[b].push_back(a);
  };
  for (size_t i = 0; i < leaves_.size() && options_.centre_only; ++i) {
    const QuadLeaf& L = leaves_[i];
    auto probe = [&](int cx, int cy) {
      const int j = leaf_at(cx, cy);
      if (j > static_cast<int>(i)) link(L.corners[0], leaves_[j].corners[0]);
    };
    for (int cx = L.x - 1; cx <= L.x + L.size; ++cx) {
      probe(cx, L.y - 1);
      probe(cx, L.y + L.size);
    }
    for (int cy = L.y; cy < L.y + L.size; ++cy) {
      probe(L.x - 1, cy);
      probe(L.x + L.size, cy);
    }
  }
  for (size_t i = 0; i < leaves_.size() && !options_.centre_only; ++i) {
    const QuadLeaf& L = leaves_[i];
    for (int a = 0; a < 5; ++a)
      for (int b = a + 1; b < 5; ++b)
        if (L.corners[a] >= 0 && L.corners[b] >= 0) link(L.corners[a], L.corners[b]);
    for (int a = 0; a < 4; ++a) {
      const int v = L.corners[a];
      if (v < 0) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int j = leaf_at(vertices_[v].x + dx, vertices_[v].y + dy);
          if (j < 0 || j == static_cast<int>(i)) continue;
          for (int w : leaves_[j].corners)
            if (w >= 0) link(v, w);
        }
    }
  }
  adj_start_.assign(nv + 1, 0);
  for (int v = 0; v < nv; ++v) {
    adj_start_[v] = static_cast<int>(adj_.size());
    std::sort(nb[v].begin(), nb[v].end());
    nb[v].erase(std::unique(nb[v].begin(), nb[v].end()), nb[v].end());
    for (int w : nb[v]) {
      const Cell a = vertices_[v], b = vertices_[w];
      if (!line_of_sight(a, b)) continue;
      adj_.push_back(w);
      adj_cost_.push_back(static_cast<float>(std::hypot(a.x - b.x, a.y - b.y)));
    }
  }
  adj_start_[nv] = static_cast<int>(adj_.size());
}

}  // namespace mrt::spike
