// rviz markers of spike_node: the decomposition, the inflated map and the
// moving obstacles' footprints.
#pragma once

#include <string>

#include <visualization_msgs/MarkerArray.h>

#include "mrt_spike/world_planner.h"

namespace mrt::spike::node {

/// "decomposition" (quadtree leaves' outlines, LINE_LIST; only with SPIKE's
/// quadtree) and "inflated" (cells blocked by the inflation only,
/// CUBE_LIST); replaces all markers.
visualization_msgs::MarkerArray static_markers(const WorldPlanner& p, const std::string& frame);
/// "moving_obstacles": the cells blocked by the footprints (CUBE_LIST).
visualization_msgs::MarkerArray obstacle_markers(const WorldPlanner& p, const std::string& frame);

}  // namespace mrt::spike::node
