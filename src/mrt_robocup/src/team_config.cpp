#include <yaml-cpp/yaml.h>

#include <set>

#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"
#include "mrt_robocup/team_session.h"

namespace mrt::robocup {
namespace {

[[noreturn]] void fail(const std::string& file, const YAML::Node& n, const std::string& what) {
  throw common::ParseError(file, n.Mark().line + 1, n.Mark().column + 1, what);
}

std::vector<double> numbers(const std::string& file, const YAML::Node& n, std::size_t count, const char* key) {
  if (!n || !n.IsSequence() || n.size() != count)
    fail(file, n ? n : YAML::Node(), std::string("expected '") + key + "' as a list of " + std::to_string(count) + " numbers");
  std::vector<double> v;
  for (const YAML::Node& x : n) {
    try {
      v.push_back(x.as<double>());
    } catch (const YAML::Exception&) {
      fail(file, x, std::string("expected a number in '") + key + "'");
    }
  }
  return v;
}

}  // namespace

std::vector<TeamRobot> load_team(const std::string& path) {
  const std::string text = common::read_file(path);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw common::ParseError(path, e.mark.line + 1, e.mark.column + 1, e.msg);
  }
  const YAML::Node robots = root["robots"];
  if (!robots || !robots.IsSequence() || robots.size() == 0) fail(path, root, "expected a non-empty 'robots' list");
  std::vector<TeamRobot> team;
  std::set<std::string> names;
  for (const YAML::Node& r : robots) {
    for (const auto& kv : r)
      if (const std::string k = kv.first.as<std::string>(); k != "name" && k != "base" && k != "pose" && k != "home")
        fail(path, kv.first, "unknown key '" + k + "' (expected name, base, pose, home)");
    TeamRobot t;
    if (!r["name"] || !r["base"]) fail(path, r, "a robot needs 'name' and 'base'");
    t.name = r["name"].as<std::string>();
    t.base = r["base"].as<std::string>();
    if (!names.insert(t.name).second) fail(path, r["name"], "duplicate robot '" + t.name + "'");
    const auto p = numbers(path, r["pose"], 3, "pose");
    t.pose = Pose2D(p[0], p[1], common::deg_to_rad(p[2]));
    const auto h = numbers(path, r["home"], 2, "home");
    t.home = {h[0], h[1]};
    team.push_back(t);
  }
  return team;
}

}  // namespace mrt::robocup
