#include "mrt_scare/task_machine.h"

#include "fuzzy_yaml.h"
#include "yaml_util.h"

namespace mrt::scare {

using detail::YamlReader;

int TaskDefinition::find(const std::string& state) const {
  for (std::size_t i = 0; i < states.size(); ++i)
    if (states[i].name == state) return static_cast<int>(i);
  return -1;
}

const char* to_string(TaskRun::Outcome o) {
  switch (o) {
    case TaskRun::Outcome::kRunning: return "running";
    case TaskRun::Outcome::kSucceeded: return "succeeded";
    case TaskRun::Outcome::kAborted: return "aborted";
    case TaskRun::Outcome::kReplan: return "replan";
    case TaskRun::Outcome::kHandBack: return "hand_back";
  }
  return "?";
}

namespace {

Transition parse_transition(const YamlReader& y, const YAML::Node& n, const std::string& what) {
  const std::string v = y.string(n, what);
  if (v == "done") return {Transition::Kind::kDone, ""};
  if (v == "abort") return {Transition::Kind::kAbort, ""};
  if (v == "retry") return {Transition::Kind::kRetry, ""};
  if (v == "replan") return {Transition::Kind::kReplan, ""};
  if (v == "hand_back") return {Transition::Kind::kHandBack, ""};
  if (v.rfind("goto ", 0) == 0 && v.size() > 5) return {Transition::Kind::kState, v.substr(5)};
  y.fail(n, "expected done, abort, retry, replan, hand_back or 'goto <state>' for '" + what + "'");
}

MachineState parse_state(const YamlReader& y, const YAML::Node& n, const std::string& name, FuzzyModel& model,
                         const std::string& text) {
  y.map(n, "state", {"success", "failure", "timeout", "timeout_per", "on_success", "on_failure", "on_timeout",
                     "retries"});
  MachineState s;
  s.name = name;
  if (const YAML::Node c = n["success"]) s.success = model.compile(y.string(c, "success"), detail::origin(c, y.file(), text));
  if (const YAML::Node c = n["failure"]) s.failure = model.compile(y.string(c, "failure"), detail::origin(c, y.file(), text));
  s.timeout = y.non_negative(n, "timeout", 0.0);
  if (const YAML::Node tp = n["timeout_per"]) {
    y.map(tp, "timeout_per", {"datum", "factor"});
    s.timeout_datum = y.string(tp, "datum", "", true, "timeout_per");
    s.timeout_factor = y.non_negative(tp, "factor", 0.0);
  }
  if (s.success < 0 && s.failure < 0 && s.timeout <= 0.0 && s.timeout_datum.empty())
    y.fail(n, "expected at least one of 'success', 'failure', 'timeout' in state '" + name + "'");
  if (n["on_success"]) s.on_success = parse_transition(y, n["on_success"], "on_success");
  if (n["on_failure"]) s.on_failure = parse_transition(y, n["on_failure"], "on_failure");
  if (n["on_timeout"]) s.on_timeout = parse_transition(y, n["on_timeout"], "on_timeout");
  if (n["retries"]) s.retries = static_cast<int>(y.integer(n["retries"], "retries", 0, 100));
  return s;
}

TaskDefinition parse_task(const YamlReader& y, const YAML::Node& n, const std::string& name, FuzzyModel& model,
                          const std::string& text) {
  y.map(n, "task", {"states"});
  TaskDefinition d;
  d.name = name;
  const YAML::Node states = y.required(n, "states", "task");
  if (!states.IsMap() || states.size() == 0) y.fail(states, "expected a map of states for 'states'");
  for (auto it = states.begin(); it != states.end(); ++it) {
    const std::string sname = y.string(it->first, "state name");
    if (d.find(sname) >= 0) y.fail(it->first, "duplicate state '" + sname + "'");
    d.states.push_back(parse_state(y, it->second, sname, model, text));
  }
  // Every `goto` names a state of this task.
  for (auto it = states.begin(); it != states.end(); ++it)
    for (const char* key : {"on_success", "on_failure", "on_timeout"}) {
      const YAML::Node t = it->second[key];
      if (!t) continue;
      const Transition tr = parse_transition(y, t, key);
      if (tr.kind == Transition::Kind::kState && d.find(tr.state) < 0)
        y.fail(t, "unknown state '" + tr.state + "' in task '" + name + "'");
    }
  return d;
}

}  // namespace

TaskLibrary parse_task_library(const std::string& text, const std::string& file) {
  const YamlReader y(file);
  const YAML::Node root = y.load(text);
  // The sequencer's own keys are read by task_config.cpp from the same file.
  y.map(root, "task file",
        {"fuzzy", "threshold", "tasks", "jobs", "path_task", "max_replans", "replan_timeout", "suspend_in_manual"});
  TaskLibrary lib;
  lib.model = detail::parse_fuzzy(y, y.required(root, "fuzzy", "task file"), text);
  lib.threshold = y.bounded(root, "threshold", 0.5, 0.0, true, 1.0);
  const YAML::Node tasks = y.required(root, "tasks", "task file");
  if (!tasks.IsMap() || tasks.size() == 0) y.fail(tasks, "expected a map of tasks for 'tasks'");
  for (auto it = tasks.begin(); it != tasks.end(); ++it) {
    const std::string name = y.string(it->first, "task name");
    if (lib.tasks.count(name)) y.fail(it->first, "duplicate task '" + name + "'");
    lib.tasks[name] = parse_task(y, it->second, name, *lib.model, text);
  }
  if (const YAML::Node jobs = root["jobs"]) {
    if (!jobs.IsMap()) y.fail(jobs, "expected a map of jobs for 'jobs'");
    for (auto it = jobs.begin(); it != jobs.end(); ++it) {
      const std::string name = y.string(it->first, "job name");
      if (lib.jobs.count(name)) y.fail(it->first, "duplicate job '" + name + "'");
      if (!it->second.IsSequence() || it->second.size() == 0)
        y.fail(it->second, "expected a non-empty list of tasks for job '" + name + "'");
      std::vector<std::string>& list = lib.jobs[name];
      // A copy: the range of a for over it->second would live in the
      // iterator's temporary proxy (ASan: stack-use-after-scope).
      const YAML::Node tasks = it->second;
      for (const auto& t : tasks) {
        list.push_back(y.string(t, "task"));
        if (!lib.tasks.count(list.back())) y.fail(t, "unknown task '" + list.back() + "' in job '" + name + "'");
      }
    }
  }
  return lib;
}

const std::vector<std::string>* TaskLibrary::job_tasks(const std::string& job) const {
  auto it = jobs.find(job);
  if (it == jobs.end()) it = jobs.find(job.substr(0, job.find('.')));
  return it == jobs.end() ? nullptr : &it->second;
}

TaskLibrary load_task_library(const std::string& path) { return parse_task_library(detail::read_file(path), path); }

TaskRun::TaskRun(const TaskLibrary& lib, const TaskDefinition& def) : lib_(lib), def_(def) {}

const std::string& TaskRun::state() const { return def_.states[static_cast<std::size_t>(state_)].name; }

void TaskRun::start(double now, const CrispMap& crisp) {
  outcome_ = Outcome::kRunning;
  retries_used_ = 0;
  reason_.clear();
  enter(0, now, crisp);
}

void TaskRun::enter(int state, double now, const CrispMap& crisp) {
  state_ = state;
  entered_ = now;
  const MachineState& s = def_.states[static_cast<std::size_t>(state)];
  limit_ = s.timeout;
  if (!s.timeout_datum.empty()) {
    const auto it = crisp.find(s.timeout_datum);
    limit_ += s.timeout_factor * (it == crisp.end() ? 0.0 : it->second.first);
  }
}

TaskRun::Outcome TaskRun::follow(const Transition& t, double now, const CrispMap& crisp) {
  switch (t.kind) {
    case Transition::Kind::kState: enter(def_.find(t.state), now, crisp); return outcome_ = Outcome::kRunning;
    case Transition::Kind::kDone: return outcome_ = Outcome::kSucceeded;
    case Transition::Kind::kRetry:
      if (retries_used_ < def_.states[static_cast<std::size_t>(state_)].retries) {
        ++retries_used_;
        enter(state_, now, crisp);
        return outcome_ = Outcome::kRunning;
      }
      return outcome_ = Outcome::kAborted;  // retries exhausted
    case Transition::Kind::kReplan: return outcome_ = Outcome::kReplan;
    case Transition::Kind::kHandBack: return outcome_ = Outcome::kHandBack;
    case Transition::Kind::kAbort: break;
  }
  return outcome_ = Outcome::kAborted;
}

TaskRun::Outcome TaskRun::update(double now, const CrispMap& crisp) {
  if (outcome_ != Outcome::kRunning) return outcome_;
  const MachineState& s = def_.states[static_cast<std::size_t>(state_)];
  lib_.model->evaluate(crisp);
  if (s.success >= 0 && lib_.model->degree(s.success) >= lib_.threshold) {
    reason_ = "success";
    return follow(s.on_success, now, crisp);
  }
  if (s.failure >= 0 && lib_.model->degree(s.failure) >= lib_.threshold) {
    reason_ = "failure";
    return follow(s.on_failure, now, crisp);
  }
  if ((s.timeout > 0.0 || !s.timeout_datum.empty()) && now - entered_ > limit_) {
    reason_ = "timeout";
    return follow(s.on_timeout, now, crisp);
  }
  return outcome_;
}

}  // namespace mrt::scare
