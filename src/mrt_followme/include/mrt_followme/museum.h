// FollowMe's configuration (config/followme.yaml, format in the README):
// the exhibits with the robot's stop and the visitor's spot, the doors, the
// tour, the guide's and the visitor's parameters. ROS-free.
#pragma once

#include <string>
#include <vector>

#include "mrt_common/pose2d.h"

namespace mrt::followme {

using common::Point2D;
using common::Pose2D;

struct Exhibit {
  std::string name;
  Point2D stop;  // where the robot waits
  Point2D spot;  // where a visitor stands to look
};

struct Door {
  std::string name;
  Point2D a, b;  // the wall that closes it
};

struct GuideOptions {
  double arrive_tolerance = 0.3;
  double lookahead = 0.7;
  double keep_max = 2.8;
  double keep_resume = 2.2;
  double lost_time = 4.0;
  double look_radius = 1.0;
  double look_time = 2.0;
  double ready_distance = 2.4;
  double wander_distance = 3.0;
  double follow_distance = 2.8;
  double still_speed = 0.15;
  double call_after = 6.0;
  double max_wait = 40.0;      // s at an exhibit with the visitor by the robot: go on
  double robot_radius = 0.25;
  double safety_distance = 0.15;
  double resolution = 0.05;
};

struct VisitorOptions {
  std::string name = "guest";   // the mover of the world it steers
  std::string color = "purple"; // what the robot's camera reports
  double comfortable = 1.4;
  double return_distance = 2.0; // m from the robot where it stops when it comes back
  double walk_speed = 0.7;
  double look_time = 6.0;
  int wander_after = 0;         // wanders off after this exhibit of the tour (1-based; 0 never)
  std::string wander_to;        // exhibit it wanders to
  double wander_stay = 25.0;
};

struct FollowMeConfig {
  std::vector<Exhibit> exhibits;
  std::vector<Door> doors;
  std::vector<std::string> tour;
  GuideOptions guide;
  VisitorOptions visitor;

  /// Index of the exhibit named `name`; throws std::out_of_range if none.
  std::size_t exhibit_index(const std::string& name) const;
  const Door& door(const std::string& name) const;
};

/// Reads and checks the file; errors are mrt::common::ParseError
/// (file:line:column: expected ...), also for a tour naming an unknown exhibit.
FollowMeConfig load_followme_config(const std::string& path);

/// Checks a tour (names of known exhibits, none twice, at least one);
/// returns an empty string when good, else what is wrong.
std::string check_tour(const FollowMeConfig& config, const std::vector<std::string>& tour);

}  // namespace mrt::followme
