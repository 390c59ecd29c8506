// A situation file for scare_allocate and the tests: the shared world model
// (crisp data) and each robot's pose, current job and data age. ROS-free.
#pragma once

#include <string>
#include <vector>

#include "mrt_scare/coordinator.h"

namespace mrt::scare {

struct SituationRobot {
  std::string id;
  Pose2D pose;
  std::string incumbent;  // slot name, "" none
  double age = 0.0;       // s since its data were sent
};

struct Situation {
  CrispMap world;
  std::vector<SituationRobot> robots;
};

/// Throws common::ParseError (file:line:column), also for an incumbent that
/// is no slot of `set`.
Situation parse_situation(const std::string& yaml_text, const std::string& file, const ActivitySet& set);
Situation load_situation(const std::string& path, const ActivitySet& set);

/// The allocation input: every robot's view (straight-line cost), its
/// incumbent and age penalty, opportunities from the world model.
TeamInput team_input(const ActivitySet& set, const Situation& s, const CoordinatorOptions& o = {});

}  // namespace mrt::scare
