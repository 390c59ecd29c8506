// The debug image: the frame with the scanned annulus and every detection drawn over it.
#include <opencv2/imgproc.hpp>

#include <cmath>

#include "mrt_recvision/detector.h"

namespace mrt::recvision {

cv::Scalar color_rgb(ColorClass c) {
  switch (c) {
    case ColorClass::kYellow: return {255, 230, 0};
    case ColorClass::kBlue: return {0, 90, 255};
    case ColorClass::kOrange: return {255, 120, 0};
    case ColorClass::kCyan: return {0, 255, 255};
    case ColorClass::kMagenta: return {255, 0, 255};
    case ColorClass::kWhite: return {255, 255, 255};
    case ColorClass::kGreen: return {0, 200, 0};
    case ColorClass::kRed: return {255, 0, 0};
    case ColorClass::kPurple: return {140, 40, 200};
    case ColorClass::kBeige: return {190, 175, 150};
    case ColorClass::kGrey: return {128, 128, 128};
    case ColorClass::kBronze: return {170, 120, 60};
    default: return {60, 60, 60};
  }
}

namespace {
// Outlines drawn over the image: the ball's in magenta (it stands out on
// orange and green), black robots in red.
cv::Scalar rgb_of(ColorClass c) {
  if (c == ColorClass::kOrange) return {255, 0, 255};
  if (c == ColorClass::kBlack || c == ColorClass::kNone) return {255, 0, 0};
  return color_rgb(c);
}
}  // namespace

void Detector::draw(const Frame& f, const std::vector<Detection>& dets, cv::Mat& out) const {
  f.rgb.copyTo(out);
  const auto& cam = cal_.camera;
  const cv::Point c(static_cast<int>(std::lround(cam.cx)), static_cast<int>(std::lround(cam.cy)));
  // The scanned annulus.
  double u = 0, v = 0;
  for (double d : {cal_.detector.min_distance, cal_.detector.line_max_distance}) {
    if (cam.project_ground(d, 0.0, u, v)) cv::circle(out, c, static_cast<int>(std::hypot(u - cam.cx, v - cam.cy)), {90, 90, 90}, 1);
  }
  for (const Detection& d : dets) {
    if (!cam.project_ground(d.vx, d.vy, u, v)) continue;
    const cv::Point p(static_cast<int>(std::lround(u)), static_cast<int>(std::lround(v)));
    if (d.membership_class == "Line" || d.membership_class == "Wall") {
      cv::circle(out, p, 1, {255, 0, 0}, cv::FILLED);
    } else if (d.membership_class == "Ball") {
      cv::circle(out, p, 7, rgb_of(d.color), 2);
      cv::line(out, c, p, rgb_of(d.color), 1);
    } else if (d.membership_class == "Goal") {
      cv::drawMarker(out, p, rgb_of(d.color), cv::MARKER_CROSS, 14, 2);
    } else if (d.membership_class == "GoalPost") {
      cv::drawMarker(out, p, rgb_of(d.color), cv::MARKER_TRIANGLE_UP, 10, 2);
    } else {
      cv::rectangle(out, p - cv::Point(6, 6), p + cv::Point(6, 6), rgb_of(d.color), 2);
    }
  }
}

}  // namespace mrt::recvision
