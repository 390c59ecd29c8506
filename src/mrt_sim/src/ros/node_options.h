// Parameters of sim_node, read once at start-up into a validated struct
// (the stack's one node-parameter style: mrt_common_ros/params.h).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "mrt_sim/world.h"

namespace mrt::sim::node {

/// One entry of ~plugins: a sim_node plugin (mrt_sim/ros/sim_plugin.h).
struct PluginSpec {
  std::string name;  // its parameter namespace ~<name>/ ([A-Za-z0-9_], unique)
  std::string type;  // its pluginlib class ("PACKAGE/CLASS", derived from mrt::sim::SimPlugin)
};

struct NodeOptions {
  std::string world_file;              // ~world (required)
  std::vector<PluginSpec> plugins;     // ~plugins: [{name: N, type: PACKAGE/CLASS}, ...], in load order
  double rate_hz = 1000.0;             // ~rate_hz: physics steps per simulated second
  double real_time_factor = 1.0;       // ~real_time_factor: sim seconds per wall second
  bool publish_clock = true;           // ~publish_clock
  int clock_divider = 1;               // ~clock_divider: /clock every N steps
  double ground_truth_rate = 100.0;    // ~ground_truth_rate: Hz of ground_truth and its tf
  double marker_rate = 20.0;           // ~marker_rate: Hz of dynamic_markers
  double path_rate = 10.0;             // ~path_rate: Hz of ground_truth_path updates
  int path_length = 1000;              // ~path_length: poses kept in the trail
  double cmd_timeout = 0.5;            // ~cmd_timeout: sim seconds; 0 disables the watchdog
  std::string world_frame = "world";   // ~world_frame
  std::string frame_prefix;            // ~frame_prefix: prepended to every robot frame
  std::string sensor_parent = "base_link_truth";  // ~sensor_parent: parent of sensor frames
  std::vector<std::string> joint_state_robots;   // ~joint_state_robots: publish <robot>/joint_states
  std::vector<std::string> description_robots;   // ~description_robots: sensor frames from robot_description
  std::vector<std::string> robots;     // ~robots: the world's robots to simulate (empty = all); a team's size
  double camera_rate = 0.0;            // ~camera_rate: Hz of every robot's camera (0 = the world file's)
  double camera_scale = 1.0;           // ~camera_scale: every robot's camera renders images scaled by this
  int seed = -1;                       // ~seed: the world's noise seed (-1 = the world file's)

  double dt() const { return 1.0 / rate_hz; }
  /// Steps between two publications at `rate` Hz (at least 1).
  long steps_per(double rate) const;
  bool joint_states_for(const std::string& robot) const;
  bool described(const std::string& robot) const;
};

/// Reads and validates the private parameters of `pnh` with
/// mrt_common_ros's ParamReader; throws its ParamError naming the first bad
/// one ("~rate_hz: expected a finite number > 0").
NodeOptions load_node_options(const ros::NodeHandle& pnh);

/// Applies ~robots, ~camera_rate, ~camera_scale and ~seed to a loaded world:
/// keeps only the robots named (in the world's order; throws
/// std::invalid_argument naming the parameter for a name the world does not
/// have), sets the rate of every camera the world gives and scales its
/// image (mrt_common OmniCamera::scaled); a ~seed >= 0 replaces the
/// world's seed.
void apply_team_options(const NodeOptions& o, World& world);

}  // namespace mrt::sim::node
