#include "mrt_roby/route_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mrt_common/yaml_reader.h"
#include "mrt_spike/map_sources.h"
#include "mrt_spike/planner.h"

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

struct RoutePlanner::Spike {
  spike::WorldGrid map;
  spike::OccupancyGrid inflated;
  std::unique_ptr<spike::SpikePlanner> planner;
};

namespace {
constexpr double kResolution = 0.1;  // m, SPIKE's finest cell on Roby's map
constexpr double kMargin = 20.0;     // m of map around the buildings and the route
}  // namespace

RoutePlanner::RoutePlanner(RoadMap map)
    : map_(std::move(map)), unreachable_(map_.route.size(), false), spike_(std::make_shared<Spike>()) {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  for (const auto& bl : map_.buildings)
    x0 = std::min(x0, bl.xmin), y0 = std::min(y0, bl.ymin), x1 = std::max(x1, bl.xmax), y1 = std::max(y1, bl.ymax);
  for (const auto& p : map_.route) x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  spike::WorldGrid& m = spike_->map;
  m.frame.resolution = kResolution;
  m.frame.origin_x = x0 - kMargin, m.frame.origin_y = y0 - kMargin;
  m.grid = spike::OccupancyGrid(static_cast<int>((x1 - x0 + 2 * kMargin) / kResolution) + 1,
                                static_cast<int>((y1 - y0 + 2 * kMargin) / kResolution) + 1);
  // A cell is blocked when it may touch a building (centre within half a
  // cell diagonal); inflating by clearance + one cell diagonal then keeps
  // every point of a valid segment at least `clearance` from every building.
  const double half_diag = kResolution / std::sqrt(2.0);
  for (int y = 0; y < m.grid.height(); ++y)
    for (int x = 0; x < m.grid.width(); ++x) {
      const Point2D c{m.frame.origin_x + kResolution * x, m.frame.origin_y + kResolution * y};
      for (const auto& bl : map_.buildings)
        if (point_rect_distance(c, bl) <= half_diag) m.grid.set_blocked(x, y, true);
    }
  spike_->inflated = spike::inflate(m.grid, (map_.clearance + 2 * half_diag) / kResolution);
  spike_->planner = std::make_unique<spike::SpikePlanner>(spike_->inflated);
}

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
  bool clear = true;
  for (const auto& bl : map_.buildings) {
    const double d = segment_rect_distance(a, b, bl);
    if (d < map_.clearance && !(d > 0.0 && d >= point_rect_distance(a, bl) - 1e-9)) clear = false;
  }
  if (clear) return {};
  const Spike& sp = *spike_;
  const spike::Cell ca = sp.map.cell_at(a.x, a.y), cb = sp.map.cell_at(b.x, b.y);
  if (!sp.inflated.inside(ca.x, ca.y) || !sp.inflated.inside(cb.x, cb.y))
    throw std::runtime_error("no collision-free way round the buildings (a point outside the planner's map)");
  auto world = [&](const spike::Cell& c) {
    return Point2D{sp.map.frame.origin_x + sp.map.frame.resolution * c.x,
                   sp.map.frame.origin_y + sp.map.frame.resolution * c.y};
  };
  std::vector<Point2D> via;
  spike::Cell from = ca;
  if (sp.inflated.blocked(ca.x, ca.y)) {  // back out to the nearest cell keeping the clearance
    from = spike::diagnose(sp.inflated, ca, cb).nearest;
    via.push_back(world(from));
  }
  const spike::PlanResult r = sp.planner->plan(from, cb);
  if (!r.solved) throw std::runtime_error("no collision-free way round the buildings (" + r.reason + ")");
  for (size_t i = 1; i + 1 < r.path.size(); ++i) via.push_back(world(r.path[i]));
  return via;
}

}  // namespace mrt::roby
