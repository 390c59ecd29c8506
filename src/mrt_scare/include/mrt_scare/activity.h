// SCARE coordination (manual ch. 11, §2.3.3): the designer's activities —
// jobs (one robot's activity, with a cardinality) and schemata (several
// robots' activity, with roles) — and the robots' parameters, loaded from
// YAML (format in doc/formats.md). ROS-free.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrt_scare/fuzzy_model.h"

namespace mrt::scare {

/// Where the robot filling a role must go: two crisp data (e.g. BallX,
/// BallY, in m) or a fixed point; none -> no travel cost.
struct Target {
  enum class Kind { kNone, kFixed, kCrisp } kind = Kind::kNone;
  double x = 0.0, y = 0.0;
  std::string x_datum, y_datum;
};

/// One role of an activity: between `min` and `max` robots fill it when the
/// activity is taken (a job has one role, named after the job).
struct RoleSpec {
  std::string name;
  int min = 1;
  int max = 1;
  Target target;
};

struct ActivitySpec {
  std::string name;
  bool schema = false;   // a schema is taken only if every role is filled
  double priority = 1.0; // designer's weight, (0, 10]
  std::string opportunity_text;
  int opportunity = -1;  // expression id in the ActivitySet's FuzzyModel, -1: constant
  double opportunity_constant = 0.0;  // `opportunity: 0.3` (a number in [0, 1])
  std::vector<RoleSpec> roles;
};

/// One robot's static parameters.
struct RobotSpec {
  std::string id;
  double max_speed = 1.0;  // m/s, for the straight-line time estimate
  /// Attitude by "Activity" or "Activity.role", in [0, 1]; the role entry
  /// wins over the activity's; neither -> the set's default_attitude.
  std::map<std::string, double> attitude;
};

/// How allocation trades utility against stability (doc/coordination.md, "Allocation").
struct AllocationOptions {
  double time_scale = 2.0;       // s: fit = attitude / (1 + time / time_scale)
  double hysteresis = 0.15;      // utility margin the incumbent keeps its role by
  double min_opportunity = 0.05; // activities below it are not on the agenda
  int exact_max_robots = 6;      // exact DP up to this team size, else greedy + local search
  /// s: a robot that took its slot less than `dwell` ago keeps it unless
  /// cardinality or coverage cannot be met otherwise (0: no dwell).
  double dwell = 0.0;
};

/// One (activity, role) pair: what a robot is assigned to.
struct Slot {
  int activity = -1;
  int role = -1;
};

struct ActivitySet {
  std::vector<ActivitySpec> activities;
  std::vector<RobotSpec> robots;  // optional team description (by id)
  double default_attitude = 0.5;
  AllocationOptions options;
  std::shared_ptr<FuzzyModel> model;  // shared: evaluation state is per copy-owner

  /// All (activity, role) pairs in declaration order.
  std::vector<Slot> slots() const;
  /// "Defense" for a job, "PassageToMate.passer" for a schema's role.
  std::string slot_name(const Slot& s) const;
  /// Slot index by name, or -1.
  int find_slot(const std::string& name) const;
  int find_activity(const std::string& name) const;
  const RobotSpec* find_robot(const std::string& id) const;
  double attitude(const RobotSpec& r, const Slot& s) const;
  /// Opportunity degrees per activity after model->evaluate(crisp).
  std::vector<double> opportunities() const;
  /// The robot's spec from the team description, or a default one.
  RobotSpec robot_or_default(const std::string& id) const;
};

/// Parses an activity file; throws common::ParseError with file:line:column.
ActivitySet parse_activities(const std::string& yaml_text, const std::string& file);
ActivitySet load_activities(const std::string& path);

}  // namespace mrt::scare
