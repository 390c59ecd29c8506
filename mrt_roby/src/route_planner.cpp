#include "mrt_roby/route_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mrt_common/yaml_reader.h"

namespace mrt::roby {

namespace {

double point_rect_distance(const Point2D& p, const Building& r) {
  const double dx = std::max({r.xmin - p.x, 0.0, p.x - r.xmax});
  const double dy = std::max({r.ymin - p.y, 0.0, p.y - r.ymax});
  return std::hypot(dx, dy);
}

double point_segment_distance(const Point2D& p, const Point2D& a, const Point2D& b) {
  const double vx = b.x - a.x, vy = b.y - a.y;
  const double l2 = vx * vx + vy * vy;
  double t = l2 > 0 ? ((p.x - a.x) * vx + (p.y - a.y) * vy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * vx - p.x, a.y + t * vy - p.y);
}

bool segments_cross(const Point2D& a, const Point2D& b, const Point2D& c, const Point2D& d) {
  auto cross = [](const Point2D& o, const Point2D& p, const Point2D& q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

}  // namespace

double segment_rect_distance(const Point2D& a, const Point2D& b, const Building& r) {
  const Point2D c[4] = {{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}};
  if (point_rect_distance(a, r) == 0.0 || point_rect_distance(b, r) == 0.0) return 0.0;
  double best = std::min(point_rect_distance(a, r), point_rect_distance(b, r));
  for (int i = 0; i < 4; ++i) {
    const Point2D& p = c[i];
    const Point2D& q = c[(i + 1) % 4];
    if (segments_cross(a, b, p, q)) return 0.0;
    best = std::min(best, point_segment_distance(p, a, b));
  }
  return best;
}

RoadMap parse_road_map(const std::string& yaml_text, const std::string& file) {
  const common::YamlReader r(file);
  const YAML::Node root = r.load(yaml_text);
  if (!root.IsMap()) throw common::ParseError(file, 1, 1, "expected a map at the top level");
  r.map(root, "top level", {"frame", "clearance", "buildings", "route"});
  RoadMap m;
  if (root["frame"]) m.frame = r.string(root["frame"], "frame");
  if (root["clearance"]) m.clearance = r.non_negative(root["clearance"], "clearance");
  if (root["buildings"]) {
    if (!root["buildings"].IsSequence()) r.fail(root["buildings"], "expected a list for 'buildings'");
    for (const auto& b : root["buildings"]) {
      r.map(b, "buildings", {"name", "box"});
      Building bl;
      if (!b["name"] || !b["box"]) r.fail(b, "a building needs 'name' and 'box'");
      bl.name = r.string(b["name"], "name");
      const YAML::Node box = b["box"];
      if (!box.IsSequence() || box.size() != 4) r.fail(box, "expected [xmin, ymin, xmax, ymax] for 'box'");
      bl.xmin = r.number(box[0], "box");
      bl.ymin = r.number(box[1], "box");
      bl.xmax = r.number(box[2], "box");
      bl.ymax = r.number(box[3], "box");
      if (!(bl.xmax > bl.xmin && bl.ymax > bl.ymin)) r.fail(box, "expected xmax > xmin and ymax > ymin");
      m.buildings.push_back(bl);
    }
  }
  if (!root["route"]) r.fail(root, "missing key 'route'");
  const YAML::Node route = root["route"];
  if (!route.IsSequence() || route.size() == 0) r.fail(route, "expected a non-empty list for 'route'");
  for (const auto& p : route) {
    if (!p.IsSequence() || p.size() != 2) r.fail(p, "expected [x, y] for a route point");
    m.route.push_back({r.number(p[0], "route"), r.number(p[1], "route")});
  }
  return m;
}

RoadMap load_road_map(const std::string& path) {
  return parse_road_map(common::read_file(path, "cannot open file", 1 << 20), path);
}

RoutePlanner::RoutePlanner(RoadMap map) : map_(std::move(map)), unreachable_(map_.route.size(), false) {}

bool RoutePlanner::leg_free(const Point2D& a, const Point2D& b) const {
  for (const auto& bl : map_.buildings)
    if (segment_rect_distance(a, b, bl) < map_.clearance) return false;
  return true;
}

std::vector<Point2D> RoutePlanner::plan(const Point2D& start) {
  std::fill(unreachable_.begin(), unreachable_.end(), false);
  Point2D prev = start;
  for (std::size_t i = 0; i < map_.route.size(); ++i) {
    if (!leg_free(prev, map_.route[i]))
      throw std::invalid_argument("route leg " + std::to_string(i) + " passes too close to a building");
    prev = map_.route[i];
  }
  return map_.route;
}

std::vector<Point2D> RoutePlanner::replan(const Point2D& from, const Point2D& failed) {
  std::size_t k = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < map_.route.size(); ++i) {
    const double d = std::hypot(map_.route[i].x - failed.x, map_.route[i].y - failed.y);
    if (d < best) best = d, k = i;
  }
  if (!map_.route.empty()) unreachable_[k] = true;
  std::vector<Point2D> out;
  for (std::size_t i = k + 1; i < map_.route.size(); ++i)
    if (!unreachable_[i]) out.push_back(map_.route[i]);
  // The legs between route points were checked by plan(); the first leg
  // starts wherever the robot gave up.
  if (!out.empty()) {
    std::vector<Point2D> via = detour(from, out.front());
    out.insert(out.begin(), via.begin(), via.end());
  }
  return out;
}

std::vector<Point2D> RoutePlanner::detour(const Point2D& a, const Point2D& b) const {
  // A robot that gave up inside a building's clearance may leave it by any
  // leg that comes no closer to that building than it already is.
  auto free_from = [&](std::size_t u, const Point2D& p, const Point2D& q) {
    if (u != 0) return leg_free(p, q);
    for (const auto& bl : map_.buildings) {
      const double d = segment_rect_distance(p, q, bl);
      if (d < map_.clearance && !(d > 0.0 && d >= point_rect_distance(p, bl) - 1e-9)) return false;
    }
    return true;
  };
  if (free_from(0, a, b)) return {};
  // Visibility graph: a, b and every building corner pushed out by the
  // clearance plus 1 % in x and y, so that a leg along a side between two
  // such corners keeps the clearance.
  std::vector<Point2D> nodes{a, b};
  const double m = map_.clearance * 1.01;
  for (const auto& bl : map_.buildings)
    for (const Point2D& c : {Point2D{bl.xmin - m, bl.ymin - m}, Point2D{bl.xmax + m, bl.ymin - m},
                             Point2D{bl.xmax + m, bl.ymax + m}, Point2D{bl.xmin - m, bl.ymax + m}})
      nodes.push_back(c);
  const std::size_t n = nodes.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> prev(n, n);
  std::vector<bool> done(n, false);
  dist[0] = 0.0;
  for (std::size_t it = 0; it < n; ++it) {
    std::size_t u = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!done[i] && dist[i] < std::numeric_limits<double>::infinity() && (u == n || dist[i] < dist[u])) u = i;
    if (u == n || u == 1) break;
    done[u] = true;
    for (std::size_t v = 0; v < n; ++v) {
      if (done[v] || v == u || !free_from(u, nodes[u], nodes[v])) continue;
      const double d = dist[u] + std::hypot(nodes[v].x - nodes[u].x, nodes[v].y - nodes[u].y);
      if (d < dist[v]) dist[v] = d, prev[v] = u;
    }
  }
  if (prev[1] == n) throw std::runtime_error("no collision-free way round the buildings");
  std::vector<Point2D> via;
  for (std::size_t v = prev[1]; v != 0; v = prev[v]) via.push_back(nodes[v]);
  std::reverse(via.begin(), via.end());
  return via;
}

}  // namespace mrt::roby
