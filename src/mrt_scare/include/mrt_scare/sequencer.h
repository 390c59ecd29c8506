// The SCARE sequencer: activates, monitors and terminates the tasks of a
// plan and handles their exceptions (manual ch. 11; Roby, §2.3.1). ROS-free.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mrt_scare/task.h"
#include "mrt_scare/task_machine.h"

namespace mrt::scare {

/// Auto / Manual (the Status flag of manual §10.4.10).
enum class Mode { kAuto, kManual };
const char* to_string(Mode m);

struct SequencerOptions {
  TaskSpec path_task = TaskSpec::reach_path_point(0.5, 30.0, 0.0);
  /// Consecutive aborted plans after which the sequencer gives up (0 = never).
  /// A plan that does not answer a re-plan request starts the count afresh.
  int max_replans = 5;
  /// s waiting for the planner's answer after which the re-plan request is
  /// sent again, from the pose at that time (0 = never).
  double replan_timeout = 10.0;
  /// In Manual mode the active task is suspended (its timeout clock stops).
  bool suspend_in_manual = true;
  /// Task machines (task_machine.h): when set, a path point runs the machine
  /// named path_task.name (path_task then carries only the name) and a job
  /// runs its tasks' machines. Null: the single-state TaskSpec above.
  std::shared_ptr<const TaskLibrary> machines;
};

/// kAborted: a task's `abort` handler (or exhausted retries) ended the plan
/// or job; kHandedBack: a task's `hand_back` handler returned the job to the
/// coordinator. Both wait for a new plan or job.
enum class SequencerState { kIdle, kRunning, kWaitingForPlan, kDone, kGaveUp, kAborted, kHandedBack };
const char* to_string(SequencerState s);

struct SequencerEvent {
  enum class Type {
    kPlanAccepted,     // a new plan replaced the old one
    kTaskStarted,      // index, point
    kTaskSucceeded,    // index, point
    kTaskFailed,       // index, point (the timeout expired)
    kPlanAborted,      // the whole plan was aborted
    kReplanRequested,  // pose: re-plan from here; index/point: the failed one (also re-sent
                       // every replan_timeout while no plan comes)
    kRouteCompleted,   // every path point reached
    kGaveUp,           // max_replans consecutive failures
    kModeChanged,
    kJobAccepted,      // a job replaced the plan or job (index: its number of tasks)
    kTaskRetried,      // a machine's `retry` re-entered a state of the task
    kJobAborted,       // an `abort` handler ended the plan or job
    kHandedBack,       // a `hand_back` handler returned the job to the coordinator
    kJobDone,          // every task of the job succeeded
  };
  Type type;
  double time = 0.0;
  std::size_t index = 0;
  Point2D point;
  Pose2D pose;
  double elapsed = 0.0;  // task events: s the task had been active
  double timeout = 0.0;  // task events: its failure limit
  std::string task{};    // task events: the task's name (filled by the sequencer)
  std::string reason{};  // task ends: success, failure or timeout
};
const char* to_string(SequencerEvent::Type t);

class Sequencer {
 public:
  explicit Sequencer(SequencerOptions options = {});

  /// A plan from the planner: the ordered path points. An empty plan stops
  /// the robot (Idle). Replaces any running plan.
  std::vector<SequencerEvent> set_plan(const std::vector<Point2D>& points, double now,
                                       const Pose2D& pose);
  /// Monitors the active task with the current pose.
  std::vector<SequencerEvent> update(double now, const Pose2D& pose);
  std::vector<SequencerEvent> set_mode(Mode mode, double now);
  /// A job from the coordinator: runs the tasks the task file lists for it
  /// (TaskLibrary::job_tasks), in order; replaces the plan or job. "" stops
  /// (Idle). Throws std::invalid_argument for a job the file does not define.
  std::vector<SequencerEvent> set_job(const std::string& job, double now, const Pose2D& pose);
  bool knows_job(const std::string& job) const;
  /// The world model's crisp data that predicate conditions read (MAP's).
  void set_world(CrispMap world) { world_ = std::move(world); }

  SequencerState state() const { return state_; }
  Mode mode() const { return mode_; }
  /// The active task, if any.
  const Task* active() const { return task_ ? &*task_ : nullptr; }
  /// The active task's timeout limit (s of task time; a machine's current state's).
  double active_timeout() const;
  /// The active machine state ("" for a single-state task or none).
  std::string active_state() const;
  /// The job being executed ("" when running a plan or idle).
  const std::string& job() const { return job_; }
  const std::vector<Point2D>& plan() const { return plan_; }
  std::size_t reached() const { return reached_; }
  std::size_t failed() const { return failed_; }
  std::size_t replans() const { return replans_; }
  std::size_t plans() const { return plans_; }
  const SequencerOptions& options() const { return options_; }

 private:
  void start_task(std::size_t index, double now, const Pose2D& pose,
                  std::vector<SequencerEvent>& ev);
  std::size_t steps() const { return job_.empty() ? plan_.size() : job_tasks_->size(); }
  Point2D step_point(std::size_t i) const { return job_.empty() ? plan_[i] : Point2D{}; }
  /// World crisp data + the task's own (GoalDistance, GoalBearing,
  /// StartDistance for a path point; TaskElapsed).
  CrispMap task_crisp(double now, const Pose2D& pose) const;
  /// Monitors the active task once: its TaskState, with a machine's outcome mapped.
  TaskState poll(double now, const Pose2D& pose, TaskRun::Outcome& outcome, std::vector<SequencerEvent>& ev);
  void on_failure(TaskRun::Outcome outcome, const SequencerEvent& failed, double now, const Pose2D& pose,
                  std::vector<SequencerEvent>& ev);
  void name_events(std::vector<SequencerEvent>& ev) const;

  SequencerOptions options_;
  SequencerState state_ = SequencerState::kIdle;
  Mode mode_ = Mode::kAuto;
  std::vector<Point2D> plan_;
  std::optional<Task> task_;
  std::optional<TaskRun> run_;  // the active task's machine, if it has one
  std::string job_;
  const std::vector<std::string>* job_tasks_ = nullptr;
  std::size_t reached_ = 0, failed_ = 0, replans_ = 0, plans_ = 0;
  int consecutive_aborts_ = 0;
  double replan_requested_at_ = 0.0;
  SequencerEvent last_failure_{};
  CrispMap world_;  // the task whose failure asked for a re-plan
};

/// The goal as crisp data for the rule base: distance in cm and bearing in
/// degrees in (-180, 180], 0 ahead, counter-clockwise positive.
struct GoalCrisp {
  double distance_cm = 0.0;
  double bearing_deg = 0.0;
};
GoalCrisp goal_crisp(const Pose2D& pose, const Point2D& goal);

}  // namespace mrt::scare
