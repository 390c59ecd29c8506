#include "mrt_robocup/team_percepts.h"

#include <algorithm>
#include <cmath>

namespace mrt::robocup {

std::vector<map::PerceptObject> team_percepts(const sim::World& w, const std::vector<sim::OtherRobot>& others,
                                              const Pose2D& pose, double range, double distance_noise,
                                              double bearing_noise, std::mt19937_64& rng) {
  sim::SensorsConfig cfg;
  cfg.vision_range = range;
  cfg.line_point_spacing = 1e3;  // lines are for localisation: one point per line, dropped below
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<map::PerceptObject> out;
  for (const sim::SeenObject& s : sim::vision_percepts(w, others, pose, cfg)) {
    if (s.membership_class != "Ball" && s.membership_class != "Robot") continue;
    map::PerceptObject p;
    p.name = s.name;
    p.membership_class = s.membership_class;
    const double sd = std::max(distance_noise * s.distance, 0.01), sb = std::max(bearing_noise, 1e-3);
    p.attributes["distance"] = {std::max(0.0, s.distance + sd * n01(rng)), "", sd, 1.0};
    p.attributes["bearing"] = {s.bearing + sb * n01(rng), "", sb, 1.0};
    p.attributes["color"] = {0.0, s.color, 0.0, 1.0};
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<AnchorView> anchor_views(const map::WorldModel& wm, double now) {
  std::vector<AnchorView> v;
  const map::Tracker& t = wm.tracker();
  for (const map::Anchor& a : t.anchors()) {
    if (a.status != map::AnchorStatus::kConfirmed && a.status != map::AnchorStatus::kCoasting) continue;
    const map::Vec4& x = a.fused.x;
    v.push_back({wm.model().at(a.class_index).name, x(0), x(1), x(2), x(3), t.reliability(a, now)});
  }
  return v;
}

scare::CrispMap team_crisp(const std::vector<AnchorView>& anchors, bool team_owns, const FieldGeometry& f,
                           double clearance) {
  scare::CrispMap c;
  const AnchorView* ball = nullptr;
  for (const AnchorView& a : anchors)
    if (a.membership_class == "Ball" && (!ball || a.reliability > ball->reliability)) ball = &a;
  if (!ball) {
    c["BallSeen"] = {0.0, 1.0};
    c["BallOwned"] = {team_owns ? 1.0 : 0.0, 1.0};
    return c;
  }
  const double bx = ball->x, by = ball->y, rel = ball->reliability;
  c["BallX"] = {bx, rel};
  c["BallY"] = {by, rel};
  c["BallSeen"] = {rel, 1.0};
  c["BallOwned"] = {team_owns ? 1.0 : 0.0, 1.0};
  // The shot line from the ball to the goal's open side (away from the
  // opponent nearest the goal centre).
  double keeper_y = 0.0, best = 1e9;
  for (const AnchorView& a : anchors)
    if (a.membership_class == "Opponent" && std::hypot(a.x - f.goal_x, a.y) < best) {
      best = std::hypot(a.x - f.goal_x, a.y);
      keeper_y = a.y;
    }
  const double ay = best < 2.0 ? (keeper_y > 0.0 ? -0.75 : 0.75) : (by >= 0.0 ? 0.75 : -0.75);
  const double dx = f.goal_x - bx, dy = ay - by, l2 = dx * dx + dy * dy;
  bool clear = true;
  double threat = 0.0;
  for (const AnchorView& a : anchors) {
    if (a.membership_class != "Opponent") continue;
    const double t = std::clamp(((a.x - bx) * dx + (a.y - by) * dy) / std::max(l2, 1e-9), 0.0, 1.0);
    if (std::hypot(bx + t * dx - a.x, by + t * dy - a.y) < clearance) clear = false;
    if (bx < -f.goal_x / 3.0 && std::hypot(a.x - bx, a.y - by) < 1.5) threat = 1.0;
  }
  // Far from the goal the carrier dribbles on (BringBall): a pass is for a
  // blocked shot within 6 m.
  if (std::hypot(dx, dy) > 6.0) clear = true;
  c["ShotClear"] = {clear ? 1.0 : 0.0, 1.0};
  c["Threat"] = {threat, 1.0};
  c["ReceiveX"] = {std::clamp(bx + 3.0, -f.goal_x + 3.0, f.goal_x - f.penalty_depth - 0.5), rel};
  c["ReceiveY"] = {by > 0.0 ? -2.0 : 2.0, rel};
  return c;
}

}  // namespace mrt::robocup
