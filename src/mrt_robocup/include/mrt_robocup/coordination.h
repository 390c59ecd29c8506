// SCARE's coordination information for one robot's rule base when only the
// team topic (mrt_msgs/CoordinationParameters) is at hand: the job or role
// from the robot's own intention, the teammates' roles of its schema from
// theirs — the same names as the coordinator's crisp output
// (ScareJob_<Activity>, ScareRole_<Activity>_<role>, ScareMate_<role>_X/_Y).
// ROS-free.
#pragma once

#include <map>
#include <string>

#include "mrt_robocup/situation.h"

namespace mrt::robocup {

/// What the Player needs of one team message.
struct TeamEntry {
  std::string intention;  // "Defense", "PassageToMate.passer", "" none
  double x = 0.0, y = 0.0;
  double stamp = 0.0;     // s
};

/// The crisp coordination parameters of robot `self` from the latest team
/// entries (by robot id); entries older than `max_age` at `now` are
/// ignored. Empty when `self` has no entry.
Parameters coordination_from_team(const std::string& self, const std::map<std::string, TeamEntry>& team,
                                  double now, double max_age);

}  // namespace mrt::robocup
