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

// The profile in D (after roll and pitch) against the calibration's; "" if they agree.
std::string compare_profile(const std::vector<double>& d, const mrt::common::MirrorProfile& cal) {
  if (d.size() < 6 || d.size() % 2 != 0) return "D holds " + std::to_string(d.size()) + " values (expected roll, pitch and 2 or more (theta, r) pairs)";
  std::vector<std::pair<double, double>> table;
  for (std::size_t i = 2; i < d.size(); i += 2) table.emplace_back(d[i], d[i + 1]);
  mrt::common::MirrorProfile got;
  try {
    got = mrt::common::MirrorProfile(std::move(table));
  } catch (const std::exception& e) {
    return std::string("D's profile: ") + e.what();
  }
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
  if (std::abs(info.K[2] - cal.cx) > 0.5 || std::abs(info.K[5] - cal.cy) > 0.5) {
    c.why = "mirror centre (" + num(info.K[2]) + ", " + num(info.K[5]) + "), calibration (" + num(cal.cx) + ", " +
            num(cal.cy) + ")";
  } else if (info.D.size() >= 2 && (std::abs(info.D[0] - cal.roll) > 1e-3 || std::abs(info.D[1] - cal.pitch) > 1e-3)) {
    c.why = "mirror tilt (roll " + num(info.D[0]) + ", pitch " + num(info.D[1]) + "), calibration (" + num(cal.roll) +
            ", " + num(cal.pitch) + ")";
  } else {
    c.why = compare_profile(info.D, cal.profile);
  }
  c.result = c.why.empty() ? R::kMatches : R::kModelMismatch;
  return c;
}

}  // namespace mrt::recvision::ros_layer
