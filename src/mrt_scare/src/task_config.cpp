#include "mrt_scare/task_config.h"

#include <map>

#include "fuzzy_yaml.h"
#include "yaml_util.h"

namespace mrt::scare {

namespace {

using detail::YamlReader;

/// The task file's `fuzzy:` section, for `predicate` conditions.
struct Fuzzy {
  std::shared_ptr<FuzzyModel> model;
  const std::string* text = nullptr;
};

std::shared_ptr<const Condition> parse_condition(const YamlReader& r, const YAML::Node& n,
                                                 const std::string& what, const Fuzzy& fz) {
  r.map(n, what, {"within", "timeout", "per_metre", "predicate"});
  if (n["predicate"]) {
    if (n.size() != 1) r.fail(n, "'predicate' takes no other key in '" + what + "'");
    if (!fz.model) r.fail(n["predicate"], "a 'predicate' condition needs a top-level 'fuzzy' section");
    const std::string text = r.string(n["predicate"], "predicate");
    const int id = fz.model->compile(text, detail::origin(n["predicate"], r.file(), *fz.text));
    return std::make_shared<FuzzyCondition>(fz.model, id, text);
  }
  if (n["within"]) {
    if (n.size() != 1) r.fail(n, "'within' takes no other key in '" + what + "'");
    return std::make_shared<WithinDistance>(r.positive(n["within"], "within"));
  }
  if (n["timeout"]) {
    const double per = n["per_metre"] ? r.non_negative(n["per_metre"], "per_metre") : 0.0;
    return std::make_shared<Timeout>(r.positive(n["timeout"], "timeout"), per);
  }
  r.fail(n, "expected 'within', 'timeout' or 'predicate' in '" + what + "'");
}

TaskSpec parse_task(const YamlReader& r, const YAML::Node& n, const std::string& name, const Fuzzy& fz) {
  r.map(n, name, {"success", "failure", "on_failure"});
  TaskSpec t;
  t.name = name;
  for (const char* key : {"success", "failure"}) {
    const YAML::Node list = n[key];
    if (!list) r.fail(n, "missing key '" + std::string(key) + "' in '" + name + "'");
    if (!list.IsSequence() || list.size() == 0)
      r.fail(list, "expected a non-empty list of conditions for '" + std::string(key) + "'");
    for (const auto& c : list)
      (std::string(key) == "success" ? t.success : t.failure)
          .push_back(parse_condition(r, c, name + "." + key, fz));
  }
  if (n["on_failure"]) {
    const std::string s = r.string(n["on_failure"], "on_failure");
    if (s == "abort_and_replan") t.on_failure = OnFailure::kAbortAndReplan;
    else if (s == "skip") t.on_failure = OnFailure::kSkip;
    else r.fail(n["on_failure"], "unknown on_failure '" + s + "' (expected abort_and_replan or skip)");
  }
  return t;
}

/// A task file of state machines: some task has `states` (task_machine.h).
bool is_machine_file(const YAML::Node& root) {
  if (root["jobs"] || root["threshold"]) return true;
  const YAML::Node tasks = root["tasks"];
  if (!tasks || !tasks.IsMap()) return false;
  for (auto it = tasks.begin(); it != tasks.end(); ++it)
    if (it->second.IsMap() && it->second["states"]) return true;
  return false;
}

/// The keys the sequencer reads from either format.
void read_sequencer_keys(const YamlReader& r, const YAML::Node& root, SequencerOptions& o) {
  if (root["max_replans"]) {
    const double m = r.non_negative(root["max_replans"], "max_replans");
    if (m != static_cast<int>(m) || m > 1000)
      r.fail(root["max_replans"], "expected an integer 0..1000 for 'max_replans'");
    o.max_replans = static_cast<int>(m);
  }
  if (root["replan_timeout"]) o.replan_timeout = r.non_negative(root["replan_timeout"], "replan_timeout");
  if (root["suspend_in_manual"])
    o.suspend_in_manual = r.boolean(root["suspend_in_manual"], "suspend_in_manual");
}

SequencerOptions parse_machine_options(const YamlReader& r, const YAML::Node& root, const std::string& yaml_text) {
  SequencerOptions o;
  auto lib = std::make_shared<TaskLibrary>(parse_task_library(yaml_text, r.file()));
  std::string path_task = "ReachPathPoint";
  if (root["path_task"]) path_task = r.string(root["path_task"], "path_task");
  // A file of jobs only need not define the path task (its plans then never end by themselves).
  if (!lib->tasks.count(path_task) && (root["path_task"] || lib->jobs.empty()))
    r.fail(root["path_task"] ? root["path_task"] : root["tasks"],
           "path task '" + path_task + "' is not defined under 'tasks'");
  o.path_task = TaskSpec{};  // the machine decides; the spec carries the name
  o.path_task.name = path_task;
  o.machines = std::move(lib);
  read_sequencer_keys(r, root, o);
  return o;
}

}  // namespace

SequencerOptions parse_sequencer_options(const std::string& yaml_text, const std::string& file) {
  const YamlReader r(file);
  const YAML::Node root = r.load(yaml_text);
  if (!root.IsMap()) throw common::ParseError(file, 1, 1, "expected a map at the top level");
  if (is_machine_file(root)) return parse_machine_options(r, root, yaml_text);
  r.map(root, "top level", {"tasks", "path_task", "max_replans", "replan_timeout", "suspend_in_manual", "fuzzy"});
  Fuzzy fz;
  fz.text = &yaml_text;
  if (root["fuzzy"]) fz.model = detail::parse_fuzzy(r, root["fuzzy"], yaml_text);
  if (!root["tasks"]) r.fail(root, "missing key 'tasks'");
  r.map(root["tasks"], "tasks", {"ReachPathPoint"});
  std::map<std::string, TaskSpec> tasks;
  for (auto it = root["tasks"].begin(); it != root["tasks"].end(); ++it) {
    const std::string name = it->first.Scalar();
    tasks[name] = parse_task(r, it->second, name, fz);
  }
  SequencerOptions o;
  std::string path_task = "ReachPathPoint";
  if (root["path_task"]) path_task = r.string(root["path_task"], "path_task");
  if (!tasks.count(path_task))
    r.fail(root["path_task"] ? root["path_task"] : root["tasks"],
           "path task '" + path_task + "' is not defined under 'tasks'");
  o.path_task = tasks[path_task];
  read_sequencer_keys(r, root, o);
  return o;
}

SequencerOptions load_sequencer_options(const std::string& path) {
  return parse_sequencer_options(detail::read_file(path), path);
}

}  // namespace mrt::scare
