// What Mr. BRIAN's obstacle sectors hold in the museum: only echoes the map
// does not explain (people). An echo within kMappedTolerance of the range
// the map predicts from the localizer's pose (or beyond it) is a wall or an
// exhibit, which SPIKE's plan already keeps clear of, and reads as no echo;
// Roby's avoidance rules, written for open ground, would otherwise refuse to
// turn into a 1 m door. Nearer than kTooClose every echo counts (the
// FollowVisitor goals are not planned by SPIKE). Used by the in-process loop
// and by unmapped_sonar_node. ROS-free.
#pragma once

#include <cmath>

#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

namespace mrt::followme {

constexpr double kMappedTolerance = 0.25;  // m
constexpr double kTooClose = 0.3;          // m

/// `range` (m) as the sectors get it: `s.max_range` when the map (`known`:
/// walls, closed doors, posts, no people) explains it.
inline double unmapped_range(const sim::World& known, const common::Pose2D& estimate, const sim::SonarConfig& s,
                             double range) {
  const double expected = sim::sonar_range(known, {}, estimate, s);
  const bool mapped = range > kTooClose && (std::abs(range - expected) < kMappedTolerance || range > expected);
  return mapped ? s.max_range : range;
}

}  // namespace mrt::followme
