#include "mrt_spike/obstacle_tracker.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

namespace mrt::spike {

namespace {

// The attribute's number when it is given, numeric and finite.
std::optional<double> finite_number(const mrt::common::PerceptObject& o, const char* name) {
  const std::optional<double> v = o.number(name);
  if (v && std::isfinite(*v)) return v;
  return std::nullopt;
}

}  // namespace

ObstacleTracker::ObstacleTracker(ObstacleTrackerOptions options, ObstacleSink& sink)
    : options_(std::move(options)), sink_(sink) {}

bool ObstacleTracker::is_obstacle(const std::string& cls) const {
  return std::find(options_.classes.begin(), options_.classes.end(), cls) != options_.classes.end();
}

// A new track or a move; without a velocity, the one from the last sighting.
void ObstacleTracker::update(const std::string& key, TrackedObstacle o, bool has_velocity) {
  auto [it, fresh] = tracks_.try_emplace(key);
  TrackedObstacle& tr = it->second;
  if (fresh) tr.id = next_id_++;
  const double dt = o.seen - tr.seen;
  if (!has_velocity && !fresh && dt > 1e-3) o.vx = (o.x - tr.x) / dt, o.vy = (o.y - tr.y) / dt;
  o.id = tr.id;
  sink_.set_obstacle(o.id, o.x, o.y, o.radius, o.vx, o.vy);
  tr = o;
  changed_ = true;
}

void ObstacleTracker::remove(std::map<std::string, TrackedObstacle>::iterator& it) {
  sink_.remove_obstacle(it->second.id);
  it = tracks_.erase(it);
  changed_ = true;
}

std::size_t ObstacleTracker::add_percept(const std::string& robot,
                                         const std::vector<mrt::common::PerceptObject>& objects,
                                         const mrt::common::Pose2D& to_map, double stamp) {
  std::size_t dropped = 0;
  for (const auto& ob : objects) {
    if (!is_obstacle(ob.membership_class)) continue;
    const std::optional<mrt::common::Cartesian> local = mrt::common::cartesian(ob);
    if (!local || !std::isfinite(local->x) || !std::isfinite(local->y)) {
      ++dropped;
      continue;
    }
    const mrt::common::Point2D p = to_map.transform({local->x, local->y});
    const std::optional<double> vx = finite_number(ob, "vx"), vy = finite_number(ob, "vy");
    TrackedObstacle o;
    o.x = p.x, o.y = p.y;
    o.radius = finite_number(ob, "radius").value_or(options_.default_radius);
    o.vx = vx.value_or(0.0), o.vy = vy.value_or(0.0);
    o.seen = stamp;
    update(robot + "/" + ob.name, o, vx && vy);
  }
  dropped_ += dropped;
  return dropped;
}

std::size_t ObstacleTracker::add_world_model(const std::string& robot, const std::vector<WorldModelAnchor>& anchors,
                                             const mrt::common::Pose2D& to_map, double stamp) {
  const double c = std::cos(to_map.theta), s = std::sin(to_map.theta);
  const std::string prefix = "world_model:" + robot + "/";
  std::set<std::string> seen;
  std::size_t dropped = 0;
  for (const WorldModelAnchor& a : anchors) {
    if (a.tentative || !is_obstacle(a.membership_class)) continue;
    if (!std::isfinite(a.x) || !std::isfinite(a.y)) {
      ++dropped;
      continue;
    }
    TrackedObstacle o;
    o.x = to_map.x + c * a.x - s * a.y, o.y = to_map.y + s * a.x + c * a.y;
    o.vx = std::isfinite(a.vx) ? c * a.vx - s * a.vy : 0.0;
    o.vy = std::isfinite(a.vy) ? s * a.vx + c * a.vy : 0.0;
    const double var = std::max(a.var_x, a.var_y);
    const double sigma = std::isfinite(var) && var > 0 ? std::sqrt(var) : 0.0;
    o.radius = options_.default_radius + options_.anchor_sigmas * sigma;
    o.seen = stamp;
    const std::string key = prefix + std::to_string(a.id);
    update(key, o, true);
    seen.insert(key);
  }
  // the producer's tracks: the keys from the prefix on that start with it
  for (auto it = tracks_.lower_bound(prefix);
       it != tracks_.end() && it->first.compare(0, prefix.size(), prefix) == 0;) {
    if (seen.count(it->first)) ++it;
    else remove(it);
  }
  dropped_ += dropped;
  return dropped;
}

std::size_t ObstacleTracker::expire(double now) {
  std::size_t removed = 0;
  for (auto it = tracks_.begin(); it != tracks_.end();) {
    if (now - it->second.seen > options_.timeout) {
      remove(it);
      ++removed;
    } else {
      ++it;
    }
  }
  return removed;
}

bool ObstacleTracker::take_changed() {
  const bool c = changed_;
  changed_ = false;
  return c;
}

}  // namespace mrt::spike
