// The simulation loop: robots, movers, ball and sensor sampling.
#include "mrt_sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::sim {

using mrt::common::exp_twist;
using mrt::common::kPi;
using mrt::common::normalize_angle;

namespace {

constexpr double kPushSpeed = 0.05;  // m/s, extra separating speed of a pushed ball

double dist(const Point2D& a, const Point2D& b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)); }

// Gives the ball at least the normal velocity of the pusher's surface
// (centre `c`, radius `r`, contact-point velocity `v`) plus kPushSpeed, or
// bounces it with the ball's robot_restitution, and moves it out of the
// overlap.
void push_ball(Ball& b, const Point2D& c, double r, const Point2D& v) {
  double d = dist(b.position, c);
  if (d >= r + b.radius) return;
  Point2D n{1.0, 0.0};
  if (d > 1e-12) n = {(b.position.x - c.x) / d, (b.position.y - c.y) / d};
  const double rel = (b.velocity.x - v.x) * n.x + (b.velocity.y - v.y) * n.y;
  // Separating speed after the contact: the approach speed times the
  // restitution against bodies (a bounce), at least kPushSpeed.
  const double out = std::max(kPushSpeed, -b.robot_restitution * rel);
  if (rel < out) {
    b.velocity.x += (out - rel) * n.x;
    b.velocity.y += (out - rel) * n.y;
  }
  b.position = {c.x + (r + b.radius) * n.x, c.y + (r + b.radius) * n.y};
}

// Reflects the ball off a static point of contact `q` if it overlaps it.
void bounce(Ball& b, const Point2D& q, double d, double clearance) {
  if (d >= clearance) return;
  Point2D n{1.0, 0.0};
  if (d > 1e-12) n = {(b.position.x - q.x) / d, (b.position.y - q.y) / d};
  const double vn = b.velocity.x * n.x + b.velocity.y * n.y;
  if (vn < 0.0) {
    b.velocity.x -= (1.0 + b.restitution) * vn * n.x;
    b.velocity.y -= (1.0 + b.restitution) * vn * n.y;
  }
  b.position = {q.x + clearance * n.x, q.y + clearance * n.y};
}

}  // namespace

Simulator::Simulator(World world, double dt) : world_(std::move(world)), dt_(dt), rng_(world_.seed) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("Simulator: dt must be > 0");
  solid_ = solid_segments(world_);
  for (const RobotConfig& c : world_.robots) {
    RobotState r;
    r.config = c;
    r.pose = c.initial_pose;
    const std::size_t n = c.base.wheel_count();
    r.wheel_setpoint.assign(n, 0.0);
    r.wheel_speed.assign(n, 0.0);
    r.wheel_angle.assign(n, 0.0);
    r.encoder_angle.assign(n, 0.0);
    r.ticks.assign(n, 0);
    r.sonar.assign(c.sensors.sonars.size(), c.sensors.sonars.empty() ? 0.0 : c.sensors.sonars[0].max_range);
    std::vector<MouseModel> mice;
    for (const MouseConfig& m : c.sensors.mice) mice.emplace_back(m);
    if (mice.size() >= 2) {
      r.mice.left_id = mice[0].config().id;
      r.mice.right_id = mice[1].config().id;
    }
    mice_fault_.emplace_back(mice.size(), false);
    mice_.push_back(std::move(mice));
    robots_.push_back(std::move(r));
  }
}

std::size_t Simulator::robot_index(const std::string& name) const {
  for (std::size_t i = 0; i < robots_.size(); ++i)
    if (robots_[i].config.name == name) return i;
  throw std::out_of_range("no robot named '" + name + "'");
}

void Simulator::set_wheel_speeds(std::size_t robot, const std::vector<double>& w) {
  RobotState& r = robots_.at(robot);
  if (w.size() != r.wheel_setpoint.size())
    throw std::invalid_argument("set_wheel_speeds: robot '" + r.config.name + "' has " +
                                std::to_string(r.wheel_setpoint.size()) + " wheels, got " +
                                std::to_string(w.size()) + " speeds");
  r.wheel_setpoint = w;
}

void Simulator::set_twist(std::size_t robot, const Twist2D& t) {
  set_wheel_speeds(robot, twist_to_wheels(robots_.at(robot).config.base, t));
}

std::uint64_t Simulator::period(double hz) const {
  if (!(hz > 0.0)) return 0;
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(1.0 / (hz * dt_))));
}

// A move is blocked when the footprint at `to` overlaps an obstacle and is
// not getting out of it: a robot that starts (or is pushed) into an
// overlap may still move away.
bool Simulator::blocked(std::size_t i, const Pose2D& from, const Pose2D& to) const {
  const double r = robots_[i].config.base.body_radius;
  const Point2D a{from.x, from.y}, b{to.x, to.y};
  auto hits = [&](double clear_from, double clear_to) { return clear_to < 0.0 && clear_to < clear_from; };
  for (const Segment& s : solid_)
    if (hits(distance_to_segment(a, s) - r, distance_to_segment(b, s) - r)) return true;
  auto circle = [&](const Point2D& c, double cr) {
    return hits(dist(a, c) - r - cr, dist(b, c) - r - cr);
  };
  for (const Post& p : world_.posts)
    if (circle(p.center, p.radius)) return true;
  for (const Mover& m : world_.movers)
    if (circle(m.position, m.radius)) return true;
  for (std::size_t j = 0; j < robots_.size(); ++j)
    if (j != i && circle({robots_[j].pose.x, robots_[j].pose.y}, robots_[j].config.base.body_radius))
      return true;
  auto box = [&](const Point2D& p, double radius) {
    return std::min({p.x - world_.min_x, world_.max_x - p.x, p.y - world_.min_y, world_.max_y - p.y}) - radius;
  };
  if (hits(box(a, r), box(b, r))) return true;
  // The ball is pushed, not an obstacle, unless pushing it out of the way
  // would drive it into a wall, goal wall, post or the bounds: a pinned
  // ball blocks (otherwise it would be squeezed through the wall).
  const Ball& ball = world_.ball;
  const double touch = r + ball.radius;
  if (!ball.enabled || !hits(dist(a, ball.position) - touch, dist(b, ball.position) - touch)) return false;
  const double d = dist(b, ball.position);
  if (d < 1e-12) return true;
  const Point2D p{b.x + (ball.position.x - b.x) * touch / d, b.y + (ball.position.y - b.y) * touch / d};
  const double tol = 1e-9;  // a ball resting against a wall is touching, not inside it
  for (const Segment& s : solid_)
    if (distance_to_segment(p, s) < ball.radius - tol) return true;
  for (const Post& q : world_.posts)
    if (dist(p, q.center) < q.radius + ball.radius - tol) return true;
  return box(p, ball.radius) < -tol;
}

void Simulator::add_hook(StepHook& hook) {
  if (std::find(hooks_.list.begin(), hooks_.list.end(), &hook) == hooks_.list.end()) hooks_.list.push_back(&hook);
}

void Simulator::remove_hook(StepHook& hook) {
  hooks_.list.erase(std::remove(hooks_.list.begin(), hooks_.list.end(), &hook), hooks_.list.end());
}

void Simulator::step() {
  for (StepHook* h : hooks_.list) h->before_step(*this);
  ++steps_;
  time_ = static_cast<double>(steps_) * dt_;

  for (std::size_t i = 0; i < robots_.size(); ++i) {
    RobotState& r = robots_[i];
    const BaseConfig& g = r.config.base;
    r.wheel_speed = r.wheel_setpoint;
    r.saturated = saturate_wheels(g, r.wheel_speed) < 1.0;
    const Twist2D t = wheels_to_twist(g, r.wheel_speed);
    const Pose2D next = r.pose * exp_twist(t.vx, t.vy, t.omega, dt_);
    r.bumped = blocked(i, r.pose, next);
    if (r.bumped) {
      // The wheels slip: encoders count, the mice do not. The footprint is a
      // circle, so turning on the spot never deepens an overlap: the robot
      // still turns (else a robot arcing into an obstacle froze for good,
      // seen in the RoboCup demo against an opponent).
      r.pose.theta = next.theta;
      r.twist = Twist2D{0.0, 0.0, t.omega};
    } else {
      r.pose = next;
      r.twist = t;
    }
    const double enc_noise = r.config.sensors.encoder_noise;
    for (std::size_t k = 0; k < r.wheel_angle.size(); ++k) {
      const double d = r.wheel_speed[k] * dt_;
      r.wheel_angle[k] += d;
      r.encoder_angle[k] += enc_noise > 0.0 ? d * (1.0 + enc_noise * std::normal_distribution<double>()(rng_)) : d;
      r.ticks[k] = static_cast<std::int64_t>(
          std::floor(r.encoder_angle[k] * r.config.sensors.ticks_per_rev / (2.0 * kPi)));
    }
    for (std::size_t k = 0; k < mice_[i].size(); ++k)
      if (mice_[i][k].step(r.twist, r.pose, time_, dt_, world_.surfaces, rng_)) mice_fault_[i][k] = true;
  }
  move_movers();
  move_ball();
  for (std::size_t i = 0; i < robots_.size(); ++i) update_sensors(i);
  for (StepHook* h : hooks_.list) h->after_step(*this);
}

std::size_t Simulator::mover_index(const std::string& name) const {
  for (std::size_t i = 0; i < world_.movers.size(); ++i)
    if (world_.movers[i].name == name) return i;
  throw std::out_of_range("no mover named '" + name + "'");
}

void Simulator::steer_mover(std::size_t index, const Point2D& target, double speed) {
  Mover& m = world_.movers.at(index);
  m.waypoints = {m.position, target};
  m.next = 1;
  m.loop = false;
  m.speed = std::max(0.0, speed);
  m.done = speed <= 0.0;
  if (m.done) m.velocity = {0.0, 0.0};
}

void Simulator::add_wall(const Segment& wall) {
  world_.walls.push_back(wall);
  solid_ = solid_segments(world_);
}

void Simulator::move_movers() {
  for (Mover& m : world_.movers) {
    const Point2D start = m.position;
    Point2D p = start;
    std::size_t next = m.next;
    bool done = m.done;
    double left = m.speed * dt_;
    // Walk along the polyline, carrying what is left of the step past each
    // waypoint; bounded so a loop of coincident waypoints cannot spin.
    for (std::size_t guard = 0; !done && left > 0.0 && guard <= m.waypoints.size(); ++guard) {
      const Point2D& w = m.waypoints[next];
      const double d = dist(p, w);
      if (d > left) {
        p = {p.x + (w.x - p.x) * left / d, p.y + (w.y - p.y) * left / d};
        break;
      }
      p = w;
      left -= d;
      if (next + 1 < m.waypoints.size()) {
        ++next;
      } else if (m.loop) {
        next = 0;
      } else {
        done = true;
      }
    }
    // A walker waits rather than step into a robot.
    bool wait = false;
    for (const RobotState& r : robots_) {
      const Point2D c{r.pose.x, r.pose.y};
      const double touch = m.radius + r.config.base.body_radius;
      if (dist(p, c) < touch && dist(p, c) < dist(start, c)) wait = true;
    }
    if (wait) {
      m.velocity = {0.0, 0.0};
      continue;
    }
    m.velocity = {(p.x - start.x) / dt_, (p.y - start.y) / dt_};
    m.position = p;
    m.next = next;
    m.done = done;
  }
}

void Simulator::move_ball() {
  Ball& b = world_.ball;
  if (!b.enabled) return;
  for (const RobotState& r : robots_) {
    const double c = std::cos(r.pose.theta), s = std::sin(r.pose.theta);
    // The contact point's velocity: the body's plus omega x (its offset),
    // which is tangential for a circular body and so does not push.
    push_ball(b, {r.pose.x, r.pose.y}, r.config.base.body_radius,
              {c * r.twist.vx - s * r.twist.vy, s * r.twist.vx + c * r.twist.vy});
  }
  for (const Mover& m : world_.movers) push_ball(b, m.position, m.radius, m.velocity);

  const double speed = std::hypot(b.velocity.x, b.velocity.y);
  if (speed > 0.0) {
    const double k = std::max(0.0, speed - b.friction * dt_) / speed;
    b.velocity = {b.velocity.x * k, b.velocity.y * k};
  }
  b.position = {b.position.x + b.velocity.x * dt_, b.position.y + b.velocity.y * dt_};
  for (const Segment& s : solid_) {
    Point2D q;
    const double d = distance_to_segment(b.position, s, &q);
    bounce(b, q, d, b.radius);
  }
  for (const Post& p : world_.posts) bounce(b, p.center, dist(b.position, p.center), p.radius + b.radius);
  // The bounds are walls too.
  const double x0 = world_.min_x, x1 = world_.max_x, y0 = world_.min_y, y1 = world_.max_y;
  for (const Segment& s : {Segment{{x0, y0}, {x1, y0}}, Segment{{x1, y0}, {x1, y1}},
                           Segment{{x1, y1}, {x0, y1}}, Segment{{x0, y1}, {x0, y0}}}) {
    Point2D q;
    const double d = distance_to_segment(b.position, s, &q);
    bounce(b, q, d, b.radius);
  }
}

std::vector<OtherRobot> Simulator::other_robots(std::size_t i) const {
  std::vector<OtherRobot> others;
  for (std::size_t j = 0; j < robots_.size(); ++j) {
    if (j == i) continue;
    const RobotState& o = robots_[j];
    others.push_back({o.config.name, {o.pose.x, o.pose.y}, o.config.base.body_radius, o.config.color});
  }
  return others;
}

void Simulator::update_sensors(std::size_t i) {
  RobotState& r = robots_[i];
  const SensorsConfig& cfg = r.config.sensors;
  auto fires = [&](double hz) {
    const std::uint64_t p = period(hz);
    return p > 0 && steps_ % p == 0;
  };
  r.mice_ready = r.encoders_ready = r.sonar_ready = r.vision_ready = r.dgps_ready = false;
  r.camera_ready = fires(cfg.camera.rate);

  if (fires(cfg.rate_mice) && mice_[i].size() >= 2) {
    r.mice_ready = true;
    mice_[i][0].read(r.mice.left_dx, r.mice.left_dy, &r.mice.left_reports);
    mice_[i][1].read(r.mice.right_dx, r.mice.right_dy, &r.mice.right_reports);
    r.mice.time = time_;
    r.mice.left_stamp = mice_[i][0].last_report_time();
    r.mice.right_stamp = mice_[i][1].last_report_time();
    r.mice.left_fault = mice_fault_[i][0];
    r.mice.right_fault = mice_fault_[i][1];
    std::fill(mice_fault_[i].begin(), mice_fault_[i].end(), false);
  }
  r.encoders_ready = fires(cfg.rate_encoders);

  const bool sonar = fires(cfg.rate_sonar) && !cfg.sonars.empty();
  const bool vision = fires(cfg.rate_vision);
  if (sonar || vision) {
    std::vector<Circle> circles;
    std::vector<OtherRobot> others;
    for (std::size_t j = 0; j < robots_.size(); ++j) {
      if (j == i) continue;
      const RobotState& o = robots_[j];
      circles.push_back({{o.pose.x, o.pose.y}, o.config.base.body_radius});
      others.push_back({o.config.name, {o.pose.x, o.pose.y}, o.config.base.body_radius, o.config.color});
    }
    if (sonar) {
      r.sonar_ready = true;
      for (std::size_t k = 0; k < cfg.sonars.size(); ++k) {
        const SonarConfig& s = cfg.sonars[k];
        double d = sonar_range(world_, circles, r.pose, s);
        if (d < s.max_range && cfg.sonar_noise > 0.0)
          d = std::min(s.max_range,
                       std::max(s.min_range, d + cfg.sonar_noise * std::normal_distribution<double>()(rng_)));
        r.sonar[k] = d;
      }
    }
    if (vision) {
      r.vision_ready = true;
      std::vector<SeenObject> no_more_noise;  // realistic percepts carry their own
      r.vision = vision_percepts(world_, others, r.pose, cfg);
      if (cfg.vision_realistic) r.vision = realistic_percepts(r.vision, cfg, rng_);
      for (SeenObject& o : cfg.vision_realistic ? no_more_noise : r.vision) {
        const double dn = cfg.vision_distance_noise * o.distance;
        if (dn > 0.0) o.distance = std::max(0.0, o.distance + dn * std::normal_distribution<double>()(rng_));
        if (cfg.vision_bearing_noise > 0.0)
          o.bearing = normalize_angle(o.bearing + cfg.vision_bearing_noise *
                                                      std::normal_distribution<double>()(rng_));
      }
    }
  }
  if (fires(cfg.rate_dgps)) {
    r.dgps_ready = true;
    std::normal_distribution<double> n(0.0, cfg.dgps_noise > 0.0 ? cfg.dgps_noise : 1.0);
    const double ex = cfg.dgps_noise > 0.0 ? n(rng_) : 0.0, ey = cfg.dgps_noise > 0.0 ? n(rng_) : 0.0;
    r.dgps = {r.pose.x + ex, r.pose.y + ey};
  }
}

}  // namespace mrt::sim
