#include "mrt_robocup/coordination.h"

namespace mrt::robocup {

Parameters coordination_from_team(const std::string& self, const std::map<std::string, TeamEntry>& team,
                                  double now, double max_age) {
  Parameters p;
  const auto me = team.find(self);
  if (me == team.end() || now - me->second.stamp > max_age) return p;
  const std::string& mine = me->second.intention;
  if (mine.empty()) return p;
  const auto dot = mine.find('.');
  const std::string activity = mine.substr(0, dot);
  if (dot == std::string::npos) {
    p["ScareJob_" + activity] = {1.0, 1.0};
    return p;
  }
  p["ScareRole_" + activity + "_" + mine.substr(dot + 1)] = {1.0, 1.0};
  // The other roles of the schema, as the coordinator names them.
  for (const auto& [id, e] : team) {
    if (id == self || now - e.stamp > max_age) continue;
    const auto d = e.intention.find('.');
    if (d == std::string::npos || e.intention.substr(0, d) != activity) continue;
    const std::string role = e.intention.substr(d + 1);
    p["ScareMate_" + role + "_X"] = {e.x, 1.0};
    p["ScareMate_" + role + "_Y"] = {e.y, 1.0};
  }
  return p;
}

}  // namespace mrt::robocup
