// Wheel joints of the robot description (mrt_description) from the board's
// encoders (ROS-free): joint names in the motor order and encoder counts as
// wheel angles, for the node's sensor_msgs/JointState.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_common/base_kinematics.h"

namespace mrt::airboard {

/// Joint names of `n` wheels: a differential base [left_wheel_joint,
/// right_wheel_joint], an omni base wheel_<i>_joint (the URDF's names).
inline std::vector<std::string> wheel_joint_names(mrt::common::BaseType type, std::size_t n) {
  if (type == mrt::common::BaseType::kDifferential && n == 2) return {"left_wheel_joint", "right_wheel_joint"};
  std::vector<std::string> names;
  for (std::size_t i = 0; i < n; ++i) names.push_back("wheel_" + std::to_string(i) + "_joint");
  return names;
}

/// Wheel angle (rad) of a cumulative encoder count: 2 pi counts / counts_per_rev.
inline double counts_to_angle(std::int64_t counts, double counts_per_rev) {
  return 2.0 * mrt::common::kPi * static_cast<double>(counts) / counts_per_rev;
}

}  // namespace mrt::airboard
