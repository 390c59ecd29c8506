#include "mrt_followme/museum.h"

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"

namespace mrt::followme {

using common::ParseError;
using common::YamlReader;

std::size_t FollowMeConfig::exhibit_index(const std::string& name) const {
  for (std::size_t i = 0; i < exhibits.size(); ++i)
    if (exhibits[i].name == name) return i;
  throw std::out_of_range("no exhibit named '" + name + "'");
}

const Door& FollowMeConfig::door(const std::string& name) const {
  for (const Door& d : doors)
    if (d.name == name) return d;
  throw std::out_of_range("no door named '" + name + "'");
}

std::string check_tour(const FollowMeConfig& config, const std::vector<std::string>& tour) {
  if (tour.empty()) return "the tour has no exhibit";
  std::set<std::string> seen;
  for (const std::string& name : tour) {
    bool known = false;
    for (const Exhibit& e : config.exhibits) known = known || e.name == name;
    if (!known) return "unknown exhibit '" + name + "'";
    if (!seen.insert(name).second) return "exhibit '" + name + "' twice in the tour";
  }
  return "";
}

namespace {

Point2D point(const YamlReader& r, const YAML::Node& m, const char* key, const std::string& what) {
  const auto v = r.numbers(r.required(m, key, what), key, 2);
  return {v[0], v[1]};
}

void read_guide(const YamlReader& r, const YAML::Node& n, GuideOptions& g) {
  r.map(n, "guide",
        {"arrive_tolerance", "lookahead", "keep_max", "keep_resume", "lost_time", "look_radius", "look_time",
         "ready_distance", "wander_distance", "follow_distance", "still_speed", "call_after", "max_wait", "robot_radius",
         "safety_distance", "resolution"});
  g.arrive_tolerance = r.positive(n, "arrive_tolerance", g.arrive_tolerance);
  g.lookahead = r.positive(n, "lookahead", g.lookahead);
  g.keep_max = r.positive(n, "keep_max", g.keep_max);
  g.keep_resume = r.positive(n, "keep_resume", g.keep_resume);
  g.lost_time = r.positive(n, "lost_time", g.lost_time);
  g.look_radius = r.positive(n, "look_radius", g.look_radius);
  g.look_time = r.positive(n, "look_time", g.look_time);
  g.ready_distance = r.positive(n, "ready_distance", g.ready_distance);
  g.wander_distance = r.positive(n, "wander_distance", g.wander_distance);
  g.follow_distance = r.positive(n, "follow_distance", g.follow_distance);
  g.still_speed = r.positive(n, "still_speed", g.still_speed);
  g.call_after = r.positive(n, "call_after", g.call_after);
  g.max_wait = r.positive(n, "max_wait", g.max_wait);
  g.robot_radius = r.positive(n, "robot_radius", g.robot_radius);
  g.safety_distance = r.non_negative(n, "safety_distance", g.safety_distance);
  g.resolution = r.bounded(n, "resolution", g.resolution, 0.005, false, 1.0);
  if (g.keep_resume > g.keep_max) r.fail(n["keep_resume"], "expected 'keep_resume' <= 'keep_max'");
}

void read_visitor(const YamlReader& r, const YAML::Node& n, VisitorOptions& v) {
  r.map(n, "visitor",
        {"name", "color", "comfortable", "return_distance", "walk_speed", "look_time", "wander_after", "wander_to", "wander_stay"});
  v.name = r.string(n, "name", v.name, false, "visitor");
  v.color = r.string(n, "color", v.color, false, "visitor");
  v.comfortable = r.positive(n, "comfortable", v.comfortable);
  v.return_distance = r.positive(n, "return_distance", v.return_distance);
  v.walk_speed = r.positive(n, "walk_speed", v.walk_speed);
  v.look_time = r.positive(n, "look_time", v.look_time);
  if (n["wander_after"]) v.wander_after = static_cast<int>(r.integer(n["wander_after"], "wander_after", 0, 1000));
  v.wander_to = r.string(n, "wander_to", v.wander_to, false, "visitor");
  v.wander_stay = r.positive(n, "wander_stay", v.wander_stay);
}

}  // namespace

FollowMeConfig load_followme_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, "cannot open the file");
  std::stringstream text;
  text << in.rdbuf();
  const YamlReader r(path);
  const YAML::Node root = r.load(text.str());
  r.map(root, "followme", {"exhibits", "doors", "tour", "guide", "visitor"});
  FollowMeConfig c;
  const YAML::Node exhibits = r.required(root, "exhibits", "followme");
  for (const YAML::Node& e : r.sequence(exhibits, "exhibits")) {
    r.map(e, "exhibits", {"name", "stop", "spot"});
    c.exhibits.push_back({r.string(e, "name", "", true, "exhibits"), point(r, e, "stop", "exhibits"),
                          point(r, e, "spot", "exhibits")});
  }
  if (const YAML::Node doors = root["doors"]) {
    for (const YAML::Node& d : r.sequence(doors, "doors")) {
      r.map(d, "doors", {"name", "wall"});
      const auto w = r.numbers(r.required(d, "wall", "doors"), "wall", 4);
      c.doors.push_back({r.string(d, "name", "", true, "doors"), {w[0], w[1]}, {w[2], w[3]}});
    }
  }
  const YAML::Node tour = r.required(root, "tour", "followme");
  for (const YAML::Node& t : r.sequence(tour, "tour")) c.tour.push_back(r.string(t, "tour"));
  const std::string bad = check_tour(c, c.tour);
  if (!bad.empty()) r.fail(tour, "expected a tour of known exhibits: " + bad);
  if (root["guide"]) read_guide(r, root["guide"], c.guide);
  if (root["visitor"]) read_visitor(r, root["visitor"], c.visitor);
  if (!c.visitor.wander_to.empty()) {
    bool known = false;
    for (const Exhibit& e : c.exhibits) known = known || e.name == c.visitor.wander_to;
    if (!known) r.fail(root["visitor"]["wander_to"], "expected the name of an exhibit for 'wander_to'");
  }
  return c;
}

}  // namespace mrt::followme
