// murea_node's parameters and message conversions (the node's boundary).
#pragma once

#include <mrt_msgs/Percept.h>
#include <ros/node_handle.h>
#include <sensor_msgs/LaserScan.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mrt_common/ontology.h"
#include "mrt_murea/tracker.h"

namespace mrt::murea::node {

struct NodeOptions {
  std::string map_file;             // ~map: world file or map_server map (required unless use_map_topic)
  bool use_map_topic = false;       // ~use_map_topic (amcl's): the first nav_msgs/OccupancyGrid on `map` instead
  TrackerOptions tracker;           // ~accuracy_xy, ~accuracy_theta, ~timeout, ~tolerance_<class>, window, collapse, ~refine*
  std::string frame_prefix;         // ~frame_prefix, e.g. "robot1/"
  std::string map_frame = "map";    // ~global_frame_id, alias ~map_frame (global: not prefixed)
  std::string odom_frame = "odom";  // ~odom_frame_id, alias ~odom_frame (prefixed)
  std::string base_frame = "base_link";  // ~base_frame_id, alias ~base_frame (prefixed)
  int scan_max_beams = 30;          // ~scan_max_beams, alias ~laser_max_beams (amcl's): wall points per scan
  std::string odom_topic;           // ~odom_topic: nav_msgs/Odometry topic; empty = tf odom -> base_link
  double odom_alpha_xy = 0.2;       // ~odom_alpha_xy: translation sd per metre travelled
  double odom_alpha_theta = 0.2;    // ~odom_alpha_theta: heading sd per radian turned
  double odom_alpha_theta_xy = 0.05;  // ~odom_alpha_theta_xy: heading sd per metre travelled (rad/m)
  double transform_tolerance = 0.1;   // ~transform_tolerance: s the map -> odom tf is post-dated
  bool publish_tf = true;           // ~tf_broadcast (amcl's), alias ~publish_tf
  double tf_rate = 20.0;            // ~tf_rate: Hz of map -> odom republication
  /// ~initial_pose_x, ~initial_pose_y (m), ~initial_pose_a (rad), as amcl's:
  /// tracking starts there when any of them is set (else a global search).
  std::optional<Pose2D> initial_pose;
  /// ~initial_cov_xx, ~initial_cov_yy (m^2), ~initial_cov_aa (rad^2): amcl's defaults.
  Covariance3 initial_cov{0.25, 0, 0, 0, 0.25, 0, 0, 0, 0.06853891945200942};
};

/// Reads and validates the private parameters (ParamError naming the parameter).
NodeOptions read_options(const ros::NodeHandle& pnh);

/// Counts of a percept message's objects that were not used.
struct DropCounts {
  mrt::common::PerceptDrops ontology;  // not an object of the ontology (unknown class, no position, ...)
  std::size_t non_map_class = 0;  // Ball, Robot, ...: not a map feature (ignored, not an error)
  std::size_t non_finite = 0;     // nan/inf in the position or the reliability, negative distance
};

/// The map percepts of a message (the objects the ontology accepts, read
/// through mrt_common's position reader: polar or Cartesian), expressed in
/// the frame of the message.
std::vector<Percept> to_percepts(const mrt_msgs::Percept& msg, DropCounts& drops);

/// Counts of a laser scan's beams that were not used.
struct ScanCounts {
  std::size_t scans = 0;     // scans received
  std::size_t invalid = 0;   // ranges outside (range_min, range_max) or not finite
};

/// The wall points a laser scan sees, in the scan's frame (mrt_murea/scan.h's
/// scan_percepts(): each valid range a `Wall` percept, at most `max_beams`,
/// evenly spaced over the valid beams).
std::vector<Percept> scan_to_percepts(const sensor_msgs::LaserScan& scan, int max_beams, ScanCounts& counts);

/// Odometry covariance of a relative motion (amcl-like alphas).
Covariance3 odometry_covariance(const Pose2D& delta, const NodeOptions& o);

/// Re-expresses percepts seen from a sensor frame mounted at `mount` (its
/// pose in base_link) in base_link.
void to_base_frame(std::vector<Percept>& percepts, const Pose2D& mount);

/// One percept frame through the pipeline of murea_node (and murea_eval):
/// odometry's motion since *last_odom predicts (none on the first frame),
/// then the percepts (in base_link) update; *last_odom becomes `odom`.
TrackResult track_frame(Tracker& tracker, std::optional<Pose2D>* last_odom, const Pose2D& odom,
                        const std::vector<Percept>& percepts, const NodeOptions& o);

}  // namespace mrt::murea::node
