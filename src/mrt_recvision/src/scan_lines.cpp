#include "mrt_recvision/scan_lines.h"

#include <cmath>

namespace mrt::recvision {

namespace {

// Appends pixel (u, v) with its floor point unless it repeats the last one
// or sees no floor.
void add_point(const mrt::common::OmniCamera& cam, double u, double v, ScanLine& line) {
  const int iu = static_cast<int>(std::lround(u)), iv = static_cast<int>(std::lround(v));
  if (iu < 0 || iv < 0 || iu >= cam.width || iv >= cam.height_px) return;
  const int off = iv * cam.width + iu;
  if (!line.points.empty() && line.points.back().offset == off) return;
  double x = 0, y = 0;
  if (!cam.pixel_to_ground(iu, iv, x, y)) return;
  line.points.push_back({off, static_cast<float>(x), static_cast<float>(y)});
}

}  // namespace

ScanGrid::ScanGrid(const mrt::common::OmniCamera& cam, const DetectorOptions& opt) {
  const double r_min = cam.profile.radius(std::atan2(opt.min_distance, cam.height));
  double r_max = cam.profile.radius(std::atan2(opt.max_distance, cam.height));
  if (!std::isfinite(r_max)) r_max = cam.profile.max_radius();
  const double r0 = std::isfinite(r_min) ? r_min : 0.0;
  radial_.resize(opt.radial_lines);
  for (int i = 0; i < opt.radial_lines; ++i) {
    ScanLine& l = radial_[i];
    l.bearing = 2.0 * M_PI * i / opt.radial_lines;
    const double s = std::sin(l.bearing), c = std::cos(l.bearing);
    for (double r = r0; r <= r_max; r += 1.0) add_point(cam, cam.cx - r * s, cam.cy - r * c, l);
  }
  for (double d : opt.circles) {
    double u = 0, v = 0;
    if (d < opt.min_distance || d > opt.max_distance || !cam.project_ground(d, 0.0, u, v)) continue;
    ScanLine l;
    l.distance = d;
    const double r = std::hypot(u - cam.cx, v - cam.cy);
    const int n = static_cast<int>(std::ceil(2.0 * M_PI * r));
    for (int k = 0; k <= n; ++k) {
      const double phi = 2.0 * M_PI * k / n;
      if (cam.project_ground(d * std::cos(phi), d * std::sin(phi), u, v)) add_point(cam, u, v, l);
    }
    circular_.push_back(std::move(l));
  }
}

void find_line_points(const ScanLine& line, const std::uint8_t* cls, const DetectorOptions& opt,
                      std::vector<LinePoint>& out) {
  constexpr auto kGreen = static_cast<std::uint8_t>(ColorClass::kGreen);
  constexpr auto kWhite = static_cast<std::uint8_t>(ColorClass::kWhite);
  const int n = static_cast<int>(line.points.size());
  // Index of the green point within `gap` unclassified points from k
  // walking by `step`, or -1.
  auto green_near = [&](int k, int step) {
    for (int j = 0; j <= opt.line_gap; ++j, k += step) {
      if (k < 0 || k >= n) return -1;
      if (cls[k] == kGreen) return k;
      if (cls[k] != 0) return -1;
    }
    return -1;
  };
  const double w2min = opt.line_min_width * opt.line_min_width, w2max = opt.line_max_width * opt.line_max_width;
  int k = 0;
  while (k < n) {
    if (cls[k] != kWhite) {
      ++k;
      continue;
    }
    const int s = k;
    while (k < n && cls[k] == kWhite) ++k;
    const int e = k - 1;
    const int before = green_near(s - 1, -1), after = green_near(e + 1, 1);
    if (before < 0 || after < 0) continue;
    // Width: from the middle of the edges (half-way to the green points).
    const ScanPoint& a = line.points[before];
    const ScanPoint& b = line.points[after];
    const ScanPoint& ps = line.points[s];
    const ScanPoint& pe = line.points[e];
    const double ax = 0.5 * (a.x + ps.x), ay = 0.5 * (a.y + ps.y), bx = 0.5 * (b.x + pe.x), by = 0.5 * (b.y + pe.y);
    const double w2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
    if (w2 < w2min || w2 > w2max) continue;
    out.push_back({static_cast<float>(0.5 * (ax + bx)), static_cast<float>(0.5 * (ay + by))});
  }
}

}  // namespace mrt::recvision
