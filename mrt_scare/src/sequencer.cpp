#include "mrt_scare/sequencer.h"

#include <cmath>

#include "mrt_common/angle.h"

namespace mrt::scare {

const char* to_string(Mode m) { return m == Mode::kAuto ? "auto" : "manual"; }

const char* to_string(SequencerState s) {
  switch (s) {
    case SequencerState::kIdle: return "idle";
    case SequencerState::kRunning: return "running";
    case SequencerState::kWaitingForPlan: return "waiting_for_plan";
    case SequencerState::kDone: return "done";
    case SequencerState::kGaveUp: return "gave_up";
  }
  return "?";
}

const char* to_string(SequencerEvent::Type t) {
  using T = SequencerEvent::Type;
  switch (t) {
    case T::kPlanAccepted: return "plan_accepted";
    case T::kTaskStarted: return "task_started";
    case T::kTaskSucceeded: return "task_succeeded";
    case T::kTaskFailed: return "task_failed";
    case T::kPlanAborted: return "plan_aborted";
    case T::kReplanRequested: return "replan_requested";
    case T::kRouteCompleted: return "route_completed";
    case T::kGaveUp: return "gave_up";
    case T::kModeChanged: return "mode_changed";
  }
  return "?";
}

Sequencer::Sequencer(SequencerOptions options) : options_(std::move(options)) {}

void Sequencer::start_task(std::size_t index, double now, const Pose2D& pose,
                           std::vector<SequencerEvent>& ev) {
  task_.emplace(options_.path_task, plan_[index], index);
  task_->activate(now, pose);
  if (mode_ == Mode::kManual && options_.suspend_in_manual) task_->suspend(now);
  ev.push_back({SequencerEvent::Type::kTaskStarted, now, index, plan_[index], pose, 0.0, task_->timeout()});
}

std::vector<SequencerEvent> Sequencer::set_plan(const std::vector<Point2D>& points, double now,
                                                const Pose2D& pose) {
  std::vector<SequencerEvent> ev;
  if (task_ && task_->state() == TaskState::kActive) task_->abort();
  task_.reset();
  if (state_ != SequencerState::kWaitingForPlan) consecutive_aborts_ = 0;
  plan_ = points;
  ++plans_;
  ev.push_back({SequencerEvent::Type::kPlanAccepted, now, points.size(), {}, pose});
  if (points.empty()) {
    state_ = SequencerState::kIdle;
    return ev;
  }
  state_ = SequencerState::kRunning;
  start_task(0, now, pose, ev);
  auto more = update(now, pose);  // the first point may already be reached
  ev.insert(ev.end(), more.begin(), more.end());
  return ev;
}

std::vector<SequencerEvent> Sequencer::update(double now, const Pose2D& pose) {
  using T = SequencerEvent::Type;
  std::vector<SequencerEvent> ev;
  if (state_ == SequencerState::kWaitingForPlan && options_.replan_timeout > 0.0 &&
      now - replan_requested_at_ > options_.replan_timeout) {
    // The planner did not answer: ask again, from where the robot is now.
    replan_requested_at_ = now;
    SequencerEvent e = last_failure_;
    e.time = now;
    e.pose = pose;
    ev.push_back(e);
    return ev;
  }
  // Several path points can be reached in one update (they may lie close).
  while (state_ == SequencerState::kRunning && task_) {
    const TaskState s = task_->update(now, pose, &world_);
    const std::size_t i = task_->index();
    const double el = task_->elapsed(now), to = task_->timeout();
    if (s == TaskState::kSucceeded) {
      ++reached_;
      consecutive_aborts_ = 0;
      ev.push_back({T::kTaskSucceeded, now, i, plan_[i], pose, el, to});
      if (i + 1 < plan_.size()) {
        start_task(i + 1, now, pose, ev);
        continue;
      }
      task_.reset();
      state_ = SequencerState::kDone;
      ev.push_back({T::kRouteCompleted, now, i, plan_[i], pose, el, to});
    } else if (s == TaskState::kFailed) {
      ++failed_;
      ev.push_back({T::kTaskFailed, now, i, plan_[i], pose, el, to});
      if (task_->spec().on_failure == OnFailure::kSkip && i + 1 < plan_.size()) {
        start_task(i + 1, now, pose, ev);
        continue;
      }
      ++consecutive_aborts_;
      ev.push_back({T::kPlanAborted, now, i, plan_[i], pose, el, to});
      task_.reset();
      if (options_.max_replans > 0 && consecutive_aborts_ > options_.max_replans) {
        state_ = SequencerState::kGaveUp;
        ev.push_back({T::kGaveUp, now, i, plan_[i], pose, el, to});
      } else {
        ++replans_;
        state_ = SequencerState::kWaitingForPlan;
        replan_requested_at_ = now;
        last_failure_ = {T::kReplanRequested, now, i, plan_[i], pose, el, to};
        ev.push_back(last_failure_);
      }
    }
    break;
  }
  return ev;
}

std::vector<SequencerEvent> Sequencer::set_mode(Mode mode, double now) {
  std::vector<SequencerEvent> ev;
  if (mode == mode_) return ev;
  mode_ = mode;
  if (task_ && options_.suspend_in_manual) {
    if (mode == Mode::kManual) task_->suspend(now);
    else task_->resume(now);
  }
  ev.push_back({SequencerEvent::Type::kModeChanged, now, 0, {}, {}});
  return ev;
}

GoalCrisp goal_crisp(const Pose2D& pose, const Point2D& goal) {
  const Point2D local = pose.inverse_transform(goal);
  GoalCrisp g;
  g.distance_cm = 100.0 * std::hypot(local.x, local.y);
  g.bearing_deg = g.distance_cm > 0.0 ? common::rad_to_deg(std::atan2(local.y, local.x)) : 0.0;
  if (g.bearing_deg <= -180.0) g.bearing_deg += 360.0;
  return g;
}

}  // namespace mrt::scare
