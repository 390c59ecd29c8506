#include "mrt_recvision/runs.h"

#include <cmath>

namespace mrt::recvision {

std::vector<Hit> first_runs(const std::vector<ScanLine>& lines, const std::vector<std::vector<std::uint8_t>>& cls,
                            std::uint8_t color, int min_length, bool skip_at_start) {
  constexpr auto kCyan = static_cast<std::uint8_t>(ColorClass::kCyan);
  constexpr auto kMagenta = static_cast<std::uint8_t>(ColorClass::kMagenta);
  constexpr auto kGreen = static_cast<std::uint8_t>(ColorClass::kGreen);
  std::vector<Hit> hits(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::vector<std::uint8_t>& c = cls[i];
    const int n = static_cast<int>(c.size());
    int k = 0;
    while (k < n) {
      if (c[k] != color) {
        ++k;
        continue;
      }
      const int s = k;
      while (k < n && c[k] == color) ++k;
      if (k - s < min_length || (skip_at_start && s == 0)) continue;
      Hit& h = hits[i];
      h.hit = true;
      h.index = s;
      h.length = k - s;
      h.x = lines[i].points[s].x;
      h.y = lines[i].points[s].y;
      h.distance = std::hypot(h.x, h.y);
      // Markers sit on top of the body: farther out in the image, until the
      // carpet shows again.
      for (int j = s; j < n && j < s + 3 * h.length + 10 && c[j] != kGreen; ++j) {
        h.cyan += c[j] == kCyan;
        h.magenta += c[j] == kMagenta;
      }
      break;
    }
  }
  return hits;
}

std::vector<Segment> group_hits(const std::vector<Hit>& hits, double max_jump) {
  std::vector<Segment> segs;
  const int n = static_cast<int>(hits.size());
  if (n == 0) return segs;
  auto joined = [&](int a, int b) {
    return hits[a].hit && hits[b].hit && std::abs(hits[a].distance - hits[b].distance) <= max_jump;
  };
  // Start at a line that does not continue its predecessor.
  int start = -1;
  for (int i = 0; i < n && start < 0; ++i)
    if (!joined((i + n - 1) % n, i)) start = i;
  const bool ring = start < 0;  // every line joined to the next: one closed segment
  if (ring) start = 0;
  for (int c = 0; c < n; ++c) {
    const int i = (start + c) % n;
    if (!hits[i].hit) continue;
    if (c > 0 && joined((i + n - 1) % n, i) && !segs.empty()) {
      Segment& s = segs.back();
      s.last = i;
      ++s.lines;
      s.pixels += hits[i].length;
      continue;
    }
    segs.push_back({i, i, 1, hits[i].length, 0.0});
  }
  for (Segment& s : segs) {
    const double step = 2.0 * M_PI / n;
    s.middle_bearing = std::remainder(step * (s.first + 0.5 * (s.lines - 1)), 2.0 * M_PI);
  }
  return segs;
}

ColorClass marker_color(const Segment& s, const std::vector<Hit>& hits) {
  int cyan = 0, magenta = 0;
  const int n = static_cast<int>(hits.size());
  for (int k = s.first, c = 0; c < s.lines; k = (k + 1) % n, ++c) {
    cyan += hits[k].cyan;
    magenta += hits[k].magenta;
  }
  if (std::max(cyan, magenta) < 3) return ColorClass::kBlack;
  return cyan >= magenta ? ColorClass::kCyan : ColorClass::kMagenta;
}

}  // namespace mrt::recvision
