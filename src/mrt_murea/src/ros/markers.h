// rviz markers of MUREA's evidence: the surviving (tied) cells, the
// estimate with its covariance ellipse, the best lattice pose, the
// runner-up (ambiguity) and the search window of the next tracked frame.
#pragma once

#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "mrt_murea/tracker.h"

namespace mrt::murea::node {

visualization_msgs::MarkerArray evidence_markers(const TrackResult& r, const Tracker& t, const std::string& frame,
                                                 const ros::Time& stamp);

}  // namespace mrt::murea::node
