// Conversions between the simulator core's types and ROS messages. Pure
// functions: no publishers, no parameters, no clocks.
#pragma once

#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/TransformStamped.h>
#include <mrt_msgs/MiceReading.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/Range.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "mrt_sim/simulator.h"

namespace mrt::sim::node {

/// Mean Earth radius used by the equirectangular local-tangent-plane
/// conversion of the DGPS (WGS84 semi-major axis), m.
constexpr double kEarthRadius = 6378137.0;

/// Frame names of one robot: "<prefix><robot>/<suffix>".
struct RobotFrames {
  std::string base_truth;   // <robot>/base_link_truth: ground truth body frame
  std::string base;         // <robot>/base_link: the body as estimated by odometry
  std::string sensor_parent;  // one of the two above, parent of the sensor frames
  std::string prefix;       // "<prefix><robot>/"
  std::string sonar(std::size_t i) const { return prefix + "sonar_" + std::to_string(i); }
  std::string mouse(const std::string& id) const { return prefix + "mouse_" + id; }
  std::string gps() const { return prefix + "gps"; }
};
RobotFrames make_frames(const std::string& frame_prefix, const std::string& robot,
                        const std::string& sensor_parent_suffix);

geometry_msgs::Pose to_pose(const Pose2D& p, double z = 0.0);
geometry_msgs::TransformStamped to_transform(const Pose2D& p, const std::string& parent,
                                             const std::string& child, const ros::Time& stamp);

/// Ground truth: pose in the world frame, twist in the body frame (the twist
/// applied during the last step), zero covariance.
nav_msgs::Odometry to_odometry(const RobotState& r, const std::string& world_frame,
                               const RobotFrames& f, const ros::Time& stamp);

mrt_msgs::MiceReading to_mice(const MiceSample& m, const RobotFrames& f, const ros::Time& stamp);

/// Wheel state; duty is the measured speed over the maximum wheel speed;
/// status flags SATURATED and WATCHDOG apply to every wheel.
mrt_msgs::WheelState to_wheel_state(const RobotState& r, bool watchdog, const ros::Time& stamp);

sensor_msgs::Range to_range(const SonarConfig& s, double range, const std::string& frame,
                            const ros::Time& stamp);

/// The omnidirectional camera's percept: one object per seen object with the
/// numeric attributes distance [m], bearing [rad], x, y [m] (in `frame`) and
/// the symbolic attribute color (when the object has one).
mrt_msgs::Percept to_percept(const std::vector<SeenObject>& seen, const SensorsConfig& cfg,
                             const std::string& robot, const std::string& frame,
                             const ros::Time& stamp);

/// Equirectangular conversion of a world position to latitude/longitude
/// around the datum (the world origin), x east and y north.
void world_to_geodetic(double lat0_deg, double lon0_deg, const Point2D& p, double& lat_deg,
                       double& lon_deg);
sensor_msgs::NavSatFix to_navsat(const Point2D& p, const SensorsConfig& cfg, const std::string& frame,
                                 const ros::Time& stamp);

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
