// rviz markers of the simulated world: the static world (floor, walls,
// field lines, posts, goals), what moves (ball, movers, robots) and what a
// robot sees. Pure functions: no publishers, no parameters, no clocks.
#pragma once

#include <string>
#include <vector>

#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "mrt_sim/simulator.h"

namespace mrt::sim::node {

/// RGBA of a symbolic colour ("yellow", "sky_blue", "#ff8000", ...); grey
/// when unknown or empty.
std_msgs::ColorRGBA color_of(const std::string& name, float alpha = 1.0f);

/// Static markers of a world: floor (green when it has field lines), walls,
/// field lines, posts and goals, in `frame`.
visualization_msgs::MarkerArray world_markers(const World& w, const std::string& frame);

/// Markers of what moves: the ball, the movers and every robot (footprint,
/// heading arrow, name), in `frame` (the world frame).
visualization_msgs::MarkerArray dynamic_markers(const World& w, const std::vector<RobotState>& robots,
                                                const std::string& frame, const ros::Time& stamp);

/// What one robot sees, drawn in the world frame from its true pose: a
/// sphere per object in the object's colour, a ray from the robot to it, the
/// sampled field-line points and a label per object. Starts with DELETEALL.
visualization_msgs::MarkerArray percept_markers(const std::vector<SeenObject>& seen,
                                                const Pose2D& robot_pose, const std::string& frame,
                                                const ros::Time& stamp);

}  // namespace mrt::sim::node
