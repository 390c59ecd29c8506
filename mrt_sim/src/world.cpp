// World geometry helpers (the YAML loader is world_loader.cpp).
#include "mrt_sim/world.h"

#include <algorithm>
#include <cmath>

namespace mrt::sim {

std::array<Segment, 3> goal_walls(const Goal& g) {
  const double h = 0.5 * g.width;
  const Point2D bl = g.pose.transform({g.depth, h}), br = g.pose.transform({g.depth, -h});
  const Point2D ml = g.pose.transform({0.0, h}), mr = g.pose.transform({0.0, -h});
  return {Segment{bl, br}, Segment{ml, bl}, Segment{mr, br}};
}

std::array<Point2D, 2> goal_posts(const Goal& g) {
  // Looking into the goal (along +x of its pose) the left post is at +y.
  const double h = 0.5 * g.width;
  return {g.pose.transform({0.0, h}), g.pose.transform({0.0, -h})};
}

std::vector<Segment> solid_segments(const World& w) {
  std::vector<Segment> out = w.walls;
  for (const Goal& g : w.goals)
    for (const Segment& s : goal_walls(g)) out.push_back(s);
  return out;
}

double distance_to_segment(const Point2D& p, const Segment& s, Point2D* closest) {
  const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0.0 ? ((p.x - s.a.x) * ex + (p.y - s.a.y) * ey) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  const Point2D c{s.a.x + t * ex, s.a.y + t * ey};
  if (closest) *closest = c;
  const double dx = p.x - c.x, dy = p.y - c.y;
  return std::sqrt(dx * dx + dy * dy);  // not hypot: this is the hot path, and slow there
}

}  // namespace mrt::sim
