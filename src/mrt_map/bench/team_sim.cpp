#include "team_sim.h"

#include <algorithm>
#include <cmath>

namespace mrt::map::bench {

namespace {
constexpr double kHalfX = 9.0, kHalfY = 6.0;  // MSL field, as mrt_sim's msl_field.yaml
}

TeamSim::TeamSim(unsigned seed, bool team_play, int teammates, int opponents) : team_play_(team_play), rng_(seed) {
  for (int i = 0; i < teammates; ++i) {
    Body b;
    b.p = random_point();
    b.goal = random_point();
    b.speed = 1.0;
    mates_.push_back(b);
  }
  for (int i = 0; i < opponents; ++i) {
    Body b;
    b.p = random_point();
    b.goal = random_point();
    b.speed = 1.5;
    opps_.push_back(b);
  }
  ball_.p = Vec2::Zero();
  ball_.radius = 0.11;
  offset_mates_.assign(mates_.size(), Vec2::Zero());
  offset_opps_.assign(opps_.size(), Vec2::Zero());
}

// Team play, as an MSL team moves (each team the same way, mirrored): the
// first robot keeps its goal (on the goal line, following the ball's y);
// the field player nearest to the ball (hysteresis 1 m) chases it (2 m/s,
// to the ball's position 0.3 s ahead, stopping in contact); the others hold their slots relative to the ball
// (defender 4.5 m behind it, two wings 1.5 m behind and 3.5 m to the
// sides, a forward 2.5 m ahead), each wandering up to +-1 m around its slot
// (renewed every 3 s), at 1.5 m/s. `side` -1: own goal at x = -9 m.
void TeamSim::set_goals(std::vector<Body>& team, std::vector<Vec2>& offsets, int& chaser, double side) {
  const Vec2 b = ball_.p;
  auto dist = [&](int i) { return (team[static_cast<std::size_t>(i)].p - b).norm(); };
  const int n = static_cast<int>(team.size());
  int nearest = -1;
  for (int i = 1; i < n; ++i)
    if (nearest < 0 || dist(i) < dist(nearest)) nearest = i;
  if (chaser < 0 || (nearest >= 0 && dist(nearest) < dist(chaser) - 1.0)) chaser = nearest;
  auto clamp_field = [](Vec2 p) {
    return Vec2(std::clamp(p.x(), -kHalfX + 0.3, kHalfX - 0.3), std::clamp(p.y(), -kHalfY + 0.3, kHalfY - 0.3));
  };
  const double u = -side * b.x();  // the ball along the team's attack direction
  const Vec2 slots[] = {Vec2(std::max(-7.0, u - 4.5), 0.5 * b.y()), Vec2(u - 1.5, b.y() + 3.5),
                        Vec2(u - 1.5, b.y() - 3.5), Vec2(std::min(7.5, u + 2.5), -0.3 * b.y())};
  for (int i = 0; i < n; ++i) {
    Body& r = team[static_cast<std::size_t>(i)];
    const Vec2& off = offsets[static_cast<std::size_t>(i)];
    if (i == 0) {
      r.goal = Vec2(side * 8.3 + 0.2 * off.x(), std::clamp(0.4 * b.y(), -1.2, 1.2));
      r.speed = 1.5;
    } else if (i == chaser) {
      // Behind the ball as seen from the robot, touching it (a robot does
      // not drive over the ball: its camera sees it in front of its body).
      const Vec2 aim = b + 0.3 * ball_.v, to = aim - r.p;
      const double gap = r.radius + ball_.radius + 0.05;
      r.goal = clamp_field(to.norm() > gap ? Vec2(aim - to.normalized() * gap) : r.p);
      r.speed = 2.0;
    } else {
      const Vec2& s = slots[static_cast<std::size_t>((i - 1) % 4)];
      r.goal = clamp_field(Vec2(-side * s.x(), s.y()) + off);
      r.speed = 1.5;
    }
  }
}

// Robots are solid: two that overlap after a step are pushed apart along the
// line between their centres, half the overlap each, and lose the part of
// their velocity that drives them into each other.
void TeamSim::separate() {
  std::vector<Body*> all;
  for (Body& b : mates_) all.push_back(&b);
  for (Body& b : opps_) all.push_back(&b);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      Body& a = *all[i];
      Body& b = *all[j];
      const Vec2 d = b.p - a.p;
      const double dist = d.norm(), contact = a.radius + b.radius;
      if (dist >= contact) continue;
      const Vec2 n = dist > 1e-9 ? Vec2(d / dist) : Vec2(1.0, 0.0);
      a.p -= 0.5 * (contact - dist) * n;
      b.p += 0.5 * (contact - dist) * n;
      a.v -= std::max(0.0, a.v.dot(n)) * n;
      b.v -= std::min(0.0, b.v.dot(n)) * n;
    }
}

Vec2 TeamSim::random_point() {
  std::uniform_real_distribution<double> ux(-kHalfX + 0.5, kHalfX - 0.5), uy(-kHalfY + 0.5, kHalfY - 0.5);
  return Vec2(ux(rng_), uy(rng_));
}

void TeamSim::move(Body& b, double dt) {
  const Vec2 d = b.goal - b.p;
  if (d.norm() < 0.2 && !team_play_) b.goal = random_point();
  // Bounded acceleration (3 m/s^2, an MSL robot's order of magnitude);
  // in team play the robot slows down on its target (no overshoot).
  const double dn = (b.goal - b.p).norm();
  const double speed = team_play_ ? std::min(b.speed, 1.5 * dn) : b.speed;
  const Vec2 want = dn > 1e-9 ? Vec2((b.goal - b.p) / dn * speed) : Vec2::Zero();
  const Vec2 dv = want - b.v;
  const double max_dv = 3.0 * dt;
  b.v += dv.norm() > max_dv ? Vec2(dv.normalized() * max_dv) : dv;
  b.p += b.v * dt;
}

void TeamSim::step(double dt) {
  if (team_play_) {
    offset_timer_ -= dt;
    if (offset_timer_ <= 0.0) {
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (Vec2& o : offset_mates_) o = Vec2(u(rng_), u(rng_));
      for (Vec2& o : offset_opps_) o = Vec2(u(rng_), u(rng_));
      offset_timer_ = 3.0;
    }
    set_goals(mates_, offset_mates_, chaser_mates_, -1.0);
    set_goals(opps_, offset_opps_, chaser_opps_, 1.0);
  }
  for (Body& b : mates_) move(b, dt);
  for (Body& b : opps_) move(b, dt);
  separate();
  // The ball: kicked every 2-4 s to a random velocity up to 4 m/s, rolling
  // friction, bouncing off the field border.
  kick_timer_ -= dt;
  if (kick_timer_ <= 0.0) {
    std::uniform_real_distribution<double> speed(0.5, 4.0), ang(-M_PI, M_PI), wait(2.0, 4.0);
    const double a = ang(rng_), s = speed(rng_);
    ball_.v = Vec2(s * std::cos(a), s * std::sin(a));
    kick_timer_ = wait(rng_);
    since_kick_ = 0.0;
  }
  since_kick_ += dt;
  ball_.v *= std::exp(-0.3 * dt);
  ball_.p += ball_.v * dt;
  if (std::fabs(ball_.p.x()) > kHalfX) {
    ball_.p.x() = std::copysign(2 * kHalfX, ball_.p.x()) - ball_.p.x();
    ball_.v.x() = -ball_.v.x();
  }
  if (std::fabs(ball_.p.y()) > kHalfY) {
    ball_.p.y() = std::copysign(2 * kHalfY, ball_.p.y()) - ball_.p.y();
    ball_.v.y() = -ball_.v.y();
  }
}

bool TeamSim::occluded(const Vec2& a, const Vec2& b, int skip_mate, int skip_opp) const {
  auto blocks = [&](const Body& o) {
    const Vec2 ab = b - a;
    const double t = std::clamp((o.p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    // The end points themselves (observer, target) do not count.
    return t > 1e-6 && t < 1.0 - 1e-6 && (a + t * ab - o.p).norm() < o.radius;
  };
  for (int i = 0; i < static_cast<int>(mates_.size()); ++i)
    if (i != skip_mate && blocks(mates_[i])) return true;
  for (int i = 0; i < static_cast<int>(opps_.size()); ++i)
    if (i != skip_opp && blocks(opps_[i])) return true;
  return false;
}

bool TeamSim::ball_in_view(int i, const CameraModel& cam) const {
  const Vec2& me = mates_[static_cast<std::size_t>(i)].p;
  return (ball_.p - me).norm() <= cam.range && !occluded(me, ball_.p, i, -1);
}

bool TeamSim::opponent_in_view(int i, int k, const CameraModel& cam) const {
  const Vec2& me = mates_[static_cast<std::size_t>(i)].p;
  const Vec2& o = opps_[static_cast<std::size_t>(k)].p;
  return (o - me).norm() <= cam.range && !occluded(me, o, i, k);
}

std::vector<PerceptObject> TeamSim::see(int i, const CameraModel& cam, RobotPose& believed) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Body& me = mates_[static_cast<std::size_t>(i)];
  const double heading = std::atan2(me.v.y(), me.v.x());
  believed.x = me.p.x() + cam.pose_sigma * n(rng_);
  believed.y = me.p.y() + cam.pose_sigma * n(rng_);
  believed.theta = heading + cam.theta_sigma * n(rng_);
  believed.cov = cam.pose_sigma * cam.pose_sigma * Mat2::Identity();
  believed.theta_sigma = cam.theta_sigma;
  std::vector<PerceptObject> out;
  auto observe = [&](const Vec2& target, const std::string& cls, const std::string& color, int skip_mate,
                     int skip_opp) {
    const Vec2 d = target - me.p;
    const double dist = d.norm();
    const double p_detect = cam.p_detect + (cam.p_detect_far - cam.p_detect) * dist / cam.range;
    if (dist > cam.range || dist < 1e-3 || u(rng_) > p_detect) return;
    if (occluded(me.p, target, skip_mate, skip_opp)) return;
    const double sd = cam.sigma_d0 + cam.sigma_d_rel * dist + cam.sigma_d_quad * dist * dist;
    // Measured relative to the TRUE pose; interpreted from the believed one.
    PerceptObject o;
    o.membership_class = cls;
    o.attributes.push_back({"color", 0.0, color, 0.0, 1.0});
    o.set("distance", dist + sd * n(rng_), sd, 1.0);
    o.set("bearing", std::atan2(d.y(), d.x()) - heading + cam.sigma_bearing * n(rng_), cam.sigma_bearing, 1.0);
    out.push_back(std::move(o));
  };
  observe(ball_.p, "Ball", "orange", i, -1);
  for (int k = 0; k < static_cast<int>(mates_.size()); ++k)
    if (k != i) observe(mates_[static_cast<std::size_t>(k)].p, "Robot", "magenta", k, -1);
  for (int k = 0; k < static_cast<int>(opps_.size()); ++k)
    observe(opps_[static_cast<std::size_t>(k)].p, "Robot", "cyan", i, k);
  if (u(rng_) < cam.clutter_rate) {  // a false ball somewhere in view
    PerceptObject o;
    o.membership_class = "Ball";
    o.attributes.push_back({"color", 0.0, "orange", 0.0, 1.0});
    const double dist = cam.range * std::sqrt(u(rng_)), b = 2 * M_PI * u(rng_);
    o.set("distance", dist, cam.sigma_d0 + cam.sigma_d_rel * dist + cam.sigma_d_quad * dist * dist, 1.0);
    o.set("bearing", b, cam.sigma_bearing, 1.0);
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace mrt::map::bench
