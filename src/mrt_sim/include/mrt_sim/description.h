// Sensor mounts from a robot's URDF (mrt_description), read with urdfdom
// (ROS-free), so the simulator and the nodes take mounting positions from
// one place.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mrt_common/pose2d.h"

namespace mrt::sim {

/// Pose of a link relative to base_link: position (m) and yaw (rad).
struct LinkMount {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0.0;
};

/// The mounts the simulator takes from a description; a link the URDF lacks
/// is empty.
struct DescriptionMounts {
  std::optional<LinkMount> omni_mirror;  // the mirror's effective viewpoint
  std::optional<LinkMount> mouse_left, mouse_right;
  std::vector<LinkMount> sonars;  // links sonar_0, sonar_1, ... up to the first missing one
};

/// Directory of mrt_description's URDF files as built into this library
/// (`<dir>/<base>.urdf`); the node passes the package's path at run time.
std::string default_description_dir();

/// Pose of `link` in `base_link` (composing the fixed joints between them),
/// or nullopt if the model has no such link or it does not hang off
/// base_link.
std::optional<LinkMount> link_mount(const std::string& urdf_xml, const std::string& link);

/// Reads `<dir>/<base>.urdf`; nullopt when there is no such file. Throws
/// std::runtime_error naming the file when it exists but does not parse.
std::optional<DescriptionMounts> read_description(const std::string& dir, const std::string& base);

}  // namespace mrt::sim
