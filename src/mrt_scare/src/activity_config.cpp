#include <set>
#include <sstream>

#include "mrt_scare/activity.h"
#include "fuzzy_yaml.h"
#include "yaml_util.h"

namespace mrt::scare {

using common::ParseError;
using detail::YamlReader;
using detail::origin;
using detail::parse_fuzzy;

std::vector<Slot> ActivitySet::slots() const {
  std::vector<Slot> out;
  for (std::size_t a = 0; a < activities.size(); ++a)
    for (std::size_t r = 0; r < activities[a].roles.size(); ++r)
      out.push_back({static_cast<int>(a), static_cast<int>(r)});
  return out;
}

std::string ActivitySet::slot_name(const Slot& s) const {
  if (s.activity < 0) return "";
  const ActivitySpec& a = activities[static_cast<std::size_t>(s.activity)];
  return a.schema ? a.name + "." + a.roles[static_cast<std::size_t>(s.role)].name : a.name;
}

int ActivitySet::find_slot(const std::string& name) const {
  const auto all = slots();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (slot_name(all[i]) == name) return static_cast<int>(i);
  return -1;
}

int ActivitySet::find_activity(const std::string& name) const {
  for (std::size_t a = 0; a < activities.size(); ++a)
    if (activities[a].name == name) return static_cast<int>(a);
  return -1;
}

const RobotSpec* ActivitySet::find_robot(const std::string& id) const {
  for (const auto& r : robots)
    if (r.id == id) return &r;
  return nullptr;
}

double ActivitySet::attitude(const RobotSpec& r, const Slot& s) const {
  const ActivitySpec& a = activities[static_cast<std::size_t>(s.activity)];
  auto it = r.attitude.find(slot_name(s));
  if (it != r.attitude.end()) return it->second;
  it = r.attitude.find(a.name);
  return it != r.attitude.end() ? it->second : default_attitude;
}

std::vector<double> ActivitySet::opportunities() const {
  std::vector<double> o;
  for (const ActivitySpec& a : activities)
    o.push_back(a.opportunity >= 0 ? model->degree(a.opportunity) : a.opportunity_constant);
  return o;
}

RobotSpec ActivitySet::robot_or_default(const std::string& id) const {
  if (const RobotSpec* r = find_robot(id)) return *r;
  RobotSpec r;
  r.id = id;
  return r;
}

namespace {

Target parse_target(const YamlReader& y, const YAML::Node& n) {
  Target t;
  if (!n) return t;
  if (!n.IsSequence() || n.size() != 2) y.fail(n, "expected 'target' as [x, y]: two numbers (m) or two crisp data names");
  double x = 0.0, v = 0.0;
  if (YamlReader::decode(n[0], x) && YamlReader::decode(n[1], v)) {
    t.kind = Target::Kind::kFixed;
    t.x = y.number(n[0], "target");
    t.y = y.number(n[1], "target");
  } else {
    t.kind = Target::Kind::kCrisp;
    t.x_datum = y.string(n[0], "target");
    t.y_datum = y.string(n[1], "target");
  }
  return t;
}

RoleSpec parse_role(const YamlReader& y, const YAML::Node& n, const std::string& what, bool job) {
  if (job)
    y.map(n, what, {"name", "opportunity", "priority", "min", "max", "target"});
  else
    y.map(n, what, {"name", "min", "max", "target"});
  RoleSpec r;
  r.name = y.string(n, "name", "", true, what);
  r.min = static_cast<int>(n["min"] ? y.integer(n["min"], "min", 1, 32) : 1);
  r.max = static_cast<int>(n["max"] ? y.integer(n["max"], "max", 1, 32) : r.min);
  if (r.max < r.min) y.fail(n["max"], "expected 'max' >= 'min' (" + std::to_string(r.min) + ")");
  r.target = parse_target(y, n["target"]);
  return r;
}

ActivitySpec parse_activity(const YamlReader& y, const YAML::Node& n, ActivitySet& set, const std::string& text) {
  if (!n.IsMap()) y.fail(n, "expected a map for an activity");
  ActivitySpec a;
  a.schema = static_cast<bool>(n["roles"]);
  if (a.schema) {
    y.map(n, "activity", {"name", "opportunity", "priority", "roles"});
    a.name = y.string(n, "name", "", true, "activity");
    const YAML::Node roles = n["roles"];  // named: sequence() returns its argument
    for (const YAML::Node& r : y.sequence(roles, "roles")) {
      a.roles.push_back(parse_role(y, r, "role", false));
      for (std::size_t i = 0; i + 1 < a.roles.size(); ++i)
        if (a.roles[i].name == a.roles.back().name) y.fail(r, "duplicate role '" + a.roles.back().name + "'");
    }
    if (a.roles.size() < 2 || a.roles.size() > 3) y.fail(n["roles"], "expected a schema with 2 or 3 roles");
  } else {
    a.roles.push_back(parse_role(y, n, "activity", true));
    a.name = a.roles[0].name;
  }
  if (a.name.empty() || a.name.find('.') != std::string::npos) y.fail(n["name"], "expected a name without '.'");
  a.priority = y.bounded(n, "priority", 1.0, 0.0, true, 10.0);
  const YAML::Node o = y.required(n, "opportunity", "activity");
  a.opportunity_text = y.string(o, "opportunity");
  double c = 0.0;
  if (YamlReader::decode(o, c)) {
    if (!(c >= 0.0 && c <= 1.0)) y.fail(o, "expected a constant 'opportunity' in [0, 1]");
    a.opportunity_constant = c;
  } else {
    a.opportunity = set.model->compile(a.opportunity_text, origin(o, y.file(), text));
  }
  return a;
}

RobotSpec parse_robot(const YamlReader& y, const YAML::Node& n, const ActivitySet& set) {
  y.map(n, "robot", {"id", "max_speed", "attitude"});
  RobotSpec r;
  r.id = y.string(n, "id", "", true, "robot");
  r.max_speed = y.positive(n, "max_speed", 1.0);
  if (const YAML::Node at = n["attitude"]) {
    if (!at.IsMap()) y.fail(at, "expected a map for 'attitude'");
    for (auto it = at.begin(); it != at.end(); ++it) {
      const std::string key = it->first.as<std::string>();
      if (set.find_slot(key) < 0 && set.find_activity(key) < 0)
        y.fail(it->first, "unknown activity or role '" + key + "' in 'attitude'");
      const double v = y.number(it->second, key);
      if (v < 0.0 || v > 1.0) y.fail(it->second, "expected an attitude in [0, 1] for '" + key + "'");
      r.attitude[key] = v;
    }
  }
  return r;
}

void parse_options(const YamlReader& y, const YAML::Node& n, AllocationOptions& o) {
  if (!n) return;
  y.map(n, "options", {"time_scale", "hysteresis", "min_opportunity", "exact_max_robots", "dwell"});
  o.time_scale = y.positive(n, "time_scale", o.time_scale);
  o.hysteresis = y.non_negative(n, "hysteresis", o.hysteresis);
  o.min_opportunity = y.fraction(n, "min_opportunity", o.min_opportunity);
  o.dwell = y.non_negative(n, "dwell", o.dwell);
  if (n["exact_max_robots"]) o.exact_max_robots = static_cast<int>(y.integer(n["exact_max_robots"], "exact_max_robots", 0, 8));
}

}  // namespace

ActivitySet parse_activities(const std::string& text, const std::string& file) {
  const YamlReader y(file);
  const YAML::Node root = y.load(text);
  y.map(root, "activity file", {"fuzzy", "activities", "robots", "default_attitude", "options"});
  ActivitySet set;
  set.model = parse_fuzzy(y, y.required(root, "fuzzy", "activity file"), text);
  std::set<std::string> names;
  const YAML::Node acts = y.required(root, "activities", "activity file");
  for (const YAML::Node& a : y.sequence(acts, "activities")) {
    set.activities.push_back(parse_activity(y, a, set, text));
    if (!names.insert(set.activities.back().name).second)
      y.fail(a, "duplicate activity '" + set.activities.back().name + "'");
  }
  if (set.activities.empty() || set.activities.size() > 64) y.fail(acts, "expected 1 to 64 activities");
  set.default_attitude = y.fraction(root, "default_attitude", set.default_attitude);
  parse_options(y, root["options"], set.options);
  if (const YAML::Node rs = root["robots"]) {
    for (const YAML::Node& r : y.sequence(rs, "robots")) {
      set.robots.push_back(parse_robot(y, r, set));
      for (std::size_t i = 0; i + 1 < set.robots.size(); ++i)
        if (set.robots[i].id == set.robots.back().id) y.fail(r, "duplicate robot '" + set.robots.back().id + "'");
    }
  }
  return set;
}

ActivitySet load_activities(const std::string& path) { return parse_activities(detail::read_file(path), path); }

}  // namespace mrt::scare
