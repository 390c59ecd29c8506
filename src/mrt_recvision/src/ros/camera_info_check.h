// The camera/camera_info a camera driver (or mrt_sim) publishes, checked
// against the calibration RecVision runs with. mrt_sim describes its
// omnidirectional camera with the non-standard distortion model
// kOmniProfileModel (mrt_common_ros/omni_camera_info.h). Any other model
// (a V4L2 driver's plumb_bob, say) is checked for its size only.
#pragma once

#include <sensor_msgs/CameraInfo.h>

#include <string>

#include "mrt_common/omni_camera.h"
#include "mrt_common_ros/omni_camera_info.h"

namespace mrt::recvision::ros_layer {

using mrt::ros_common::kOmniProfileModel;

struct CameraInfoCheck {
  enum class Result {
    kMatches,        ///< size, centre, tilt and profile agree
    kSizeOnly,       ///< another distortion model: only the size was checked (and agrees)
    kSizeMismatch,   ///< width or height differ from the calibration's
    kModelMismatch,  ///< kOmniProfileModel whose centre, tilt or profile differ (or is malformed)
  };
  Result result = Result::kMatches;
  std::string why;  ///< what differs, for the log and the diagnostics
};

/// Tolerances: centre 0.5 px, tilt 1e-3 rad, profile radius 1 px at 64
/// angles over the shorter profile, end angles 0.02 rad.
CameraInfoCheck check_camera_info(const sensor_msgs::CameraInfo& info, const mrt::common::OmniCamera& calibrated);

}  // namespace mrt::recvision::ros_layer
