// The CameraInfo of an omnidirectional camera (mrt_common::OmniCamera), as
// the simulator publishes it and RecVision reads it. Not a pinhole model:
// distortion_model kOmniProfileModel, which image_geometry and image_proc
// treat as unknown (they refuse to rectify), so nothing misreads it.
//   K = [0, 0, cx; 0, 0, cy; 0, 0, 1]  (the mirror centre; fx = fy = 0:
//       no pinhole focal length exists), R the identity, P = [K | 0]
//   D = [roll, pitch, theta_0, r_0, theta_1, r_1, ...]  (the mirror axis
//       tilt, rad, then the radial profile's samples: angle from the
//       downward vertical, rad, and image radius, px, as MirrorProfile
//       holds them)
// The viewpoint's height is its frame's in tf.
#pragma once

#include <sensor_msgs/CameraInfo.h>

#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "mrt_common/omni_camera.h"

namespace mrt::ros_common {

inline const char* const kOmniProfileModel = "mrt_omni_profile";

inline sensor_msgs::CameraInfo to_camera_info(const mrt::common::OmniCamera& c, const std::string& frame,
                                              const ros::Time& stamp) {
  sensor_msgs::CameraInfo info;  // binning 0 and roi all zeros: full resolution, no region
  info.header.stamp = stamp;
  info.header.frame_id = frame;
  info.width = static_cast<std::uint32_t>(c.width);
  info.height = static_cast<std::uint32_t>(c.height_px);
  info.distortion_model = kOmniProfileModel;
  info.K = {0.0, 0.0, c.cx, 0.0, 0.0, c.cy, 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {0.0, 0.0, c.cx, 0.0, 0.0, 0.0, c.cy, 0.0, 0.0, 0.0, 1.0, 0.0};
  info.D = {c.roll, c.pitch};
  for (const auto& [theta, radius] : c.profile.table()) {
    info.D.push_back(theta);
    info.D.push_back(radius);
  }
  return info;
}

/// The camera a kOmniProfileModel CameraInfo describes (its height left
/// at the default: tf's). "" and `*out` set, or what is wrong with it.
inline std::string from_camera_info(const sensor_msgs::CameraInfo& info, mrt::common::OmniCamera* out) {
  if (info.distortion_model != kOmniProfileModel)
    return "distortion model '" + info.distortion_model + "', expected '" + kOmniProfileModel + "'";
  const auto& d = info.D;
  if (d.size() < 6 || d.size() % 2 != 0)
    return "D holds " + std::to_string(d.size()) + " values (expected roll, pitch and 2 or more (theta, r) pairs)";
  std::vector<std::pair<double, double>> table;
  for (std::size_t i = 2; i < d.size(); i += 2) table.emplace_back(d[i], d[i + 1]);
  mrt::common::OmniCamera c;
  try {
    c.profile = mrt::common::MirrorProfile(std::move(table));
  } catch (const std::exception& e) {
    return std::string("D's profile: ") + e.what();
  }
  c.width = static_cast<int>(info.width);
  c.height_px = static_cast<int>(info.height);
  c.cx = info.K[2];
  c.cy = info.K[5];
  c.roll = d[0];
  c.pitch = d[1];
  *out = std::move(c);
  return "";
}

}  // namespace mrt::ros_common
