#include "mrt_murea/feature_map.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrt::murea {

using mrt::world::Segment;

std::optional<FeatureClass> parse_feature_class(const std::string& name) {
  for (int i = 0; i < kFeatureClassCount; ++i) {
    const auto c = static_cast<FeatureClass>(i);
    if (name == to_string(c)) return c;
  }
  return std::nullopt;
}

const char* to_string(FeatureClass c) {
  switch (c) {
    case FeatureClass::Line: return "Line";
    case FeatureClass::Goal: return "Goal";
    case FeatureClass::GoalPost: return "GoalPost";
    case FeatureClass::Landmark: return "Landmark";
    case FeatureClass::Wall: return "Wall";
  }
  return "?";
}

namespace {

// Squared distance from (px, py) to segment s.
inline double segment_distance2(double px, double py, const Segment& s) {
  const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
  const double ax = px - s.a.x, ay = py - s.a.y;
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0.0 ? (ax * ex + ay * ey) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  const double dx = ax - t * ex, dy = ay - t * ey;
  return dx * dx + dy * dy;
}

}  // namespace

DistanceGrid::DistanceGrid(std::vector<Segment> segments, double min_x, double min_y, double max_x,
                           double max_y, double resolution)
    : segments_(std::move(segments)), min_x_(min_x), min_y_(min_y), res_(resolution),
      inv_res_(1.0 / resolution), slack_(resolution * std::sqrt(2.0)) {
  if (!(resolution > 0.0) || !(max_x > min_x) || !(max_y > min_y))
    throw std::invalid_argument("DistanceGrid: expected a positive resolution and a non-empty rectangle");
  nx_ = static_cast<int>(std::ceil((max_x - min_x) / resolution));
  ny_ = static_cast<int>(std::ceil((max_y - min_y) / resolution));
  if (segments_.empty()) return;
  cells_.assign(static_cast<std::size_t>(nx_) * ny_, 0.0f);
  // Exact distance at every pixel centre. Row by row, each segment's
  // squared distance is a function of x only, so the inner loop is cheap.
  nearest_.assign(cells_.size(), 0);
  std::vector<double> best(nx_);
  for (int j = 0; j < ny_; ++j) {
    const double y = min_y_ + (j + 0.5) * res_;
    std::fill(best.begin(), best.end(), std::numeric_limits<double>::infinity());
    std::uint32_t* arg = &nearest_[static_cast<std::size_t>(j) * nx_];
    for (std::size_t k = 0; k < segments_.size(); ++k)
      for (int i = 0; i < nx_; ++i) {
        const double d2 = segment_distance2(min_x_ + (i + 0.5) * res_, y, segments_[k]);
        if (d2 < best[i]) {
          best[i] = d2;
          arg[i] = static_cast<std::uint32_t>(k);
        }
      }
    for (int i = 0; i < nx_; ++i) cells_[static_cast<std::size_t>(j) * nx_ + i] = static_cast<float>(std::sqrt(best[i]));
  }
}

double DistanceGrid::exact(double x, double y) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& s : segments_) best = std::min(best, segment_distance2(x, y, s));
  return std::sqrt(best);
}

Point2D DistanceGrid::nearest(double x, double y, double* nx, double* ny) const {
  const Segment* arg = nullptr;
  const double fx = (x - min_x_) * inv_res_, fy = (y - min_y_) * inv_res_;
  if (fx >= 0.0 && fy >= 0.0 && fx < nx_ && fy < ny_) {
    arg = &segments_[nearest_[static_cast<std::size_t>(fy) * nx_ + static_cast<std::size_t>(fx)]];
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (const Segment& s : segments_) {
      const double d2 = segment_distance2(x, y, s);
      if (d2 < best) {
        best = d2;
        arg = &s;
      }
    }
  }
  const double ex = arg->b.x - arg->a.x, ey = arg->b.y - arg->a.y, len2 = ex * ex + ey * ey;
  double t = len2 > 0.0 ? ((x - arg->a.x) * ex + (y - arg->a.y) * ey) / len2 : 0.0;
  const bool end = t <= 0.0 || t >= 1.0;
  t = std::min(1.0, std::max(0.0, t));
  const double len = std::sqrt(len2);
  const Point2D c{arg->a.x + t * ex, arg->a.y + t * ey};
  const double dx = x - c.x, dy = y - c.y, d = std::hypot(dx, dy);
  if (end && d > 0.0) {
    // Nearest to an end point: the distance grows along (x, y) - c (the
    // distance function's gradient), not along the segment's normal. An
    // occupancy map's thick wall is a stack of short runs across it, whose
    // normals would say nothing about the distance to the wall.
    *nx = dx / d;
    *ny = dy / d;
  } else {
    *nx = len > 0.0 ? -ey / len : 1.0;
    *ny = len > 0.0 ? ex / len : 0.0;
  }
  return c;
}

double DistanceGrid::at(double x, double y) const {
  if (segments_.empty()) return std::numeric_limits<double>::infinity();
  const double fx = (x - min_x_) * inv_res_, fy = (y - min_y_) * inv_res_;
  if (fx >= 0.0 && fy >= 0.0 && fx < nx_ && fy < ny_)
    return cells_[static_cast<std::size_t>(fy) * nx_ + static_cast<std::size_t>(fx)];
  return exact(x, y);
}

double Layer::distance(double x, double y) const {
  if (grid) return grid->at(x, y);
  double best = std::numeric_limits<double>::infinity();
  for (const Point2D& p : points) best = std::min(best, (p.x - x) * (p.x - x) + (p.y - y) * (p.y - y));
  return std::sqrt(best);
}

Point2D Layer::nearest(double x, double y, bool* line, double* nx, double* ny) const {
  *line = grid != nullptr;
  *nx = 1.0;
  *ny = 0.0;
  if (grid) return grid->nearest(x, y, nx, ny);
  const Point2D* best = &points.front();
  for (const Point2D& p : points)
    if (std::hypot(p.x - x, p.y - y) < std::hypot(best->x - x, best->y - y)) best = &p;
  return *best;
}

FeatureMap::FeatureMap(const mrt::world::World& world, const MapOptions& o)
    : name_(world.name), min_x_(world.min_x), min_y_(world.min_y), max_x_(world.max_x), max_y_(world.max_y) {
  if (!(o.resolution > 0.0) || !(o.padding >= 0.0))
    throw std::invalid_argument("FeatureMap: expected resolution > 0 and padding >= 0");
  const double x0 = min_x_ - o.padding, y0 = min_y_ - o.padding;
  const double x1 = max_x_ + o.padding, y1 = max_y_ + o.padding;
  lines_ = DistanceGrid(world.field_lines, x0, y0, x1, y1, o.resolution);
  walls_ = DistanceGrid(mrt::world::solid_segments(world), x0, y0, x1, y1, o.resolution);
  for (const mrt::world::Goal& g : world.goals) {
    goals_.push_back({g.name, g.color, {g.pose.x, g.pose.y}});
    const auto posts = mrt::world::goal_posts(g);
    goal_posts_.push_back({g.name + "_left", g.color, posts[0]});
    goal_posts_.push_back({g.name + "_right", g.color, posts[1]});
  }
  for (const mrt::world::Post& p : world.posts)
    if (p.membership_class == "Landmark") landmarks_.push_back({p.name, p.color, p.center});
}

const std::vector<PointFeature>& FeatureMap::points(FeatureClass c) const {
  switch (c) {
    case FeatureClass::Goal: return goals_;
    case FeatureClass::GoalPost: return goal_posts_;
    case FeatureClass::Landmark: return landmarks_;
    default: return none_;
  }
}

Layer FeatureMap::layer(FeatureClass c, const std::string& color) const {
  Layer l;
  if (c == FeatureClass::Line) l.grid = &lines_;
  else if (c == FeatureClass::Wall) l.grid = &walls_;
  else
    for (const PointFeature& f : points(c))
      if (color.empty() || f.color == color) l.points.push_back(f.position);
  return l;
}

}  // namespace mrt::murea
