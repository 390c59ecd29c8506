// The optical mouse: ideal and physical models (mouse_model.h).
#include "mrt_sim/mouse_model.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mrt::sim {

namespace {
constexpr double kG = 9.80665;  // m/s^2 per g

// The noise and fault factor of manual §4.2 for one step: the length
// shrinks, the direction never changes. Sets `fault` when one was drawn.
double noise_and_fault(const MouseConfig& c, std::mt19937_64& rng, bool* fault) {
  double k = 1.0;
  if (c.noise > 0.0) k = std::max(0.0, 1.0 + c.noise * std::normal_distribution<double>()(rng));
  if (c.fault_rate > 0.0 && std::uniform_real_distribution<double>()(rng) < c.fault_rate) {
    const double u = 1.0 - std::uniform_real_distribution<double>()(rng);  // (0, 1]
    k *= 1.0 - u * c.fault_max_fraction;
    *fault = true;
  }
  return k;
}
}  // namespace

Point2D mouse_displacement(const Pose2D& mount, const Twist2D& t, double dt) {
  // Velocity of the mouse point in the body frame, constant under a constant twist.
  const double ux = t.vx - t.omega * mount.y, uy = t.vy + t.omega * mount.x;
  const double c = std::cos(mount.theta), s = std::sin(mount.theta);
  return {dt * (c * ux + s * uy), dt * (-s * ux + c * uy)};
}

FloorUnder floor_under(const std::vector<Surface>& surfaces, const Point2D& p) {
  FloorUnder f;
  for (const Surface& s : surfaces)
    if (p.x >= s.min_x && p.x <= s.max_x && p.y >= s.min_y && p.y <= s.max_y) f = {s.resolution, s.clearance};
  return f;
}

MouseModel::MouseModel(MouseConfig cfg) : cfg_(std::move(cfg)) {}

void MouseModel::accumulate(double dx_counts, double dy_counts) {
  acc_x_ += dx_counts;
  acc_y_ += dy_counts;
  // Move whole counts out, keeping the remainder in [0, 1) (floor, as a
  // position encoder does): the counts read so far are always the floor of
  // the true total, so every report is off by less than one count, also
  // when the motion reverses (truncation towards zero would keep a
  // remainder in (-1, 1) and could be off by almost two counts then). The
  // 1e-9 count tolerance absorbs rounding of sums such as 100 x 0.3.
  const double wx = std::floor(acc_x_ + 1e-9);
  const double wy = std::floor(acc_y_ + 1e-9);
  out_x_ += static_cast<int>(wx);
  out_y_ += static_cast<int>(wy);
  acc_x_ -= wx;
  acc_y_ -= wy;
}

bool MouseModel::step(const Twist2D& t, double dt, std::mt19937_64& rng) {
  const Point2D d = mouse_displacement(cfg_.mount, t, dt);
  bool fault = false;
  const double scale = cfg_.counts_per_m * noise_and_fault(cfg_, rng, &fault);
  accumulate(d.x * scale, d.y * scale);
  return fault;
}

bool MouseModel::step(const Twist2D& t, const Pose2D& body, double time, double dt,
                      const std::vector<Surface>& surfaces, std::mt19937_64& rng) {
  const MousePhysics& ph = cfg_.physics;
  if (!ph.enabled) {
    last_report_ = time;
    return step(t, dt, rng);
  }
  const Point2D d = mouse_displacement(cfg_.mount, t, dt);
  bool fault = false;
  double scale = cfg_.counts_per_m * noise_and_fault(cfg_, rng, &fault);
  // The mouse's velocity in the world frame (body-frame velocity rotated by
  // the heading; the mount's rotation does not change its length or change).
  const double ux = t.vx - t.omega * cfg_.mount.y, uy = t.vy + t.omega * cfg_.mount.x;
  const double c = std::cos(body.theta), s = std::sin(body.theta);
  const double vx = c * ux - s * uy, vy = s * ux + c * uy;
  const double accel = std::hypot(vx - vx_, vy - vy_) / dt;
  vx_ = vx;
  vy_ = vy;
  const FloorUnder f = floor_under(surfaces, body.transform({cfg_.mount.x, cfg_.mount.y}));
  const double h = ph.height + f.clearance;
  scale *= f.resolution * std::max(0.0, 1.0 - ph.height_gain * h);
  bool lost = true;
  if (h > ph.liftoff) ++losses_.lifted;
  else if (std::hypot(vx, vy) > ph.max_speed) ++losses_.too_fast;
  else if (accel > ph.max_accel * kG) ++losses_.too_hard;
  else lost = false;
  if (!lost) accumulate(d.x * scale, d.y * scale);
  // Reports on the mouse's own clock: report k at local time phase + k /
  // rate, i.e. at simulation time (phase + k / rate) / (1 + drift).
  const double speedup = 1.0 + ph.drift_ppm * 1e-6;
  bool due = false;
  while ((ph.phase + static_cast<double>(next_report_) / ph.report_rate) / speedup <= time + 1e-12) {
    ++next_report_;
    due = true;
  }
  if (due) {
    pending_.push_back({time, out_x_, out_y_});
    out_x_ = out_y_ = 0;
    last_report_ = time;
  }
  return fault || lost;
}

void MouseModel::read(int& dx, int& dy, std::vector<MouseReport>* reports) {
  if (reports) reports->clear();
  if (!cfg_.physics.enabled) {
    dx = out_x_;
    dy = out_y_;
    out_x_ = out_y_ = 0;
    return;
  }
  dx = dy = 0;
  for (const MouseReport& r : pending_) {
    dx += r.dx;
    dy += r.dy;
  }
  if (reports) *reports = std::move(pending_);
  pending_.clear();
}

}  // namespace mrt::sim
