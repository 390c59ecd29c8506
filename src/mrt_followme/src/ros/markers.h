// rviz markers of FollowMe: the museum (walls, exhibits, landmarks, doors),
// the people, the robot (truth and estimate), the visitor's track, the plan
// and the tour's progress. Pure functions of the session's state.
#pragma once

#include <string>

#include <mrt_msgs/TourStatus.h>
#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "mrt_followme/followme_loop.h"

namespace mrt::followme::node {

visualization_msgs::MarkerArray museum_markers(const FollowMeSession& s, const std::string& frame);
visualization_msgs::MarkerArray dynamic_markers(const FollowMeSession& s, const std::string& frame);
/// One line: job, next exhibit, visited, wanders.
std::string tour_status(const FollowMeSession& s);
/// The same as a message (tour_status).
mrt_msgs::TourStatus tour_status_msg(const FollowMeSession& s, const ros::Time& stamp);
/// The summary the demo prints (the figures of followme_run).
std::string summary(const FollowMeResult& r);

}  // namespace mrt::followme::node
