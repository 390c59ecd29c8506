// SCARE sequencing, generalised (manual ch. 11): a job's tasks described in
// YAML as state machines whose success, failure and timeout conditions are
// fuzzy predicates over crisp data (Mr. BRIAN's predicate language, as the
// opportunities of activities), with exception handlers: abort, retry,
// re-plan, hand back to the coordinator. ROS-free; format in doc/formats.md.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrt_scare/fuzzy_model.h"

namespace mrt::scare {

/// What happens when a condition holds: go to another state, end the task
/// (done: success), or handle an exception.
struct Transition {
  enum class Kind { kState, kDone, kAbort, kRetry, kReplan, kHandBack } kind = Kind::kAbort;
  std::string state;  // kState
};

struct MachineState {
  std::string name;
  int success = -1, failure = -1;  // expression ids in the model (-1: none)
  double timeout = 0.0;            // s in the state (0: none) ...
  std::string timeout_datum;       // ... + factor * this datum's value on entry
  double timeout_factor = 0.0;
  Transition on_success{Transition::Kind::kDone, ""};
  Transition on_failure{Transition::Kind::kAbort, ""};
  Transition on_timeout{Transition::Kind::kAbort, ""};
  int retries = 0;                 // re-entries a `retry` allows, then abort
};

struct TaskDefinition {
  std::string name;
  std::vector<MachineState> states;   // the first is the initial state
  int find(const std::string& state) const;
};

struct TaskLibrary {
  std::shared_ptr<FuzzyModel> model;
  double threshold = 0.5;          // a condition holds when value * reliability >= threshold
  std::map<std::string, TaskDefinition> tasks;
  /// A job (the coordinator's slot name, e.g. `PassageToMate.passer`, or an
  /// activity name) -> the tasks the sequencer runs for it, in order.
  std::map<std::string, std::vector<std::string>> jobs;
  /// The tasks of `job`: the slot's own entry, else its activity's (the
  /// name before the '.'); nullptr when neither is defined.
  const std::vector<std::string>* job_tasks(const std::string& job) const;
};

/// Throws common::ParseError with file:line:column (unknown keys, states,
/// handlers, data, labels, predicates).
TaskLibrary parse_task_library(const std::string& yaml_text, const std::string& file);
TaskLibrary load_task_library(const std::string& path);

/// A running task: Running until a transition ends it.
class TaskRun {
 public:
  enum class Outcome { kRunning, kSucceeded, kAborted, kReplan, kHandBack };
  TaskRun(const TaskLibrary& lib, const TaskDefinition& def);

  /// Enters the initial state at `now` (crisp data for the timeout term).
  void start(double now, const CrispMap& crisp);
  /// Evaluates the current state's conditions: success first, then failure,
  /// then timeout; follows the transition.
  Outcome update(double now, const CrispMap& crisp);

  Outcome outcome() const { return outcome_; }
  const std::string& state() const;
  /// Why the task ended or the last transition fired: success, failure, timeout.
  const std::string& reason() const { return reason_; }
  int retries_used() const { return retries_used_; }
  double limit() const { return limit_; }

 private:
  void enter(int state, double now, const CrispMap& crisp);
  Outcome follow(const Transition& t, double now, const CrispMap& crisp);

  const TaskLibrary& lib_;
  const TaskDefinition& def_;
  int state_ = 0;
  double entered_ = 0.0, limit_ = 0.0;
  int retries_used_ = 0;
  Outcome outcome_ = Outcome::kRunning;
  std::string reason_;
};

const char* to_string(TaskRun::Outcome o);

}  // namespace mrt::scare
