// The Tracker's team side (tracker.h): teammates' tracks associated with
// the anchors, the fusion of each anchor's parts, teammates' poses refining
// classes, and the own tracks sent to the teammates.
#include "mrt_map/tracker.h"

#include <algorithm>
#include <map>

#include "mrt_map/assignment.h"
#include "mrt_map/kalman.h"

namespace mrt::map {

namespace {
// The anchor was linked to this teammate's track (robot, its symbol) before.
bool linked(const Anchor& a, const std::string& robot, std::uint32_t id) {
  const auto link = a.remote_ids.find(robot);
  return link != a.remote_ids.end() && link->second == id;
}
}  // namespace

void Tracker::associate_remote(double now, std::vector<RemoteTrack>& remote) {
  const double gate = model_.team().gate;
  const double radius = model_.tracker().maneuver_radius;
  const double fresh = model_.tracker().coast_after;
  std::map<std::string, std::vector<RemoteTrack*>> by_robot;
  for (RemoteTrack& t : remote) by_robot[t.robot].push_back(&t);
  for (const auto& [robot, tracks] : by_robot) {
    const std::size_t existing = anchors_.size();
    std::vector<std::vector<double>> cost(tracks.size(), std::vector<double>(existing, kInfeasible));
    for (std::size_t r = 0; r < tracks.size(); ++r)
      for (std::size_t c = 0; c < existing; ++c) {
        const Anchor& a = anchors_[c];
        if (!model_.compatible(tracks[r]->class_index, a.class_index)) continue;
        const Vec2 z = tracks[r]->estimate.x.head<2>();
        const double off = (z - a.fused.x.head<2>()).norm();
        // keep_teammate_link: its own symbol says it is this object, however far (a kick it saw first).
        if (off <= model_.at(a.class_index).keep_link && linked(a, robot, tracks[r]->id)) {
          cost[r][c] = 0.0;
          continue;
        }
        if (off > radius && outside_gate(a.fused, z, tracks[r]->estimate.P.topLeftCorner<2, 2>(), gate)) continue;
        const double d = mahalanobis2(a.fused, z, tracks[r]->estimate.P.topLeftCorner<2, 2>());
        const bool manoeuvre = a.status != AnchorStatus::kTentative && off <= radius;
        if (d > gate && !manoeuvre) continue;
        cost[r][c] = linked(a, robot, tracks[r]->id) ? 0.0 : std::min(d, gate);  // sticky while it gates
      }
    keep_lost_off_held(cost, gate);
    const std::vector<int> match = assign(cost, gate);
    for (std::size_t r = 0; r < tracks.size(); ++r) {
      RemoteTrack& t = *tracks[r];
      const bool is_fresh = t.last_seen >= now - fresh;
      Anchor* a = nullptr;
      if (match[r] >= 0) {
        a = &anchors_[static_cast<std::size_t>(match[r])];
        refine_class(*a, t.class_index, t.degree);
      } else if (is_fresh) {
        // A track inside another anchor's gate is the teammate's duplicate.
        bool gated = false;
        for (std::size_t k = 0; k < existing && !gated; ++k) gated = cost[r][k] < gate;
        if (gated) continue;
        const Vec2 z = t.estimate.x.head<2>();
        const Mat2 R = t.estimate.P.topLeftCorner<2, 2>();
        a = reidentify(t.class_index, z, R);
        const int card = a ? -1 : at_cardinality(t.class_index);
        if (card >= 0) {
          const int lost = claim_lost(card, {{z, R}})[0];
          if (lost >= 0) a = &anchors_[static_cast<std::size_t>(lost)];
        }
        if (a) {
          refine_class(*a, t.class_index, t.degree);
        } else {
          a = &create(now, t.class_index, t.degree);
          a->fused = t.estimate;
        }
      } else {
        continue;
      }
      a->remote_ids[robot] = t.id;
      if (is_fresh) {
        a->last_seen = std::max(a->last_seen, t.last_seen);
        a->sources.insert(t.sensors.begin(), t.sensors.end());
        seen_.insert(a->id);
      }
      a->remote[robot] = std::move(t);  // t's last use
    }
  }
}

void Tracker::fuse(double now) {
  for (Anchor& a : anchors_) {
    const auto rule = model_.at(a.class_index).fusion;
    const bool ci = rule == ClassDef::Fusion::kTeam ? model_.team().covariance_intersection
                                                    : rule == ClassDef::Fusion::kCovarianceIntersection;
    std::vector<const Estimate*> parts;
    if (a.has_local) parts.push_back(&a.local);
    for (const auto& [robot, t] : a.remote) parts.push_back(&t.estimate);
    if (parts.empty()) continue;
    // Only an own filter older than the last support left (teammates' just
    // ended): keep the team estimate, predicted (the stale one jumps, wide).
    if (a.remote.empty() && a.local_last_seen < a.last_seen && a.hits > 0) continue;
    Estimate f = *parts[0];
    for (std::size_t i = 1; i < parts.size(); ++i)
      f = ci ? covariance_intersection(f, *parts[i]) : fuse_estimates(f, *parts[i]);
    f.stamp = now;
    a.fused = f;
  }
}

void Tracker::set_teammate_pose(const std::string& robot, const Vec2& p, const Mat2& cov, double stamp) {
  teammates_[robot] = {p, cov, stamp};
}

void Tracker::refine_teammates(double now) {
  if (teammates_.empty()) return;
  for (Anchor& a : anchors_) {
    int target = -1;
    for (int c = 0; c < model_.size(); ++c)
      if (model_.at(c).refined_by_teammate_pose && c != a.class_index && model_.is_a(c, a.class_index)) target = c;
    if (target < 0) continue;
    for (const auto& [robot, t] : teammates_) {
      if (now - t.stamp > model_.team().max_latency) continue;
      if (mahalanobis2(a.fused, t.p, t.cov) <= model_.team().gate) {
        a.class_index = target;
        a.sources.insert(robot + "/pose");
        break;
      }
    }
  }
}

std::vector<RemoteTrack> Tracker::local_tracks(const std::string& robot) const {
  std::vector<RemoteTrack> out;
  for (const Anchor& a : anchors_) {
    if (!a.has_local || a.local_hits < model_.tracker().confirm_hits) continue;
    if (a.status == AnchorStatus::kDropped || now_ - a.local_last_seen > model_.tracker().coast_after) continue;
    RemoteTrack t;
    t.robot = robot;
    t.id = a.id;
    t.class_index = a.class_index;
    t.degree = a.degree;
    t.estimate = a.local;
    t.last_seen = a.local_last_seen;
    for (const std::string& s : a.sources)
      if (s.rfind(robot + "/", 0) == 0) t.sensors.insert(s);
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace mrt::map
