#include "mrt_scare/task.h"

#include "mrt_scare/sequencer.h"

#include <cmath>
#include <sstream>

namespace mrt::scare {

double distance(const Pose2D& p, const Point2D& q) { return std::hypot(q.x - p.x, q.y - p.y); }

bool WithinDistance::holds(const TaskContext& c) const {
  return scare::distance(c.pose, c.goal) <= distance_;
}

std::string WithinDistance::describe() const {
  std::ostringstream s;
  s << "within " << distance_ << " m";
  return s.str();
}

std::string Timeout::describe() const {
  std::ostringstream s;
  s << "timeout " << seconds_ << " s";
  if (per_metre_ != 0.0) s << " + " << per_metre_ << " s/m";
  return s.str();
}

TaskSpec TaskSpec::reach_path_point(double tolerance, double timeout, double per_metre) {
  TaskSpec t;
  t.name = "ReachPathPoint";
  t.success.push_back(std::make_shared<WithinDistance>(tolerance));
  t.failure.push_back(std::make_shared<Timeout>(timeout, per_metre));
  return t;
}

double TaskSpec::timeout_limit(double start_distance) const {
  double best = 0.0;
  for (const auto& c : failure)
    if (const auto* t = dynamic_cast<const Timeout*>(c.get()))
      best = std::max(best, t->limit(start_distance));
  return best;
}

const char* to_string(TaskState s) {
  switch (s) {
    case TaskState::kInactive: return "inactive";
    case TaskState::kActive: return "active";
    case TaskState::kSucceeded: return "succeeded";
    case TaskState::kFailed: return "failed";
    case TaskState::kAborted: return "aborted";
  }
  return "?";
}

Task::Task(TaskSpec spec, Point2D goal, std::size_t index)
    : spec_(std::move(spec)), goal_(goal), index_(index) {}

void Task::activate(double now, const Pose2D& pose) {
  state_ = TaskState::kActive;
  start_time_ = now;
  paused_ = 0.0;
  suspended_ = false;
  start_distance_ = distance(pose, goal_);
}

double Task::elapsed(double now) const {
  if (state_ == TaskState::kInactive) return 0.0;
  const double end = suspended_ ? suspended_at_ : now;
  return std::max(0.0, end - start_time_ - paused_);
}

bool FuzzyCondition::holds(const TaskContext& c) const {
  CrispMap data = c.world ? *c.world : CrispMap{};
  const GoalCrisp g = goal_crisp(c.pose, c.goal);
  data["GoalDistance"] = {g.distance_cm, 1.0};
  data["GoalBearing"] = {g.bearing_deg, 1.0};
  data["StartDistance"] = {c.start_distance * 100.0, 1.0};
  data["TaskElapsed"] = {c.elapsed, 1.0};
  model_->evaluate(data);
  return model_->degree(expression_) >= threshold_;
}

TaskState Task::update(double now, const Pose2D& pose, const CrispMap* world) {
  if (state_ != TaskState::kActive) return state_;
  TaskContext c;
  c.world = world;
  c.now = now;
  c.elapsed = elapsed(now);
  c.pose = pose;
  c.goal = goal_;
  c.start_distance = start_distance_;
  for (const auto& s : spec_.success)
    if (s->holds(c)) return state_ = TaskState::kSucceeded;
  if (suspended_) return state_;  // a person is driving: no timeout
  for (const auto& f : spec_.failure)
    if (f->holds(c)) return state_ = TaskState::kFailed;
  return state_;
}

void Task::suspend(double now) {
  if (suspended_ || state_ != TaskState::kActive) return;
  suspended_ = true;
  suspended_at_ = now;
}

void Task::resume(double now) {
  if (!suspended_) return;
  suspended_ = false;
  paused_ += std::max(0.0, now - suspended_at_);
}

void Task::abort() {
  if (state_ == TaskState::kActive || state_ == TaskState::kInactive) state_ = TaskState::kAborted;
}

}  // namespace mrt::scare
