#include "mrt_scare/path_cost.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace mrt::scare {

PlannerCost::Key PlannerCost::key(const Point2D& p) const {
  return {std::lround(p.x / options_.resolution), std::lround(p.y / options_.resolution)};
}

void PlannerCost::set_time(double now) {
  std::lock_guard<std::mutex> l(mutex_);
  now_ = now;
}

double PlannerCost::time(const RobotSpec& robot, const Pose2D& from, const Point2D& to) const {
  const double straight = std::hypot(to.x - from.x, to.y - from.y);
  std::lock_guard<std::mutex> l(mutex_);
  Entry& e = entries_[key(to)];
  e.from = from;
  e.to = to;
  e.requested = now_;
  if (std::isinf(e.factor)) return std::numeric_limits<double>::infinity();
  return straight * e.factor / robot.max_speed;
}

std::optional<std::pair<Pose2D, Point2D>> PlannerCost::next_query(double now) const {
  std::lock_guard<std::mutex> l(mutex_);
  const Entry* best = nullptr;
  for (auto it = entries_.begin(); it != entries_.end();)
    it = now - it->second.requested > options_.max_age ? entries_.erase(it) : std::next(it);
  for (const auto& [k, e] : entries_) {
    if (e.planned >= 0.0 && now - e.planned < options_.max_age) continue;
    if (!best || e.planned < best->planned) best = &e;  // never planned (-1) first, then the oldest
  }
  if (!best) return std::nullopt;
  return std::make_pair(best->from, best->to);
}

void PlannerCost::record(const Pose2D& from, const Point2D& to, std::optional<double> length, double now) {
  const double straight = std::hypot(to.x - from.x, to.y - from.y);
  std::lock_guard<std::mutex> l(mutex_);
  Entry& e = entries_[key(to)];
  e.planned = now;
  if (!length) {
    e.factor = std::numeric_limits<double>::infinity();
  } else {
    // A path shorter than the straight line (the planner's cell rounding)
    // or from on top of the target: no detour.
    e.factor = straight > 1e-6 ? std::max(1.0, *length / straight) : 1.0;
  }
}

double PlannerCost::detour(const Point2D& to) const {
  std::lock_guard<std::mutex> l(mutex_);
  const auto it = entries_.find(key(to));
  return it == entries_.end() ? 1.0 : it->second.factor;
}

}  // namespace mrt::scare
