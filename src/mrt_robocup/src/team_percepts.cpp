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
    if (s.membership_class != common::percept_class::kBall && s.membership_class != common::percept_class::kRobot)
      continue;
    map::PerceptObject p(s.name, s.membership_class);
    const double sd = std::max(distance_noise * s.distance, 0.01), sb = std::max(bearing_noise, 1e-3);
    const double d = std::max(0.0, s.distance + sd * n01(rng));  // the distance's draw first
    p.set("distance", d, sd).set("bearing", s.bearing + sb * n01(rng), sb);
    p.attributes.push_back({"color", 0.0, s.color, 0.0, 1.0});
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

}  // namespace mrt::robocup
