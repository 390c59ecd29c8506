// World geometry helpers (the YAML loader is world_loader.cpp).
#include "mrt_world/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrt::world {

std::vector<Post> World::posts_of(const std::string& membership_class) const {
  std::vector<Post> out;
  for (const Post& p : posts)
    if (p.membership_class == membership_class) out.push_back(p);
  return out;
}

const Door& World::door(const std::string& name) const {
  for (const Door& d : doors)
    if (d.name == name) return d;
  throw std::out_of_range("no door named '" + name + "' in world '" + this->name + "'");
}

const Region* World::region_at(const Point2D& p) const {
  for (const Region& r : regions)
    if (inside(r.polygon, p)) return &r;
  return nullptr;
}

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

bool inside(const std::vector<Point2D>& poly, const Point2D& p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Point2D &a = poly[i], &b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

}  // namespace mrt::world
