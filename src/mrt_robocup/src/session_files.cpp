#include "mrt_robocup/session_files.h"

#include <yaml-cpp/yaml.h>

#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"

namespace mrt::robocup {

TeamSessionOptions default_session_options(const std::string& package_root, const std::string& worlds) {
  TeamSessionOptions o;
  o.world = worlds + "/msl_field.yaml";
  o.match = package_root + "/config/msl_match.yaml";
  o.team = package_root + "/config/team.yaml";
  o.rule_bases = package_root + "/config/brian";
  o.activities = package_root + "/config/scare/robocup_team.yaml";
  o.map_model = package_root + "/config/map/robocup_team.yaml";
  return o;
}

void resolve_world_or_match(TeamSessionOptions& o, const std::string& field_world) {
  YAML::Node n;
  try {
    n = YAML::Load(common::read_file(o.world));
  } catch (const YAML::ParserException& e) {
    throw common::ParseError(o.world, e.mark.line + 1, e.mark.column + 1, e.msg);
  }
  if (!n.IsMap() || n["robots"] || !(n["opponents"] || n["referee"])) return;
  o.match = o.world;
  o.world = field_world;
}

}  // namespace mrt::robocup
