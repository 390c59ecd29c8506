// Catadioptric omnidirectional camera model (ROS-free, header-only): the
// radial profile of the mirror (image radius <-> viewing angle, hence
// ground distance) plus the image centre and the tilt of the mirror axis.
// One model shared by mrt_sim's rendered camera and mrt_recvision's
// processing and calibration tools, so both sides agree on every pixel.
//
// Camera frame ("viewpoint frame"): origin at the mirror's effective
// viewpoint, x forward, y left, z up (REP-103), `height` metres above the
// floor. A ray leaving the viewpoint at angle `theta` from the downward
// vertical hits the floor at ground distance d = height * tan(theta);
// theta >= pi/2 looks at or above the horizon.
//
// Image convention: the robot's forward axis points up in the image
// (decreasing v) and its left (+y) to the left (decreasing u); a point at
// bearing phi (counter-clockwise from forward) and image radius r is at
//   u = cx - r sin(phi),  v = cy - r cos(phi).
#pragma once

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mrt::common {

/// Monotone radial profile r(theta): image radius (px) against the angle of
/// the viewing ray from the downward vertical (rad). Stored as a dense
/// table interpolated linearly, so analytic mirrors and fitted profiles
/// share one representation and both directions are exact inverses.
class MirrorProfile {
 public:
  MirrorProfile() = default;

  /// `theta_radius`: (theta rad, radius px) pairs, strictly increasing in
  /// both, starting at theta = 0 with radius 0 or more (the centre).
  explicit MirrorProfile(std::vector<std::pair<double, double>> theta_radius)
      : table_(std::move(theta_radius)) {
    if (table_.size() < 2) throw std::invalid_argument("mirror profile: need at least 2 samples");
    for (std::size_t i = 1; i < table_.size(); ++i) {
      if (!(table_[i].first > table_[i - 1].first) || !(table_[i].second > table_[i - 1].second))
        throw std::invalid_argument("mirror profile: samples must increase strictly in angle and radius (sample " +
                                    std::to_string(i) + ")");
    }
  }

  /// Single-viewpoint hyperbolic mirror (unified projection model):
  /// r = gamma * sin(theta) / (xi + cos(theta)), xi in (0, 1] the mirror
  /// parameter, gamma (px) the generalised focal length; sampled up to
  /// `theta_max` (must stay below acos(-xi)).
  static MirrorProfile hyperbolic(double gamma_px, double xi, double theta_max, int samples = 512) {
    if (!(gamma_px > 0) || !(xi > 0 && xi <= 1) || !(theta_max > 0) || std::cos(theta_max) + xi <= 1e-6)
      throw std::invalid_argument("hyperbolic mirror: need gamma > 0, 0 < xi <= 1, 0 < theta_max < acos(-xi)");
    return sampled(theta_max, samples, [&](double t) { return gamma_px * std::sin(t) / (xi + std::cos(t)); });
  }

  /// Two-part mirror as MSL teams use: an isometric inner part (constant
  /// ground resolution `metres_per_px` for a viewpoint at `height`, up to
  /// ground distance `inner_range`), then an outer part linear in angle
  /// (`px_per_rad`) up to `theta_max`, which may look above the horizon.
  static MirrorProfile isometric(double height, double metres_per_px, double inner_range, double px_per_rad,
                                 double theta_max, int samples = 512) {
    if (!(height > 0) || !(metres_per_px > 0) || !(inner_range > 0) || !(px_per_rad > 0))
      throw std::invalid_argument("isometric mirror: height, resolution, inner range and px/rad must be > 0");
    const double theta_b = std::atan2(inner_range, height);
    if (!(theta_max > theta_b)) throw std::invalid_argument("isometric mirror: theta_max must exceed the inner part");
    const double r_b = inner_range / metres_per_px;
    return sampled(theta_max, samples, [&](double t) {
      return t <= theta_b ? height * std::tan(t) / metres_per_px : r_b + (t - theta_b) * px_per_rad;
    }, theta_b);
  }

  /// Image radius of a ray at angle theta; NaN outside the mirror.
  double radius(double theta) const {
    return interpolate(theta, [](const Sample& s) { return s.first; }, [](const Sample& s) { return s.second; });
  }
  /// Angle of the ray seen at image radius r; NaN outside the mirror.
  double theta(double radius_px) const {
    return interpolate(radius_px, [](const Sample& s) { return s.second; }, [](const Sample& s) { return s.first; });
  }
  double max_theta() const { return table_.empty() ? 0.0 : table_.back().first; }
  double max_radius() const { return table_.empty() ? 0.0 : table_.back().second; }
  const std::vector<std::pair<double, double>>& table() const { return table_; }

 private:
  using Sample = std::pair<double, double>;

  // Samples f evenly on [0, theta_max], plus the kink `knot` if given.
  template <class F>
  static MirrorProfile sampled(double theta_max, int samples, F f, double knot = -1.0) {
    std::vector<Sample> t;
    const int n = std::max(samples, 2);
    for (int i = 0; i < n; ++i) {
      const double th = theta_max * i / (n - 1);
      if (knot > 0.0 && !t.empty() && t.back().first < knot && th > knot) t.emplace_back(knot, f(knot));
      t.emplace_back(th, f(th));
    }
    if (t[0].second == t[1].second) t[0].second = t[1].second * 0.5;  // keep strict monotony at the centre
    return MirrorProfile(std::move(t));
  }

  template <class Key, class Value>
  double interpolate(double x, Key key, Value value) const {
    if (table_.empty() || !std::isfinite(x) || x < key(table_.front()) || x > key(table_.back()))
      return std::numeric_limits<double>::quiet_NaN();
    auto it = std::lower_bound(table_.begin(), table_.end(), x,
                               [&](const Sample& s, double v) { return key(s) < v; });
    if (it == table_.begin()) return value(*it);
    const Sample& hi = *it;
    const Sample& lo = *(it - 1);
    const double a = (x - key(lo)) / (key(hi) - key(lo));
    return value(lo) + a * (value(hi) - value(lo));
  }

  std::vector<Sample> table_;
};

/// The whole camera: image size, mirror centre in the image, viewpoint
/// height above the floor, tilt of the mirror axis (roll about x, pitch
/// about y, rad) and the radial profile.
struct OmniCamera {
  int width = 640;
  int height_px = 480;
  double cx = 320.0;
  double cy = 240.0;
  double height = 0.6;  // m, viewpoint above the floor
  double roll = 0.0;
  double pitch = 0.0;
  MirrorProfile profile;

  /// Rotation of the mirror axis frame in the viewpoint frame.
  Eigen::Matrix3d tilt() const {
    return (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
  }

  /// The same camera for images scaled by `scale` (> 0; mrt_sim's
  /// ~camera_scale, mrt_recvision's ~scale): size rounded to whole pixels,
  /// the mirror centre with OpenCV's pixel-centre convention
  /// (c' = (c + 0.5) s - 0.5, what cv::resize does to a point), every
  /// radius of the mirror profile times s; viewpoint height and tilt
  /// unchanged. Throws std::invalid_argument for scale <= 0 or an image
  /// under 16 pixels.
  OmniCamera scaled(double scale) const {
    if (!(scale > 0.0) || !std::isfinite(scale)) throw std::invalid_argument("camera scale: expected a number > 0");
    OmniCamera out = *this;
    out.width = static_cast<int>(std::lround(width * scale));
    out.height_px = static_cast<int>(std::lround(height_px * scale));
    if (out.width < 4 || out.height_px < 4 || out.width * out.height_px < 16)
      throw std::invalid_argument("camera scale: " + std::to_string(scale) + " leaves an image of " +
                                  std::to_string(out.width) + "x" + std::to_string(out.height_px) + " pixels");
    out.cx = (cx + 0.5) * scale - 0.5;
    out.cy = (cy + 0.5) * scale - 0.5;
    std::vector<std::pair<double, double>> table = profile.table();
    for (auto& s : table) s.second *= scale;
    out.profile = MirrorProfile(std::move(table));
    return out;
  }

  /// Pixel of a 3-D point given in the viewpoint frame; false if the point
  /// is outside the mirror's field of view or the image.
  bool project(const Eigen::Vector3d& p, double& u, double& v) const {
    const Eigen::Vector3d q = tilt().transpose() * p;
    const double rho = std::hypot(q.x(), q.y());
    if (rho <= 0.0 && q.z() >= 0.0) return false;
    const double r = profile.radius(std::atan2(rho, -q.z()));
    if (!std::isfinite(r)) return false;
    const double phi = std::atan2(q.y(), q.x());
    u = cx - r * std::sin(phi);
    v = cy - r * std::cos(phi);
    return u >= 0.0 && v >= 0.0 && u < width && v < height_px;
  }

  /// Pixel of a floor point (x, y) given relative to the point under the
  /// viewpoint (robot-frame metres, camera mount offset removed).
  bool project_ground(double x, double y, double& u, double& v) const {
    return project(Eigen::Vector3d(x, y, -height), u, v);
  }

  /// Unit direction (viewpoint frame) of the ray seen at pixel (u, v);
  /// false outside the mirror.
  bool ray(double u, double v, Eigen::Vector3d& dir) const {
    const double du = cx - u, dv = cy - v;
    const double th = profile.theta(std::hypot(du, dv));
    if (!std::isfinite(th)) return false;
    const double phi = std::atan2(du, dv);
    const Eigen::Vector3d q(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), -std::cos(th));
    dir = tilt() * q;
    return true;
  }

  /// Floor point (x, y) seen at pixel (u, v); false if the ray misses the
  /// floor (at or above the horizon) or the mirror.
  bool pixel_to_ground(double u, double v, double& x, double& y) const {
    Eigen::Vector3d d;
    if (!ray(u, v, d) || d.z() >= -1e-9) return false;
    const double s = height / -d.z();
    x = s * d.x();
    y = s * d.y();
    return true;
  }
};

}  // namespace mrt::common
