#include "mrt_spike/line_of_sight.h"

#include <cmath>
#include <cstdlib>

namespace mrt::spike {

bool line_of_sight(const OccupancyGrid& grid, const Cell& a, const Cell& b) {
  int x = a.x, y = a.y;
  if (grid.blocked(x, y)) return false;
  const int dx = std::abs(b.x - a.x), dy = std::abs(b.y - a.y);
  const int sx = b.x > a.x ? 1 : -1, sy = b.y > a.y ? 1 : -1;
  // The i-th vertical grid line crossed is at parameter (2i+1)/(2dx), the
  // j-th horizontal one at (2j+1)/(2dy): compare (2i+1)*dy with (2j+1)*dx.
  long i = 0, j = 0;
  while (i < dx || j < dy) {
    const long tx = (2 * i + 1) * static_cast<long>(dy);
    const long ty = (2 * j + 1) * static_cast<long>(dx);
    if (i < dx && (j >= dy || tx < ty)) {
      x += sx;
      ++i;
    } else if (j < dy && (i >= dx || ty < tx)) {
      y += sy;
      ++j;
    } else {  // exactly through a corner
      if (grid.blocked(x + sx, y) && grid.blocked(x, y + sy)) return false;
      x += sx;
      y += sy;
      ++i;
      ++j;
    }
    if (grid.blocked(x, y)) return false;
  }
  return true;
}

double path_length(const std::vector<Cell>& path) {
  double len = 0.0;
  for (size_t k = 1; k < path.size(); ++k)
    len += std::hypot(path[k].x - path[k - 1].x, path[k].y - path[k - 1].y);
  return len;
}

bool path_valid(const OccupancyGrid& grid, const std::vector<Cell>& path, const Cell& start,
                const Cell& goal, std::string* why) {
  auto fail = [&](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (path.empty()) return fail("empty path");
  if (path.front() != start) return fail("first waypoint is not the start");
  if (path.back() != goal) return fail("last waypoint is not the goal");
  if (path.size() == 1 && grid.blocked(start.x, start.y)) return fail("start is blocked");
  for (size_t k = 1; k < path.size(); ++k)
    if (!line_of_sight(grid, path[k - 1], path[k]))
      return fail("segment " + std::to_string(k - 1) + " (" + std::to_string(path[k - 1].x) + "," +
                  std::to_string(path[k - 1].y) + ")-(" + std::to_string(path[k].x) + "," +
                  std::to_string(path[k].y) + ") crosses a blocked cell or corner");
  return true;
}

}  // namespace mrt::spike
