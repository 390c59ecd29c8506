#include "mrt_scare/situation.h"

#include "yaml_util.h"

namespace mrt::scare {

using detail::YamlReader;

Situation parse_situation(const std::string& text, const std::string& file, const ActivitySet& set) {
  const YamlReader y(file);
  const YAML::Node root = y.load(text);
  y.map(root, "situation", {"world", "robots"});
  Situation s;
  if (const YAML::Node w = root["world"]) {
    if (!w.IsMap()) y.fail(w, "expected a map for 'world'");
    for (auto it = w.begin(); it != w.end(); ++it) {
      const std::string name = it->first.as<std::string>();
      if (it->second.IsSequence()) {
        const auto v = y.numbers(it->second, name, 2);
        if (!(v[1] >= 0.0 && v[1] <= 1.0)) y.fail(it->second[1], "expected a reliability in [0, 1] for '" + name + "'");
        s.world[name] = {v[0], v[1]};
      } else {
        s.world[name] = {y.number(it->second, name), 1.0};
      }
    }
  }
  const YAML::Node robots = y.required(root, "robots", "situation");
  for (const YAML::Node& r : y.sequence(robots, "robots")) {
    y.map(r, "robot", {"id", "pose", "incumbent", "age"});
    SituationRobot sr;
    sr.id = y.string(r, "id", "", true, "robot");
    const YAML::Node p = y.required(r, "pose", "robot");
    const auto v = p.IsSequence() && p.size() == 3 ? y.numbers(p, "pose", 3) : y.numbers(p, "pose", 2);
    sr.pose = Pose2D(v[0], v[1], v.size() == 3 ? v[2] : 0.0);
    sr.incumbent = y.string(r, "incumbent", "", false, "robot");
    if (!sr.incumbent.empty() && set.find_slot(sr.incumbent) < 0)
      y.fail(r["incumbent"], "unknown job or role '" + sr.incumbent + "'");
    sr.age = y.non_negative(r, "age", 0.0);
    for (const auto& o : s.robots)
      if (o.id == sr.id) y.fail(r, "duplicate robot '" + sr.id + "'");
    s.robots.push_back(sr);
  }
  return s;
}

Situation load_situation(const std::string& path, const ActivitySet& set) {
  return parse_situation(detail::read_file(path), path, set);
}

TeamInput team_input(const ActivitySet& set, const Situation& s, const CoordinatorOptions& o) {
  TeamInput in;
  set.model->evaluate(s.world);
  in.opportunity = set.opportunities();
  const StraightLineCost cost;
  for (const SituationRobot& r : s.robots) {
    RobotView v = robot_view(set, set.robot_or_default(r.id), r.pose, s.world, cost);
    v.incumbent = r.incumbent.empty() ? -1 : set.find_slot(r.incumbent);
    v.confidence = age_confidence(r.age, o);
    in.robots.push_back(std::move(v));
  }
  return in;
}

}  // namespace mrt::scare
