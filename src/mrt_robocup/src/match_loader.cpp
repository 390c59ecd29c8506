// The match-file loader (format: doc/match.md, "Match file"); every error
// names file:line:column through mrt_common/yaml_reader.h.
#include <fstream>
#include <set>
#include <sstream>

#include "mrt_common/angle.h"
#include "mrt_common/parse_error.h"
#include "mrt_common/yaml_reader.h"
#include "mrt_robocup/match.h"

namespace mrt::robocup {

namespace {

using YAML::Node;

class MatchLoader : private mrt::common::YamlReader {
 public:
  using YamlReader::load;
  explicit MatchLoader(const std::string& file) : YamlReader(file) {}

  MatchConfig match(const Node& root) const {
    if (!root.IsMap()) {
      if (root.IsNull()) throw mrt::common::ParseError(file(), 1, 1, "expected a map at the top level, got an empty document");
      fail(root, "expected a map at the top level");
    }
    map(root, "match", {"teams", "own_goal", "field_half_width", "ball_robot_restitution", "kicker",
                        "opponent_kick_speed", "keeper_distance", "defender_distance", "opponents",
                        "clear_movers", "referee"});
    MatchConfig c;
    if (const Node n = root["teams"]) {
      if (!n.IsSequence() || n.size() != 2) fail(n, "expected a list of 2 team names for 'teams'");
      c.teams = {string(n[0], "teams"), string(n[1], "teams")};
      if (c.teams[0] == c.teams[1]) fail(n, "expected two different team names in 'teams'");
    }
    c.own_goal = string(root, "own_goal", c.own_goal, false, "match");
    c.field_half_width = positive(root, "field_half_width", c.field_half_width);
    c.ball_robot_restitution = fraction(root, "ball_robot_restitution", c.ball_robot_restitution);
    if (const Node n = root["kicker"]) c.kicker = kicker(n);
    c.opponent_kick_speed = positive(root, "opponent_kick_speed", c.opponent_kick_speed);
    c.keeper_distance = non_negative(root, "keeper_distance", c.keeper_distance);
    c.defender_distance = positive(root, "defender_distance", c.defender_distance);
    c.clear_movers = boolean(root, "clear_movers", c.clear_movers);
    if (const Node n = root["opponents"]) {
      std::set<std::string> names;
      for (const Node& e : sequence(n, "opponents")) {
        c.opponents.push_back(opponent(e));
        if (!names.insert(c.opponents.back().name).second)
          fail(e["name"], "duplicate opponent name '" + c.opponents.back().name + "'");
      }
    }
    if (const Node n = root["referee"]) c.referee = referee(n);
    return c;
  }

 private:
  KickerConfig kicker(const Node& n) const {
    map(n, "kicker", {"max_speed", "reach", "half_angle", "dribble_max_speed", "dribble_max_omega"});
    KickerConfig k;
    k.max_speed = positive(n, "max_speed", k.max_speed);
    k.reach = non_negative(n, "reach", k.reach);
    k.half_angle = mrt::common::deg_to_rad(bounded(n, "half_angle", mrt::common::rad_to_deg(k.half_angle), 0.0, true, 180.0));
    k.dribble_max_speed = non_negative(n, "dribble_max_speed", k.dribble_max_speed);
    k.dribble_max_omega = non_negative(n, "dribble_max_omega", k.dribble_max_omega);
    return k;
  }

  OpponentConfig opponent(const Node& n) const {
    map(n, "opponents", {"name", "role", "x", "y", "radius", "speed"});
    OpponentConfig o;
    o.name = string(n, "name", "", true, "opponents");
    o.role = string(n, "role", o.role, false, "opponents");
    if (o.role != "goalkeeper" && o.role != "defender" && o.role != "attacker" && o.role != "static")
      fail(n["role"], "expected 'role' goalkeeper, defender, attacker or static, got '" + o.role + "'");
    o.home = {number(required(n, "x", "opponents"), "x"), number(required(n, "y", "opponents"), "y")};
    o.radius = positive(n, "radius", o.radius);
    o.speed = non_negative(n, "speed", o.speed);
    return o;
  }

  RefereeConfig referee(const Node& n) const {
    map(n, "referee", {"restart_delay", "stuck_timeout", "kickoff_team", "auto_start", "restart_wait"});
    RefereeConfig r;
    r.restart_delay = non_negative(n, "restart_delay", r.restart_delay);
    r.stuck_timeout = non_negative(n, "stuck_timeout", r.stuck_timeout);
    r.restart_wait = non_negative(n, "restart_wait", r.restart_wait);
    if (const Node k = n["kickoff_team"]) r.kickoff_team = static_cast<int>(integer(k, "kickoff_team", 0, 1));
    r.auto_start = boolean(n, "auto_start", r.auto_start);
    return r;
  }
};

}  // namespace

MatchConfig parse_match_config(const std::string& yaml_text, const std::string& file) {
  MatchLoader l(file);
  return l.match(l.load(yaml_text));
}

MatchConfig load_match_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw mrt::common::ParseError(path, 0, 0, "cannot open the match file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_match_config(ss.str(), path);
}

}  // namespace mrt::robocup
