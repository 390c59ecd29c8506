#include "mrt_map/world_model.h"

#include <cmath>
#include <utility>

#include "mrt_common/angle.h"

namespace mrt::map {

WorldModel::WorldModel(const ConceptualModel& model, WorldModelOptions options)
    : model_(model), options_(std::move(options)), classifier_(model), merger_(model), tracker_(model) {}

void WorldModel::set_robot_pose(const RobotPose& pose, double stamp) {
  pose_ = pose;
  tracker_.set_teammate_pose(options_.robot, Vec2(pose.x, pose.y), pose.cov + 1e-4 * Mat2::Identity(), stamp);
}

int WorldModel::add_percept(const std::vector<PerceptObject>& objects, const RobotPose& pose, double stamp,
                            double now, const std::string& sensor) {
  if (!std::isfinite(stamp) || std::fabs(now - stamp) > options_.max_percept_age) {
    counters_.stale += objects.size();
    return 0;
  }
  int n = 0;
  for (const PerceptObject& o : objects) {
    Rejection why = Rejection::kNone;
    auto obs = classifier_.observe(o, pose, stamp, options_.robot, sensor, &why);
    switch (why) {
      case Rejection::kUnknownClass: ++counters_.unknown_class; break;
      case Rejection::kNonFinite: ++counters_.non_finite; break;
      case Rejection::kNoPosition: ++counters_.no_position; break;
      case Rejection::kUnmatched: ++counters_.unmatched; break;
      case Rejection::kNone: break;
    }
    if (!obs) continue;
    if (!model_.world().contains(obs->z.x(), obs->z.y())) {
      ++counters_.outside_world;
      continue;
    }
    pending_.push_back(std::move(*obs));
    ++counters_.accepted;
    ++n;
  }
  return n;
}

void WorldModel::add_teammate_model(const std::string& robot, const std::vector<RemoteTrack>& tracks, double stamp,
                                    const RobotPose* pose) {
  if (robot == options_.robot) return;  // never our own data back
  teammates_[robot] = {tracks, stamp};
  if (pose) tracker_.set_teammate_pose(robot, Vec2(pose->x, pose->y), pose->cov + 1e-4 * Mat2::Identity(), stamp);
}

void WorldModel::update(double now) {
  const std::vector<Observation> merged = merger_.merge(pending_);
  pending_.clear();
  std::vector<RemoteTrack> remote;
  for (auto& [robot, m] : teammates_) {
    if (now - m.stamp > model_.team().max_latency) {
      counters_.stale_team += m.tracks.size();
      m.tracks.clear();
      continue;
    }
    for (RemoteTrack t : m.tracks) {
      t.robot = robot;
      if (!merger_.compensate(t, now)) ++counters_.stale_team;
      else if (!model_.world().contains(t.estimate.x(0), t.estimate.x(1))) ++counters_.outside_world;
      else remote.push_back(std::move(t));
    }
  }
  tracker_.cycle(now, merged, std::move(remote));
}

void WorldModel::set_parameter(const std::string& name, double value, double reliability, double) {
  parameters_[name] = {name, value, reliability};
}

double WorldModel::quantity(const CrispEntry& e, const Anchor& a) const {
  using Q = CrispEntry::Quantity;
  const Vec4& x = a.fused.x;
  const double dx = x(0) - pose_.x, dy = x(1) - pose_.y;
  switch (e.quantity) {
    case Q::kDistance: return std::hypot(dx, dy);
    case Q::kBearing: return mrt::common::normalize_angle(std::atan2(dy, dx) - pose_.theta);
    case Q::kX: return x(0);
    case Q::kY: return x(1);
    case Q::kVx: return x(2);
    case Q::kVy: return x(3);
    case Q::kSpeed: return std::hypot(x(2), x(3));
    case Q::kParameter: break;
  }
  return 0.0;
}

std::vector<CrispDatum> WorldModel::crisp(double now) const {
  std::vector<CrispDatum> out;
  for (const CrispEntry& e : model_.crisp()) {
    CrispDatum d{e.name, e.missing, 0.0};
    if (e.quantity == CrispEntry::Quantity::kParameter) {
      const auto it = parameters_.find(e.parameter);
      if (it != parameters_.end()) d = {e.name, it->second.value * e.scale, it->second.reliability};
      out.push_back(d);
      continue;
    }
    const Anchor* best = nullptr;
    double best_key = 0.0;
    for (const Anchor& a : tracker_.anchors()) {
      if (a.status != AnchorStatus::kConfirmed && a.status != AnchorStatus::kCoasting) continue;
      if (!model_.is_a(a.class_index, e.class_index)) continue;
      const double r = tracker_.reliability(a, now);
      if (r < e.min_reliability || r <= 0.0) continue;
      const double key = e.select == CrispEntry::Select::kNearest
                             ? -std::hypot(a.fused.x(0) - pose_.x, a.fused.x(1) - pose_.y)
                         : e.select == CrispEntry::Select::kBestSupported ? tracker_.support(a, now)
                                                                          : r;
      if (!best || key > best_key) {
        best = &a;
        best_key = key;
      }
    }
    if (best) d = {e.name, quantity(e, *best) * e.scale, tracker_.reliability(*best, now)};
    out.push_back(d);
  }
  return out;
}

}  // namespace mrt::map
