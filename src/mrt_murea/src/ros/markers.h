// rviz markers of MUREA's evidence: the surviving (tied) cells, the
// estimate with its covariance ellipse, the best lattice pose, the
// runner-up (ambiguity) and the search window of the next tracked frame.
#pragma once

#include <geometry_msgs/PoseArray.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "mrt_murea/tracker.h"

namespace mrt::murea::node {

visualization_msgs::MarkerArray evidence_markers(const TrackResult& r, const Tracker& t, const std::string& frame,
                                                 const ros::Time& stamp);

/// amcl's `particlecloud` for MUREA: the surviving cells (the lattice poses
/// tied with the best, the plateau; the best pose alone when the search was
/// cut short), then the runner-up mode when the search was ambiguous.
geometry_msgs::PoseArray particle_cloud(const TrackResult& r, const std::string& frame, const ros::Time& stamp);

}  // namespace mrt::murea::node
