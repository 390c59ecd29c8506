#include "team_sim.h"

#include <cmath>

namespace mrt::map::bench {

namespace {
constexpr double kHalfX = 9.0, kHalfY = 6.0;  // MSL field, as mrt_sim's msl_field.yaml
}

TeamSim::TeamSim(unsigned seed, int teammates, int opponents) : rng_(seed) {
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
}

Vec2 TeamSim::random_point() {
  std::uniform_real_distribution<double> ux(-kHalfX + 0.5, kHalfX - 0.5), uy(-kHalfY + 0.5, kHalfY - 0.5);
  return Vec2(ux(rng_), uy(rng_));
}

void TeamSim::move(Body& b, double dt) {
  const Vec2 d = b.goal - b.p;
  if (d.norm() < 0.2) b.goal = random_point();
  // Bounded acceleration (3 m/s^2, an MSL robot's order of magnitude).
  const Vec2 want = (b.goal - b.p).normalized() * b.speed;
  const Vec2 dv = want - b.v;
  const double max_dv = 3.0 * dt;
  b.v += dv.norm() > max_dv ? Vec2(dv.normalized() * max_dv) : dv;
  b.p += b.v * dt;
}

void TeamSim::step(double dt) {
  for (Body& b : mates_) move(b, dt);
  for (Body& b : opps_) move(b, dt);
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
    if (dist > cam.range || dist < 1e-3 || u(rng_) > cam.p_detect) return;
    if (occluded(me.p, target, skip_mate, skip_opp)) return;
    const double sd = cam.sigma_d0 + cam.sigma_d_rel * dist;
    // Measured relative to the TRUE pose; interpreted from the believed one.
    PerceptObject o;
    o.membership_class = cls;
    o.attributes["color"].symbol = color;
    o.attributes["distance"] = {dist + sd * n(rng_), "", sd, 1.0};
    o.attributes["bearing"] = {std::atan2(d.y(), d.x()) - heading + cam.sigma_bearing * n(rng_), "",
                               cam.sigma_bearing, 1.0};
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
    o.attributes["color"].symbol = "orange";
    const double dist = cam.range * std::sqrt(u(rng_)), b = 2 * M_PI * u(rng_);
    o.attributes["distance"] = {dist, "", cam.sigma_d0 + cam.sigma_d_rel * dist, 1.0};
    o.attributes["bearing"] = {b, "", cam.sigma_bearing, 1.0};
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace mrt::map::bench
