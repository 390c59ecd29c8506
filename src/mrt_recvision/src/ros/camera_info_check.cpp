#include "camera_info_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <utility>
#include <vector>

namespace mrt::recvision::ros_layer {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// The described profile against the calibration's; "" if they agree.
std::string compare_profile(const mrt::common::MirrorProfile& got, const mrt::common::MirrorProfile& cal) {
  if (std::abs(got.max_theta() - cal.max_theta()) > 0.02)
    return "mirror profile ends at " + num(got.max_theta()) + " rad, calibration at " + num(cal.max_theta());
  const double end = std::min(got.max_theta(), cal.max_theta());
  for (int i = 0; i <= 64; ++i) {
    const double t = end * i / 64.0;
    const double a = got.radius(t), b = cal.radius(t);
    if (std::isfinite(a) && std::isfinite(b) && std::abs(a - b) > 1.0)
      return "mirror radius at " + num(t) + " rad is " + num(a) + " px, calibration " + num(b) + " px";
  }
  return "";
}

// The described camera's centre, tilt and profile against the calibration's; "" if they agree.
std::string compare(const mrt::common::OmniCamera& got, const mrt::common::OmniCamera& cal) {
  if (std::abs(got.cx - cal.cx) > 0.5 || std::abs(got.cy - cal.cy) > 0.5)
    return "mirror centre (" + num(got.cx) + ", " + num(got.cy) + "), calibration (" + num(cal.cx) + ", " +
           num(cal.cy) + ")";
  if (std::abs(got.roll - cal.roll) > 1e-3 || std::abs(got.pitch - cal.pitch) > 1e-3)
    return "mirror tilt (roll " + num(got.roll) + ", pitch " + num(got.pitch) + "), calibration (" + num(cal.roll) +
           ", " + num(cal.pitch) + ")";
  return compare_profile(got.profile, cal.profile);
}

}  // namespace

CameraInfoCheck check_camera_info(const sensor_msgs::CameraInfo& info, const mrt::common::OmniCamera& cal) {
  using R = CameraInfoCheck::Result;
  CameraInfoCheck c;
  if (int(info.width) != cal.width || int(info.height) != cal.height_px) {
    c.result = R::kSizeMismatch;
    c.why = "camera_info " + std::to_string(info.width) + "x" + std::to_string(info.height) + ", calibration " +
            std::to_string(cal.width) + "x" + std::to_string(cal.height_px);
    return c;
  }
  if (info.distortion_model != kOmniProfileModel) {
    c.result = R::kSizeOnly;
    c.why = "distortion model '" + info.distortion_model + "': size checked only";
    return c;
  }
  mrt::common::OmniCamera got;
  c.why = mrt::ros_common::from_camera_info(info, &got);
  if (c.why.empty()) c.why = compare(got, cal);
  c.result = c.why.empty() ? R::kMatches : R::kModelMismatch;
  return c;
}

}  // namespace mrt::recvision::ros_layer
