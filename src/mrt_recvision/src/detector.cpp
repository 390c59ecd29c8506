#include "mrt_recvision/detector.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrt_recvision/runs.h"

namespace mrt::recvision {

mrt::common::PerceptObject to_percept_object(const Detection& d) {
  mrt::common::PerceptObject o("", d.membership_class);
  const double sxy = std::hypot(d.sigma_distance, d.distance * d.sigma_bearing);
  o.set("distance", d.distance, d.sigma_distance, d.reliability).set("bearing", d.bearing, d.sigma_bearing, d.reliability);
  o.set("x", d.x, sxy, d.reliability).set("y", d.y, sxy, d.reliability);
  o.set_symbol("color", color_name(d.color), d.reliability);
  return o;
}

namespace {
constexpr auto kOrange = static_cast<std::uint8_t>(ColorClass::kOrange);
}  // namespace

Detector::Detector(const Calibration& cal) : cal_(cal), grid_(cal.camera, cal.detector), objects_(cal.objects) {
  const auto& cam = cal_.camera;
  const auto& o = cal_.detector;
  valid_half_ = cv::Mat::zeros(cam.height_px / 2, cam.width / 2, CV_8U);
  for (int v = 0; v < valid_half_.rows; ++v) {
    for (int u = 0; u < valid_half_.cols; ++u) {
      double x = 0, y = 0;
      if (!cam.pixel_to_ground(2 * u, 2 * v, x, y)) continue;
      const double d = std::hypot(x, y);
      if (d >= o.min_distance && d <= o.max_distance) valid_half_.at<std::uint8_t>(v, u) = 255;
    }
  }
  // Floor metres and bearing radians per image pixel, per centimetre of distance.
  for (double d = 0.0; d <= o.max_distance + 0.01; d += 0.01) {
    const double r = cam.profile.radius(std::atan2(d, cam.height));
    const double th2 = cam.profile.theta(r + 1.0);
    const double d2 = std::isfinite(th2) && th2 < M_PI / 2 ? cam.height * std::tan(th2) : 2.0 * d + 1.0;
    m_per_px_.push_back(std::isfinite(r) ? d2 - d : 1.0);
    rad_per_px_.push_back(std::isfinite(r) && r > 1.0 ? 1.0 / r : M_PI);
  }
  r_inner_ = cam.profile.radius(std::atan2(o.min_distance, cam.height));
  radial_cls_.resize(grid_.radial().size());
  for (std::size_t i = 0; i < grid_.radial().size(); ++i) radial_cls_[i].resize(grid_.radial()[i].points.size());
}

void Detector::set_mount(double x, double y, double yaw) {
  cal_.mount_x = x;
  cal_.mount_y = y;
  cal_.mount_yaw = yaw;
}

bool Detector::accepts(const Frame& f, std::string& why) const {
  if (f.rgb.type() != CV_8UC3) {
    why = "not an 8-bit 3-channel image";
    return false;
  }
  if (f.rgb.cols != cal_.camera.width || f.rgb.rows != cal_.camera.height_px) {
    why = "size " + std::to_string(f.rgb.cols) + "x" + std::to_string(f.rgb.rows) + " (calibrated " +
          std::to_string(cal_.camera.width) + "x" + std::to_string(cal_.camera.height_px) + ")";
    return false;
  }
  return true;
}

Detection Detector::make(const char* cls, ColorClass c, double x, double y, double px) const {
  Detection d;
  d.membership_class = cls;
  d.color = c;
  d.vx = x;
  d.vy = y;
  // Radial spread: `px` pixels of image radius at this floor distance (table per 1 cm).
  const double dv = std::hypot(x, y);
  const std::size_t bin = std::min(m_per_px_.size() - 1, static_cast<std::size_t>(dv * 100.0));
  d.sigma_distance = std::max(px * m_per_px_[bin], 1e-3);
  d.sigma_bearing = px * rad_per_px_[bin];
  const double c0 = std::cos(cal_.mount_yaw), s0 = std::sin(cal_.mount_yaw);
  d.x = cal_.mount_x + c0 * x - s0 * y;
  d.y = cal_.mount_y + s0 * x + c0 * y;
  d.distance = std::hypot(d.x, d.y);
  d.bearing = std::atan2(d.y, d.x);
  return d;
}

std::vector<Detection> Detector::process(const Frame& f) {
  std::string why;
  if (!accepts(f, why)) throw std::invalid_argument("frame refused: " + why);
  if (!f.rgb.isContinuous()) throw std::invalid_argument("frame refused: not continuous");
  const std::uint8_t* img = f.rgb.ptr<std::uint8_t>();
  const ColorTable& t = cal_.colors;
  for (std::size_t i = 0; i < grid_.radial().size(); ++i) {
    const auto& pts = grid_.radial()[i].points;
    std::uint8_t* c = radial_cls_[i].data();
    for (std::size_t k = 0; k < pts.size(); ++k) c[k] = t.lookup(img + 3 * pts[k].offset);
  }
  stats_ = DetectorStats();
  std::vector<Detection> out;
  const DetectorOptions& o = cal_.detector;
  if (o.find_ball) find_ball(f, out);
  if (o.find_goals) find_goals(out);
  if (o.find_robots) find_robots(out);
  if (o.find_lines) find_lines(img, out);
  if (cal_.objects.enabled) find_objects(out);
  return out;
}

void Detector::find_lines(const std::uint8_t* img, std::vector<Detection>& out) {
  const auto& o = cal_.detector;
  std::vector<LinePoint> pts;
  for (std::size_t i = 0; i < grid_.radial().size(); ++i)
    find_line_points(grid_.radial()[i], radial_cls_[i].data(), o, pts);
  for (const ScanLine& l : grid_.circular()) {
    cls_.resize(l.points.size());
    for (std::size_t k = 0; k < l.points.size(); ++k) cls_[k] = cal_.colors.lookup(img + 3 * l.points[k].offset);
    find_line_points(l, cls_.data(), o, pts);
  }
  const double max2 = o.line_max_distance * o.line_max_distance;
  pts.erase(std::remove_if(pts.begin(), pts.end(), [&](const LinePoint& p) { return p.x * p.x + p.y * p.y > max2; }),
            pts.end());
  stats_.line_points_found = static_cast<int>(pts.size());
  const std::size_t step =
      o.max_line_points > 0 && pts.size() > std::size_t(o.max_line_points) ? (pts.size() + o.max_line_points - 1) / o.max_line_points : 1;
  for (std::size_t k = 0; k < pts.size(); k += step) {
    Detection d = make("Line", ColorClass::kWhite, pts[k].x, pts[k].y, 1.0);
    d.reliability = 0.9;
    out.push_back(d);
  }
}

bool Detector::ball_direction(const Frame& f, const cv::Rect& roi, Eigen::Vector3d& dir, int& count,
                              double& r_min, double& r_max) const {
  const auto& cam = cal_.camera;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  count = 0;
  r_min = 1e9;
  r_max = 0.0;
  for (int v = roi.y; v < roi.y + roi.height; ++v) {
    const std::uint8_t* row = f.rgb.ptr<std::uint8_t>(v);
    for (int u = roi.x; u < roi.x + roi.width; ++u) {
      if (cal_.colors.lookup(row + 3 * u) != kOrange) continue;
      Eigen::Vector3d d;
      const double r = std::hypot(u - cam.cx, v - cam.cy);
      if (r < 1.0 || !cam.ray(u, v, d)) continue;
      // Weight each pixel by the solid angle it covers, sin(theta) dtheta/dr / r,
      // so the mean direction is the axis of the ball's cone of rays.
      const double dth = cam.profile.theta(r + 0.5) - cam.profile.theta(r - 0.5);
      if (!std::isfinite(dth)) continue;
      r_min = std::min(r_min, r);
      r_max = std::max(r_max, r);
      sum += d * (std::sin(cam.profile.theta(r)) * dth / r);
      ++count;
    }
  }
  if (count == 0 || sum.norm() <= 0.0) return false;
  dir = sum.normalized();
  return true;
}

void Detector::find_ball(const Frame& f, std::vector<Detection>& out) {
  const auto& o = cal_.detector;
  const auto& cam = cal_.camera;
  cls_half_.create(valid_half_.size(), CV_8U);
  for (int v = 0; v < cls_half_.rows; ++v) {
    const std::uint8_t* src = f.rgb.ptr<std::uint8_t>(2 * v);
    std::uint8_t* dst = cls_half_.ptr<std::uint8_t>(v);
    for (int u = 0; u < cls_half_.cols; ++u) dst[u] = cal_.colors.lookup(src + 6 * u);
  }
  cv::compare(cls_half_, kOrange, mask_, cv::CMP_EQ);
  cv::bitwise_and(mask_, valid_half_, mask_);
  const int n = cv::connectedComponentsWithStats(mask_, labels_, stats_cc_, centroids_, 8, CV_32S);
  int best = -1;
  for (int i = 1; i < n; ++i) {
    if (4 * stats_cc_.at<int>(i, cv::CC_STAT_AREA) < o.min_ball_pixels) continue;
    ++stats_.ball_candidates;
    if (best < 0 || stats_cc_.at<int>(i, cv::CC_STAT_AREA) > stats_cc_.at<int>(best, cv::CC_STAT_AREA)) best = i;
  }
  if (best < 0) return;
  cv::Rect roi(2 * stats_cc_.at<int>(best, cv::CC_STAT_LEFT) - 2, 2 * stats_cc_.at<int>(best, cv::CC_STAT_TOP) - 2,
               2 * stats_cc_.at<int>(best, cv::CC_STAT_WIDTH) + 4, 2 * stats_cc_.at<int>(best, cv::CC_STAT_HEIGHT) + 4);
  roi &= cv::Rect(0, 0, cam.width, cam.height_px);
  Eigen::Vector3d dir;
  int count = 0;
  double r_min = 0, r_max = 0;
  if (!ball_direction(f, roi, dir, count, r_min, r_max) || count < o.min_ball_pixels || dir.z() >= -1e-6) return;
  // The ball's centre is o.ball_radius above the floor on that ray.
  const double s = (cam.height - o.ball_radius) / -dir.z();
  double bx = s * dir.x(), by = s * dir.y(), px = 0.5;
  // A ball reaching into the body's blind zone is partly hidden: its
  // centroid is biased outwards. Use the outermost ray instead, tangent to
  // the far side of the ball: d = (h - R) tan(theta) - R / cos(theta).
  const double th_out = cam.profile.theta(r_max + 0.5);
  if (r_min <= r_inner_ + 1.5 && std::isfinite(th_out) && th_out < M_PI / 2) {
    const double d = (cam.height - o.ball_radius) * std::tan(th_out) - o.ball_radius / std::cos(th_out);
    const double b = std::atan2(dir.y(), dir.x());
    bx = d * std::cos(b);
    by = d * std::sin(b);
    px = 1.0;
  }
  Detection d = make("Ball", ColorClass::kOrange, bx, by, px);
  d.reliability = std::min(1.0, count / (5.0 * o.min_ball_pixels));
  out.push_back(d);
}

void Detector::find_goals(std::vector<Detection>& out) {
  const auto& o = cal_.detector;
  for (ColorClass c : {ColorClass::kYellow, ColorClass::kBlue}) {
    const auto hits = first_runs(grid_.radial(), radial_cls_, static_cast<std::uint8_t>(c), 2, false);
    const auto segs = group_hits(hits, 1e9);
    const Segment* best = nullptr;
    for (const Segment& s : segs)
      if (s.pixels >= o.min_goal_pixels && s.lines >= 2 && (!best || s.pixels > best->pixels)) best = &s;
    if (!best) continue;
    const Hit& a = hits[best->first];
    const Hit& b = hits[best->last];
    Detection pa = make("GoalPost", c, a.x, a.y, 1.0), pb = make("GoalPost", c, b.x, b.y, 1.0);
    Detection g = make("Goal", c, 0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 1.0);
    g.reliability = std::min(1.0, best->pixels / (4.0 * o.min_goal_pixels));
    pa.reliability = pb.reliability = g.reliability;
    out.push_back(g);
    out.push_back(pa);
    out.push_back(pb);
  }
}

void Detector::find_robots(std::vector<Detection>& out) {
  const auto& o = cal_.detector;
  const auto hits = first_runs(grid_.radial(), radial_cls_, static_cast<std::uint8_t>(ColorClass::kBlack), 2, true);
  for (const Segment& s : group_hits(hits, 0.3)) {
    if (s.pixels < o.min_robot_pixels) continue;
    // Nearest floor point of the body, then one radius farther at the
    // segment's middle bearing.
    double dmin = 1e9;
    for (int k = s.first;; k = (k + 1) % int(hits.size())) {
      dmin = std::min(dmin, hits[k].distance);
      if (k == s.last) break;
    }
    const double bearing = s.middle_bearing;
    const double d = dmin + o.robot_radius;
    Detection r = make("Robot", marker_color(s, hits), d * std::cos(bearing), d * std::sin(bearing), 1.0);
    r.sigma_distance = std::hypot(r.sigma_distance, 0.2 * o.robot_radius);
    r.reliability = std::min(1.0, s.pixels / (2.0 * o.min_robot_pixels));
    out.push_back(r);
  }
}

}  // namespace mrt::recvision

namespace mrt::recvision {

void Detector::find_objects(std::vector<Detection>& out) {
  std::vector<FoundObject> found;
  std::vector<LinePoint> walls;
  objects_.find(grid_, radial_cls_, found, walls);
  const double step = 2.0 * M_PI / grid_.radial().size();
  for (const FoundObject& f : found) {
    Detection d = make(cal_.objects.kinds[f.kind].membership_class.c_str(), f.color, f.x, f.y, 1.0);
    // The bearing is the middle of the lines covered: within half a line's
    // step for a fully seen object (each edge is known to a step).
    d.sigma_bearing = std::max(d.sigma_bearing, 0.5 * step);
    d.reliability = f.occluded ? 0.7 : 1.0;
    out.push_back(d);
  }
  for (const LinePoint& p : walls) {
    Detection d = make("Wall", cal_.objects.wall, p.x, p.y, 0.5);
    d.reliability = 0.9;
    out.push_back(d);
  }
}

}  // namespace mrt::recvision
