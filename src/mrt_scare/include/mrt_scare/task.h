// SCARE sequencing (manual ch. 11, §2.3.1): a task is a configurable state
// machine with success and failure conditions and a timeout. ROS-free.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrt_common/pose2d.h"
#include "mrt_scare/fuzzy_model.h"

namespace mrt::scare {

using common::Point2D;
using common::Pose2D;

/// Euclidean distance from a pose's position to a point (m).
double distance(const Pose2D& p, const Point2D& q);

/// What a task's conditions can look at, once per update.
struct TaskContext {
  double now = 0.0;          // s
  double elapsed = 0.0;      // s the task has been active (paused time excluded)
  Pose2D pose;               // robot pose in the plan's frame
  Point2D goal;              // the task's path point
  double start_distance = 0; // m from the pose at activation to the goal
  const CrispMap* world = nullptr;  // the world model's crisp data, if any
};

/// One condition of a task, built from the YAML configuration.
class Condition {
 public:
  virtual ~Condition() = default;
  virtual bool holds(const TaskContext& c) const = 0;
  /// Human-readable form, e.g. "within 0.5 m".
  virtual std::string describe() const = 0;
};

/// The robot is within `distance` metres of the goal.
class WithinDistance : public Condition {
 public:
  explicit WithinDistance(double distance) : distance_(distance) {}
  bool holds(const TaskContext& c) const override;
  std::string describe() const override;
  double distance() const { return distance_; }

 private:
  double distance_;
};

/// The task has been active longer than `seconds + per_metre * start_distance`.
class Timeout : public Condition {
 public:
  Timeout(double seconds, double per_metre) : seconds_(seconds), per_metre_(per_metre) {}
  bool holds(const TaskContext& c) const override { return c.elapsed > limit(c.start_distance); }
  std::string describe() const override;
  double limit(double start_distance) const { return seconds_ + per_metre_ * start_distance; }

 private:
  double seconds_;
  double per_metre_;
};

/// A fuzzy predicate (Mr. BRIAN's language) over the world model's crisp
/// data and the task's own: GoalDistance (cm), GoalBearing (deg, (-180,
/// 180], counter-clockwise), StartDistance (cm), TaskElapsed (s). Holds when
/// value * reliability >= threshold.
class FuzzyCondition : public Condition {
 public:
  FuzzyCondition(std::shared_ptr<FuzzyModel> model, int expression, std::string text, double threshold = 0.5)
      : model_(std::move(model)), expression_(expression), text_(std::move(text)), threshold_(threshold) {}
  bool holds(const TaskContext& c) const override;
  std::string describe() const override { return "predicate " + text_; }

 private:
  std::shared_ptr<FuzzyModel> model_;
  int expression_;
  std::string text_;
  double threshold_;
};

/// What the sequencer does when a task fails.
enum class OnFailure { kAbortAndReplan, kSkip };

/// The configuration of one kind of task (e.g. ReachPathPoint).
struct TaskSpec {
  std::string name = "ReachPathPoint";
  std::vector<std::shared_ptr<const Condition>> success;  // any holds -> success
  std::vector<std::shared_ptr<const Condition>> failure;  // any holds -> failure
  OnFailure on_failure = OnFailure::kAbortAndReplan;

  /// The ReachPathPoint of manual §2.3.1: success within `tolerance` m,
  /// failure after `timeout` s (+ `per_metre` s per metre of the leg).
  static TaskSpec reach_path_point(double tolerance, double timeout, double per_metre = 0.0);
  /// The largest timeout limit among the failure conditions (0 if none).
  double timeout_limit(double start_distance) const;
};

enum class TaskState { kInactive, kActive, kSucceeded, kFailed, kAborted };
const char* to_string(TaskState s);

/// One instance of a task: Inactive -> Active -> Succeeded | Failed, or
/// Aborted by the sequencer. Time spent suspended (manual mode) does not
/// count towards the timeout. Success is checked before failure.
class Task {
 public:
  Task(TaskSpec spec, Point2D goal, std::size_t index);

  void activate(double now, const Pose2D& pose);
  /// Evaluates the conditions; returns the (possibly new) state.
  TaskState update(double now, const Pose2D& pose, const CrispMap* world = nullptr);
  void suspend(double now);
  void resume(double now);
  void abort();

  TaskState state() const { return state_; }
  bool suspended() const { return suspended_; }
  const TaskSpec& spec() const { return spec_; }
  const Point2D& goal() const { return goal_; }
  std::size_t index() const { return index_; }
  double elapsed(double now) const;
  double timeout() const { return spec_.timeout_limit(start_distance_); }
  double start_distance() const { return start_distance_; }

 private:
  TaskSpec spec_;
  Point2D goal_;
  std::size_t index_;
  TaskState state_ = TaskState::kInactive;
  double start_time_ = 0.0;
  double paused_ = 0.0;         // total suspended time
  double suspended_at_ = 0.0;
  bool suspended_ = false;
  double start_distance_ = 0.0;
};

}  // namespace mrt::scare
