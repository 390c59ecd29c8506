#include "mrt_followme/guide.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mrt::followme {

namespace {

double dist(const Point2D& a, const Point2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
Point2D xy(const Pose2D& p) { return {p.x, p.y}; }
constexpr double kSeen = 1.0;  // s: a track younger than this is "in sight"
constexpr std::size_t kWindow = 12;  // plan points searched ahead for the nearest

}  // namespace

const char* to_string(Job j) {
  switch (j) {
    case Job::kReplan: return "Replan";
    case Job::kGuide: return "Guide";
    case Job::kWaitVisitor: return "WaitVisitor";
    case Job::kFollowVisitor: return "FollowVisitor";
    case Job::kDone: return "Done";
  }
  return "?";
}

Guide::Guide(GuideOptions options, std::vector<Exhibit> tour) : opt_(options), tour_(std::move(tour)) {
  if (tour_.empty()) job_ = Job::kDone;
}

void Guide::enter(Job j, double t, const std::string& what) {
  job_ = j;
  entered_ = t;
  events_.push_back({t, what, current_ < tour_.size() ? tour_[current_].name : ""});
  requested_ = waiting_ = false;
  look_ = still_ = 0.0;
  called_ = false;
  if (j == Job::kReplan) {
    plan_.clear();
    ++replans_;
  }
}

void Guide::next_exhibit(double t) {
  visited_.push_back(tour_[current_].name);
  events_.push_back({t, "visited", tour_[current_].name});
  ++current_;
  looked_ = false;
}

void Guide::set_plan(std::vector<Point2D> path, double t) {
  if (job_ != Job::kReplan) return;
  requested_ = false;
  if (path.empty()) return;
  plan_ = std::move(path);
  index_ = 0;
  enter(Job::kGuide, t, "guide");
}

void Guide::invalidate_plan(double t, const std::string& why) {
  if (job_ == Job::kGuide) enter(Job::kReplan, t, why);
}

void Guide::close_door(const Door& d, double t, double replan_delay) {
  closed_.push_back(d);
  if (replan_delay <= 0.0) {
    replan_at_.reset();
    invalidate_plan(t, "door_closed");
  } else {
    replan_at_ = t + replan_delay;
  }
}

std::vector<DoorDisc> door_discs(const Door& d, double spacing, double radius) {
  const double len = dist(d.a, d.b);
  const int n = std::max(2, static_cast<int>(std::ceil(len / spacing)) + 1);
  std::vector<DoorDisc> out;
  for (int i = 0; i < n; ++i) {
    const double k = static_cast<double>(i) / (n - 1);
    out.push_back({d.name + "_" + std::to_string(i), {d.a.x + k * (d.b.x - d.a.x), d.a.y + k * (d.b.y - d.a.y)}, radius});
  }
  return out;
}

void Guide::set_tour(std::vector<Exhibit> tour, double t) {
  tour_ = std::move(tour);
  current_ = 0;
  looked_ = false;
  enter(tour_.empty() ? Job::kDone : Job::kReplan, t, "new_tour");
}

GuideOutput Guide::update(const GuideInput& in) {
  GuideOutput out;
  dt_ = std::max(0.0, in.t - last_t_);
  last_t_ = in.t;
  if (replan_at_ && in.t >= *replan_at_) {  // a door closed a moment ago
    replan_at_.reset();
    invalidate_plan(in.t, "door_closed");
  }
  switch (job_) {
    case Job::kReplan:
      if (!requested_) {
        out.plan_request = tour_[current_].stop;
        requested_ = true;
      }
      return out;
    case Job::kGuide: return guide(in);
    case Job::kWaitVisitor: return wait_visitor(in);
    case Job::kFollowVisitor: return follow_visitor(in);
    case Job::kDone: return out;
  }
  return out;
}

// Follow the plan; the exception "visitor behind": stand while it is
// farther than keep_max (or out of sight) until it is within keep_resume;
// "visitor lost": out of sight for lost_time -> FollowVisitor.
GuideOutput Guide::guide(const GuideInput& in) {
  GuideOutput out;
  const bool seen = in.visitor && in.t - in.visitor->last_seen < kSeen;
  if (!in.visitor || in.t - in.visitor->last_seen > opt_.lost_time) {
    if (in.visitor) {
      wandering_ = false;
      enter(Job::kFollowVisitor, in.t, "lost");
    }
    return out;
  }
  const double dv = dist(xy(in.pose), in.visitor->position);
  if (waiting_) {
    if (seen && dv < opt_.keep_resume) waiting_ = false;
  } else if (!seen || dv > opt_.keep_max) {
    waiting_ = true;
  }
  const Point2D p = xy(in.pose);
  // Skip what is behind: the nearest plan point a short way ahead (not the
  // nearest overall, which may lie beyond a wall), then look ahead.
  std::size_t best = index_;
  for (std::size_t j = index_; j < plan_.size() && j < index_ + kWindow; ++j)
    if (dist(p, plan_[j]) < dist(p, plan_[best])) best = j;
  index_ = best;
  while (index_ + 1 < plan_.size() && dist(p, plan_[index_]) < opt_.lookahead) ++index_;
  if (index_ + 1 == plan_.size() && dist(p, plan_.back()) < opt_.arrive_tolerance) {
    enter(Job::kWaitVisitor, in.t, "arrived");
    return out;
  }
  if (!waiting_) out.goal = plan_[index_];
  return out;
}

// Exceptions: "wandered" (the visitor far from the exhibit and from the
// robot) -> FollowVisitor; "lost" -> FollowVisitor.
GuideOutput Guide::wait_visitor(const GuideInput& in) {
  GuideOutput out;
  if (!in.visitor) return out;
  const Exhibit& e = tour_[current_];
  const double dt = dt_;
  const VisitorTrack& v = *in.visitor;
  const bool seen = in.t - v.last_seen < kSeen;
  if (seen && dist(v.position, e.spot) < opt_.look_radius && v.speed() < opt_.still_speed) {
    look_ += dt;
    if (look_ >= opt_.look_time) looked_ = true;
  }
  const double dr = dist(v.position, xy(in.pose));
  // Ready: it has looked, left the spot and stands by the robot (one
  // passing by on its way elsewhere is not ready).
  if (seen && looked_ && dr < opt_.ready_distance && dist(v.position, e.spot) > 0.5 * opt_.look_radius &&
      v.speed() < opt_.still_speed) {
    next_exhibit(in.t);
    enter(current_ == tour_.size() ? Job::kDone : Job::kReplan, in.t, current_ == tour_.size() ? "done" : "ready");
    return out;
  }
  // The exception "no visit": the visitor stays by the robot (it looked
  // while out of sight, or does not care for this exhibit): go on.
  if (seen && dr < opt_.ready_distance && in.t - entered_ > opt_.max_wait) {
    events_.push_back({in.t, "moved_on", e.name});
    next_exhibit(in.t);
    enter(current_ == tour_.size() ? Job::kDone : Job::kReplan, in.t, current_ == tour_.size() ? "done" : "ready");
    return out;
  }
  const bool wandered = seen && dist(v.position, e.spot) > opt_.wander_distance && dr > opt_.wander_distance;
  if (wandered || in.t - v.last_seen > opt_.lost_time) {
    if (looked_) next_exhibit(in.t);
    wandering_ = wandered;
    enter(Job::kFollowVisitor, in.t, wandered ? "wander" : "lost");
  }
  return out;
}

// Keep follow_distance from the visitor (its last position when out of
// sight); once it has stood still for call_after, call it; when it is back
// near the robot (after the call, or by itself) -> Replan.
GuideOutput Guide::follow_visitor(const GuideInput& in) {
  GuideOutput out;
  const VisitorTrack& v = *in.visitor;
  const bool seen = in.t - v.last_seen < kSeen;
  const Point2D p = xy(in.pose);
  const double d = dist(p, v.position);
  // out of sight: go closer to where it was last seen, to look round
  const double keep = seen ? opt_.follow_distance : 1.0;
  if (d > keep + 0.3) {
    const double k = (d - keep) / d;
    out.goal = Point2D{p.x + (v.position.x - p.x) * k, p.y + (v.position.y - p.y) * k};
  }
  if (seen && v.speed() < opt_.still_speed && d < opt_.follow_distance + 0.6) {
    still_ += dt_;
  } else {
    still_ = 0.0;
  }
  if (!called_ && (still_ >= opt_.call_after || !wandering_)) {
    called_ = true;
    called_at_ = in.t;
    out.call_visitor = true;
    events_.push_back({in.t, "call", current_ < tour_.size() ? tour_[current_].name : ""});
  }
  if (seen && called_ && in.t - called_at_ > 1.0 && d < opt_.ready_distance && v.speed() < opt_.still_speed) {
    if (wandering_) ++wanders_;
    wandering_ = false;
    if (current_ == tour_.size()) {
      enter(Job::kDone, in.t, "done");
    } else {
      enter(Job::kReplan, in.t, "back");
    }
  }
  return out;
}

}  // namespace mrt::followme
