// Sensor models: sonar cones, omnidirectional vision (the mice: mouse_model.cpp).
#include "mrt_sim/sensors.h"

#include <algorithm>
#include <cmath>

#include "mrt_common/angle.h"

namespace mrt::sim {

mrt::common::PerceptObject to_percept_object(const SeenObject& s, const SensorsConfig& cfg) {
  mrt::common::PerceptObject o(s.name, s.membership_class);
  const double sd = cfg.vision_distance_noise * s.distance;
  o.set_polar({s.distance, s.bearing, sd, cfg.vision_bearing_noise, 1.0});
  o.set_symbol("color", s.color);
  return o;
}

using mrt::common::kPi;
using mrt::common::normalize_angle;

namespace {

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Distance along the unit ray (o, d) to segment s, or +inf.
double ray_segment(const Point2D& o, double dx, double dy, const Segment& s) {
  const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
  const double denom = cross(dx, dy, ex, ey);
  if (std::fabs(denom) < 1e-15) return INFINITY;  // parallel: a grazing ray sees nothing
  const double ax = s.a.x - o.x, ay = s.a.y - o.y;
  const double t = cross(ax, ay, ex, ey) / denom;
  const double u = cross(ax, ay, dx, dy) / denom;
  return (t >= 0.0 && u >= 0.0 && u <= 1.0) ? t : INFINITY;
}

// Distance along the unit ray (o, d) to circle c; 0 when o is inside it.
double ray_circle(const Point2D& o, double dx, double dy, const Circle& c) {
  const double ox = c.center.x - o.x, oy = c.center.y - o.y;
  const double c2 = ox * ox + oy * oy - c.radius * c.radius;
  if (c2 <= 0.0) return 0.0;
  const double b = ox * dx + oy * dy;
  const double disc = b * b - c2;
  if (b <= 0.0 || disc < 0.0) return INFINITY;
  return b - std::sqrt(disc);
}

// Calls f on every wall and goal wall without building a list.
template <typename F>
void for_each_solid(const World& w, F f) {
  for (const Segment& s : w.walls) f(s);
  for (const Goal& g : w.goals)
    for (const Segment& s : goal_walls(g)) f(s);
}

// Calls f on the world's cylinders (posts, ball, movers) and on `extra`.
template <typename F>
void for_each_circle(const World& w, const std::vector<Circle>& extra, F f) {
  for (const Post& p : w.posts) f(Circle{p.center, p.radius});
  if (w.ball.enabled) f(Circle{w.ball.position, w.ball.radius});
  for (const Mover& m : w.movers) f(Circle{m.position, m.radius});
  for (const Circle& c : extra) f(c);
}

// Distance from o to the part of segment s inside the wedge of unit
// directions between `right` and `left` (< 180 degrees wide) around `mid`.
double wedge_segment(const Point2D& o, const Point2D& right, const Point2D& left, const Point2D& mid,
                     const Segment& s) {
  // Clip p(t) = a + t (b - a) against f(p) >= 0 for three linear forms.
  const double ax = s.a.x - o.x, ay = s.a.y - o.y, bx = s.b.x - o.x, by = s.b.y - o.y;
  double t0 = 0.0, t1 = 1.0;
  auto clip = [&](double fa, double fb) {
    if (fa < 0.0 && fb < 0.0) return false;
    if (fa < 0.0) t0 = std::max(t0, fa / (fa - fb));
    if (fb < 0.0) t1 = std::min(t1, fa / (fa - fb));
    return t0 <= t1;
  };
  if (!clip(cross(right.x, right.y, ax, ay), cross(right.x, right.y, bx, by)) ||
      !clip(-cross(left.x, left.y, ax, ay), -cross(left.x, left.y, bx, by)) ||
      !clip(mid.x * ax + mid.y * ay, mid.x * bx + mid.y * by))
    return INFINITY;
  const Segment part{{s.a.x + t0 * (s.b.x - s.a.x), s.a.y + t0 * (s.b.y - s.a.y)},
                     {s.a.x + t1 * (s.b.x - s.a.x), s.a.y + t1 * (s.b.y - s.a.y)}};
  return distance_to_segment(o, part);
}

// True if segment p-q crosses segment s.
bool segments_cross(const Point2D& p, const Point2D& q, const Segment& s) {
  const double rx = q.x - p.x, ry = q.y - p.y, ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
  const double denom = cross(rx, ry, ex, ey);
  if (std::fabs(denom) < 1e-15) return false;
  const double ax = s.a.x - p.x, ay = s.a.y - p.y;
  const double t = cross(ax, ay, ex, ey) / denom, u = cross(ax, ay, rx, ry) / denom;
  return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0;
}

}  // namespace

std::optional<double> ray_cast(const World& w, const std::vector<Circle>& extra, Point2D origin,
                               double angle, double max_range) {
  const double dx = std::cos(angle), dy = std::sin(angle);
  double best = INFINITY;
  for_each_solid(w, [&](const Segment& s) { best = std::min(best, ray_segment(origin, dx, dy, s)); });
  for_each_circle(w, extra, [&](const Circle& c) { best = std::min(best, ray_circle(origin, dx, dy, c)); });
  if (best > max_range) return std::nullopt;
  return best;
}

double sonar_range(const World& w, const std::vector<Circle>& extra, const Pose2D& robot,
                   const SonarConfig& s) {
  const Point2D o = robot.transform({s.mount.x, s.mount.y});
  const double heading = robot.theta + s.mount.theta, half = 0.5 * s.fov;
  double best;
  if (half < 1e-9) {
    best = ray_cast(w, extra, o, heading, s.max_range).value_or(INFINITY);
  } else {
    // The nearest echo in the cone is the nearest point of any object inside
    // the cone: nothing can hide it, since an occluder would be nearer.
    const Point2D mid{std::cos(heading), std::sin(heading)};
    const Point2D right{std::cos(heading - half), std::sin(heading - half)};
    const Point2D left{std::cos(heading + half), std::sin(heading + half)};
    best = INFINITY;
    for_each_solid(w, [&](const Segment& seg) { best = std::min(best, wedge_segment(o, right, left, mid, seg)); });
    for_each_circle(w, extra, [&](const Circle& c) {
      const double cx = c.center.x - o.x, cy = c.center.y - o.y, dist = std::sqrt(cx * cx + cy * cy);
      if (dist <= c.radius) {
        best = 0.0;
      } else if (std::fabs(normalize_angle(std::atan2(cy, cx) - heading)) <= half) {
        best = std::min(best, dist - c.radius);  // the closest point faces the sonar
      } else {  // otherwise the nearest point in the cone lies on one of its edges
        best = std::min({best, ray_circle(o, right.x, right.y, c), ray_circle(o, left.x, left.y, c)});
      }
    });
  }
  return std::min(s.max_range, std::max(s.min_range, best));
}

std::vector<SeenObject> vision_percepts(const World& w, const std::vector<OtherRobot>& others,
                                        const Pose2D& robot, const SensorsConfig& cfg) {
  const std::vector<Segment> solid = solid_segments(w);
  std::vector<Circle> cylinders;  // occluders; index matches `skip` below
  for (const Post& p : w.posts) cylinders.push_back({p.center, p.radius});
  const std::size_t ball_index = cylinders.size();
  if (w.ball.enabled) cylinders.push_back({w.ball.position, w.ball.radius});
  const std::size_t movers_index = cylinders.size();
  for (const Mover& m : w.movers) cylinders.push_back({m.position, m.radius});
  const std::size_t others_index = cylinders.size();
  for (const OtherRobot& r : others) cylinders.push_back({r.center, r.radius});

  const Point2D eye{robot.x, robot.y};
  std::vector<SeenObject> out;
  // Adds the object at `p` if in range and the line of sight to it crosses
  // no wall and no cylinder but its own (`skip`).
  auto see = [&](const Point2D& p, std::size_t skip, const std::string& name, const std::string& cls,
                 const std::string& color) {
    const double dx = p.x - eye.x, dy = p.y - eye.y, dist = std::sqrt(dx * dx + dy * dy);
    if (dist > cfg.vision_range || dist < 1e-9) return;
    // Stop the sight line 1 um short so a target on a wall's end is visible.
    const double k = (dist - 1e-6) / dist;
    const Point2D q{eye.x + k * dx, eye.y + k * dy};
    for (const Segment& s : solid)
      if (segments_cross(eye, q, s)) return;
    for (std::size_t i = 0; i < cylinders.size(); ++i)
      if (i != skip && distance_to_segment(cylinders[i].center, Segment{eye, q}) < cylinders[i].radius) return;
    out.push_back({name, cls, color, dist, normalize_angle(std::atan2(dy, dx) - robot.theta)});
  };
  const std::size_t none = cylinders.size();

  for (std::size_t i = 0; i < w.posts.size(); ++i)
    see(w.posts[i].center, i, w.posts[i].name, w.posts[i].membership_class, w.posts[i].color);
  for (const Goal& g : w.goals) {
    see({g.pose.x, g.pose.y}, none, g.name, "Goal", g.color);
    const auto posts = goal_posts(g);
    see(posts[0], none, g.name + "_left", "GoalPost", g.color);
    see(posts[1], none, g.name + "_right", "GoalPost", g.color);
  }
  if (w.ball.enabled) see(w.ball.position, ball_index, w.ball.name, "Ball", w.ball.color);
  for (std::size_t i = 0; i < w.movers.size(); ++i)
    see(w.movers[i].position, movers_index + i, w.movers[i].name, w.movers[i].membership_class,
        w.movers[i].color);
  for (std::size_t i = 0; i < others.size(); ++i)
    see(others[i].center, others_index + i, others[i].name, "Robot", others[i].color);
  // Field lines: points at the middles of n equal pieces about
  // line_point_spacing long, fixed in the world so they can be matched;
  // only the pieces whose middles fall inside the vision circle are visited.
  for (const Segment& l : w.field_lines) {
    const double ex = l.b.x - l.a.x, ey = l.b.y - l.a.y, len2 = ex * ex + ey * ey;
    const double n = std::min(1e6, std::max(1.0, std::round(std::sqrt(len2) / cfg.line_point_spacing)));
    // |a + t e - eye| <= range  <=>  t in [t0, t1]
    const double ax = l.a.x - eye.x, ay = l.a.y - eye.y;
    const double b = len2 > 0.0 ? (ax * ex + ay * ey) / len2 : 0.0;
    const double c = len2 > 0.0 ? (ax * ax + ay * ay - cfg.vision_range * cfg.vision_range) / len2 : 0.0;
    const double disc = b * b - c;
    if (len2 > 0.0 && disc < 0.0) continue;
    const double root = std::sqrt(std::max(0.0, disc));
    const double t0 = len2 > 0.0 ? -b - root : 0.0, t1 = len2 > 0.0 ? -b + root : 1.0;
    const double j0 = std::max(0.0, std::ceil(t0 * n - 0.5)), j1 = std::min(n - 1.0, std::floor(t1 * n - 0.5));
    for (double j = j0; j <= j1; ++j) {
      const double t = (j + 0.5) / n;
      see({l.a.x + t * ex, l.a.y + t * ey}, none, "line", "Line", "white");
    }
  }
  return out;
}

std::vector<SeenObject> realistic_percepts(const std::vector<SeenObject>& ideal, const SensorsConfig& cfg,
                                           std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double range = cfg.vision_range;
  std::vector<SeenObject> out;
  for (const SeenObject& o : ideal) {
    const double f = std::min(1.0, o.distance / range);
    if (uniform(rng) < cfg.vision_miss_near + (cfg.vision_miss_far - cfg.vision_miss_near) * f) continue;
    SeenObject r = o;
    r.name.clear();
    const double sd = cfg.vision_distance_noise * o.distance * (1.0 + f);
    r.distance = std::max(0.0, o.distance + sd * normal(rng));
    r.bearing = normalize_angle(o.bearing + cfg.vision_bearing_noise * normal(rng));
    out.push_back(r);
  }
  static const char* const kClass[] = {"Ball", "Robot", "GoalPost", "Obstacle"};
  static const char* const kColor[] = {"orange", "black", "yellow", ""};
  const int n = cfg.vision_false_positives > 0.0
                    ? std::poisson_distribution<int>(cfg.vision_false_positives)(rng) : 0;
  for (int k = 0; k < n; ++k) {
    const int c = std::uniform_int_distribution<int>(0, 3)(rng);
    const double d = 0.5 + (range - 0.5) * uniform(rng);
    out.push_back({"", kClass[c], kColor[c], std::max(0.0, d), normalize_angle(2.0 * kPi * uniform(rng))});
  }
  return out;
}

}  // namespace mrt::sim
