#include "mrt_scare/sequencer.h"

#include <cmath>
#include <stdexcept>

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
    case SequencerState::kAborted: return "aborted";
    case SequencerState::kHandedBack: return "handed_back";
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
    case T::kJobAccepted: return "job_accepted";
    case T::kTaskRetried: return "task_retried";
    case T::kJobAborted: return "job_aborted";
    case T::kHandedBack: return "handed_back";
    case T::kJobDone: return "job_done";
  }
  return "?";
}

Sequencer::Sequencer(SequencerOptions options) : options_(std::move(options)) {}

bool Sequencer::knows_job(const std::string& job) const {
  return options_.machines && options_.machines->job_tasks(job) != nullptr;
}

double Sequencer::active_timeout() const {
  if (!task_) return 0.0;
  return run_ ? run_->limit() : task_->timeout();
}

std::string Sequencer::active_state() const { return run_ ? run_->state() : std::string(); }

CrispMap Sequencer::task_crisp(double now, const Pose2D& pose) const {
  CrispMap d = world_;
  if (job_.empty()) {
    const GoalCrisp g = goal_crisp(pose, task_->goal());
    d["GoalDistance"] = {g.distance_cm, 1.0};
    d["GoalBearing"] = {g.bearing_deg, 1.0};
    d["StartDistance"] = {task_->start_distance() * 100.0, 1.0};
  }
  d["TaskElapsed"] = {task_->elapsed(now), 1.0};
  return d;
}

void Sequencer::start_task(std::size_t index, double now, const Pose2D& pose,
                           std::vector<SequencerEvent>& ev) {
  const TaskDefinition* def = nullptr;
  TaskSpec spec = options_.path_task;
  if (!job_.empty()) {
    spec = TaskSpec{};  // the machine decides; the Task keeps the clock
    spec.name = (*job_tasks_)[index];
  }
  if (options_.machines) {
    const auto it = options_.machines->tasks.find(spec.name);
    if (it != options_.machines->tasks.end()) def = &it->second;
  }
  task_.emplace(spec, step_point(index), index);
  task_->activate(now, pose);
  if (mode_ == Mode::kManual && options_.suspend_in_manual) task_->suspend(now);
  run_.reset();
  if (def) {
    run_.emplace(*options_.machines, *def);
    run_->start(0.0, task_crisp(now, pose));  // machine time: the task's elapsed time
  }
  ev.push_back({SequencerEvent::Type::kTaskStarted, now, index, step_point(index), pose, 0.0, active_timeout()});
}

void Sequencer::name_events(std::vector<SequencerEvent>& ev) const {
  for (auto& e : ev)
    if (e.task.empty() && e.type != SequencerEvent::Type::kPlanAccepted &&
        e.type != SequencerEvent::Type::kJobAccepted && e.type != SequencerEvent::Type::kModeChanged)
      e.task = job_.empty() ? options_.path_task.name
                            : (e.index < job_tasks_->size() ? (*job_tasks_)[e.index] : job_);
}

std::vector<SequencerEvent> Sequencer::set_plan(const std::vector<Point2D>& points, double now,
                                                const Pose2D& pose) {
  std::vector<SequencerEvent> ev;
  if (task_ && task_->state() == TaskState::kActive) task_->abort();
  task_.reset();
  run_.reset();
  job_.clear();
  job_tasks_ = nullptr;
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
  name_events(ev);
  return ev;
}

std::vector<SequencerEvent> Sequencer::set_job(const std::string& job, double now, const Pose2D& pose) {
  const std::vector<std::string>* tasks = nullptr;
  if (!job.empty()) {
    if (!knows_job(job)) throw std::invalid_argument("job '" + job + "' is not defined in the task file");
    tasks = options_.machines->job_tasks(job);
  }
  std::vector<SequencerEvent> ev;
  if (task_ && task_->state() == TaskState::kActive) task_->abort();
  task_.reset();
  run_.reset();
  plan_.clear();
  job_ = job;
  job_tasks_ = tasks;
  consecutive_aborts_ = 0;
  ev.push_back({SequencerEvent::Type::kJobAccepted, now, tasks ? tasks->size() : 0, {}, pose});
  ev.back().task = job;
  if (!tasks) {
    state_ = SequencerState::kIdle;
    return ev;
  }
  state_ = SequencerState::kRunning;
  start_task(0, now, pose, ev);
  auto more = update(now, pose);
  ev.insert(ev.end(), more.begin(), more.end());
  name_events(ev);
  return ev;
}

TaskState Sequencer::poll(double now, const Pose2D& pose, TaskRun::Outcome& outcome,
                          std::vector<SequencerEvent>& ev) {
  using O = TaskRun::Outcome;
  if (!run_) {
    const TaskState s = task_->update(now, pose, &world_);
    outcome = s == TaskState::kSucceeded ? O::kSucceeded : s == TaskState::kFailed ? O::kReplan : O::kRunning;
    return s;
  }
  const int retries = run_->retries_used();
  outcome = run_->update(task_->elapsed(now), task_crisp(now, pose));
  if (outcome == O::kRunning && run_->retries_used() > retries) {
    const std::size_t i = task_->index();
    ev.push_back({SequencerEvent::Type::kTaskRetried, now, i, step_point(i), pose, task_->elapsed(now),
                  run_->limit(), "", run_->reason()});
  }
  if (outcome == O::kRunning) return TaskState::kActive;
  if (outcome == O::kSucceeded) return TaskState::kSucceeded;
  return TaskState::kFailed;
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
  // Several steps can end in one update (path points may lie close).
  while (state_ == SequencerState::kRunning && task_) {
    TaskRun::Outcome outcome = TaskRun::Outcome::kRunning;
    const double to = active_timeout();
    const TaskState s = poll(now, pose, outcome, ev);
    const std::size_t i = task_->index();
    const double el = task_->elapsed(now);
    const std::string reason = run_ ? run_->reason() : (s == TaskState::kSucceeded ? "success" : "timeout");
    if (s == TaskState::kSucceeded) {
      ++reached_;
      consecutive_aborts_ = 0;
      ev.push_back({T::kTaskSucceeded, now, i, step_point(i), pose, el, to, "", reason});
      if (i + 1 < steps()) {
        start_task(i + 1, now, pose, ev);
        continue;
      }
      task_.reset();
      run_.reset();
      state_ = SequencerState::kDone;
      ev.push_back({job_.empty() ? T::kRouteCompleted : T::kJobDone, now, i, step_point(i), pose, el, to});
    } else if (s == TaskState::kFailed) {
      ++failed_;
      const SequencerEvent failed{T::kTaskFailed, now, i, step_point(i), pose, el, to, "", reason};
      ev.push_back(failed);
      if (!run_ && task_->spec().on_failure == OnFailure::kSkip && i + 1 < steps()) {
        start_task(i + 1, now, pose, ev);
        continue;
      }
      on_failure(outcome, failed, now, pose, ev);
    }
    break;
  }
  name_events(ev);
  return ev;
}

void Sequencer::on_failure(TaskRun::Outcome outcome, const SequencerEvent& failed, double now, const Pose2D& pose,
                           std::vector<SequencerEvent>& ev) {
  using T = SequencerEvent::Type;
  task_.reset();
  run_.reset();
  SequencerEvent e = failed;
  if (outcome == TaskRun::Outcome::kAborted || outcome == TaskRun::Outcome::kHandBack) {
    const bool back = outcome == TaskRun::Outcome::kHandBack;
    state_ = back ? SequencerState::kHandedBack : SequencerState::kAborted;
    e.type = back ? T::kHandedBack : T::kJobAborted;
    ev.push_back(e);
    return;
  }
  // Re-plan: the plan (or the job's schedule) is aborted and made again.
  ++consecutive_aborts_;
  e.type = T::kPlanAborted;
  ev.push_back(e);
  if (options_.max_replans > 0 && consecutive_aborts_ > options_.max_replans) {
    state_ = SequencerState::kGaveUp;
    e.type = T::kGaveUp;
    ev.push_back(e);
    return;
  }
  ++replans_;
  if (!job_.empty()) {  // a job is re-scheduled from its first task at once
    start_task(0, now, pose, ev);
    return;
  }
  state_ = SequencerState::kWaitingForPlan;
  replan_requested_at_ = now;
  last_failure_ = e;
  last_failure_.type = T::kReplanRequested;
  ev.push_back(last_failure_);
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
