// The rendered omnidirectional camera: per-pixel rays computed once, a
// pre-rendered floor texture, objects drawn inside their image bounding
// boxes with a depth buffer, then the image effects (camera.h).
#include "mrt_sim/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "mrt_common/angle.h"

namespace mrt::sim {

using mrt::common::kPi;

namespace detail {
// One thing to draw, in the world frame: a vertical cylinder (posts,
// movers, robots), a sphere resting on the floor (the ball) or a vertical
// wall on a segment.
struct CameraShape {
  enum Type { kCylinder, kSphere, kWall } type = kCylinder;
  double x = 0, y = 0, r = 0;    // centre and radius (cylinder, sphere)
  double ax = 0, ay = 0, bx = 0, by = 0;  // wall ends
  double height = 0;
  double band = 0;               // top band drawn in `top` (robot markers)
  cv::Vec3b color, top;
};

}  // namespace detail
using Shape = detail::CameraShape;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

enum PixelKind : std::uint8_t { kOutside = 0, kOwnBody = 1, kFloor = 2, kAbove = 3 };

cv::Vec3b scaled(const cv::Vec3b& c, double f) {
  return cv::Vec3b(cv::saturate_cast<uchar>(c[0] * f), cv::saturate_cast<uchar>(c[1] * f),
                   cv::saturate_cast<uchar>(c[2] * f));
}

// Ray (origin o at height h, direction d, |d| = 1) against a shape: ray
// length to the first hit or +inf; `top` is set when the hit is on the top
// cap or in the top band; `shade` is a brightness factor (sphere lighting).
struct Ray {
  double ox, oy, h, dx, dy, dz;
};

double hit_cylinder(const Ray& r, const Shape& s, bool& top) {
  const double px = r.ox - s.x, py = r.oy - s.y;
  const double a = r.dx * r.dx + r.dy * r.dy;
  const double b = px * r.dx + py * r.dy;
  const double c = px * px + py * py - s.r * s.r;
  double best = kInf;
  if (a > 1e-12) {
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double t = (-b - std::sqrt(disc)) / a;
      const double z = r.h + t * r.dz;
      if (t > 0.0 && z >= 0.0 && z <= s.height) {
        best = t;
        top = z >= s.height - s.band;
      }
    }
  }
  if (r.h > s.height && r.dz < 0.0) {  // the top cap, seen from above
    const double t = (s.height - r.h) / r.dz;
    const double qx = px + t * r.dx, qy = py + t * r.dy;
    if (t > 0.0 && t < best && qx * qx + qy * qy <= s.r * s.r) {
      best = t;
      top = s.band <= 0.0;  // a robot's top is its black body, its marker a band around the side
    }
  }
  return best;
}

double hit_sphere(const Ray& r, const Shape& s, double& shade) {
  const double px = r.ox - s.x, py = r.oy - s.y, pz = r.h - s.r;
  const double b = px * r.dx + py * r.dy + pz * r.dz;
  const double c = px * px + py * py + pz * pz - s.r * s.r;
  const double disc = b * b - c;
  if (disc < 0.0) return kInf;
  const double t = -b - std::sqrt(disc);
  if (t <= 0.0) return kInf;
  const double nz = (pz + t * r.dz) / s.r;  // normal's z: lit from above
  shade = 0.7 + 0.3 * nz;
  return t;
}

double hit_wall(const Ray& r, const Shape& s) {
  const double ex = s.bx - s.ax, ey = s.by - s.ay;
  const double den = r.dx * ey - r.dy * ex;
  if (std::fabs(den) < 1e-12) return kInf;
  const double wx = s.ax - r.ox, wy = s.ay - r.oy;
  const double t = (wx * ey - wy * ex) / den;
  const double u = (wx * r.dy - wy * r.dx) / den;
  if (t <= 0.0 || u < 0.0 || u > 1.0) return kInf;
  const double z = r.h + t * r.dz;
  return z >= 0.0 && z <= s.height ? t : kInf;
}

}  // namespace

cv::Vec3b color_rgb(const std::string& name, cv::Vec3b fallback) {
  static const std::map<std::string, cv::Vec3b> kColors = {
      {"orange", {255, 120, 0}}, {"yellow", {255, 220, 0}},   {"blue", {0, 70, 255}},
      {"cyan", {0, 220, 255}},   {"magenta", {240, 0, 200}},  {"red", {220, 20, 20}},
      {"green", {0, 200, 60}},   {"white", {255, 255, 255}},  {"black", {0, 0, 0}},
      {"grey", {128, 128, 128}}, {"gray", {128, 128, 128}},   {"brown", {130, 80, 30}},
      {"purple", {130, 40, 180}}, {"pink", {255, 150, 190}},  {"beige", {190, 175, 150}},
      {"bronze", {170, 120, 60}}};
  const auto it = kColors.find(name);
  return it == kColors.end() ? fallback : it->second;
}

CameraOptions camera_options(const RobotConfig& robot, std::uint64_t seed) {
  CameraOptions o;
  o.mount_x = robot.sensors.camera.mount_x;
  o.mount_y = robot.sensors.camera.mount_y;
  o.own_body_radius = robot.base.body_radius;
  o.effects = robot.sensors.camera.effects;
  o.seed = seed;
  return o;
}

CameraRenderer::CameraRenderer(const World& world, const mrt::common::OmniCamera& camera,
                               const CameraOptions& options)
    : world_(world), camera_(camera), options_(options), rng_(options.seed) {
  build_rays();
  build_floor();
  if (options_.effects.noise > 0.0) {
    // A pool of Gaussian noise, split into its positive and negative parts
    // so a frame adds one and subtracts the other with saturating SIMD
    // arithmetic (exact: only one of them is non-zero at each element).
    cv::Mat n(camera_.height_px + 32, (camera_.width + 32) * 3, CV_32F);
    cv::RNG rng(options_.seed * 7919 + 17);
    rng.fill(n, cv::RNG::NORMAL, 0.0, options_.effects.noise);
    cv::Mat pos = cv::max(n, 0.0), neg = cv::max(-n, 0.0);
    pos.convertTo(noise_pos_, CV_8U);  // rounds and saturates
    neg.convertTo(noise_neg_, CV_8U);
  }
}

void CameraRenderer::build_rays() {
  const int n = camera_.width * camera_.height_px;
  dx_.assign(n, 0.f), dy_.assign(n, 0.f), dz_.assign(n, 0.f), dxy_.assign(n, 0.f);
  gx_.assign(n, 0.f), gy_.assign(n, 0.f), tfloor_.assign(n, kInf);
  kind_.assign(n, kOutside);
  depth_.assign(n, kInf);
  const double h = camera_.height;
  const double hb = std::min(options_.own_body_height, h - 1e-3);
  const double rb = options_.own_body_radius;
  for (int v = 0; v < camera_.height_px; ++v) {
    for (int u = 0; u < camera_.width; ++u) {
      const int i = v * camera_.width + u;
      Eigen::Vector3d d;
      if (!camera_.ray(u, v, d)) continue;  // pixel (u, v) is the ray of the integer coordinates (OpenCV)
      dx_[i] = static_cast<float>(d.x()), dy_[i] = static_cast<float>(d.y()), dz_[i] = static_cast<float>(d.z());
      dxy_[i] = static_cast<float>(std::hypot(d.x(), d.y()));
      if (d.z() < -1e-9) {
        const double tb = (hb - h) / d.z();  // the own body's top
        const double bx = options_.mount_x + tb * d.x(), by = options_.mount_y + tb * d.y();
        if (bx * bx + by * by <= rb * rb) {
          kind_[i] = kOwnBody;
          continue;
        }
        const double t = h / -d.z();
        kind_[i] = kFloor;
        tfloor_[i] = static_cast<float>(t);
        gx_[i] = static_cast<float>(options_.mount_x + t * d.x());
        gy_[i] = static_cast<float>(options_.mount_y + t * d.y());
      } else {
        kind_[i] = kAbove;
      }
    }
  }
}

double CameraRenderer::illumination(double x, double y) const {
  const double a = options_.effects.illumination;
  if (a <= 0.0) return 1.0;
  const double k = 2.0 * kPi / options_.effects.illumination_scale;
  return 1.0 + a * std::sin(k * x + 0.3) * std::cos(k * y - 0.7);
}

void CameraRenderer::build_floor() {
  const double res = options_.texture_resolution;
  floor_x0_ = world_.min_x, floor_y0_ = world_.min_y;
  const int w = static_cast<int>(std::ceil((world_.max_x - world_.min_x) / res)) + 1;
  const int h = static_cast<int>(std::ceil((world_.max_y - world_.min_y) / res)) + 1;
  floor_.create(h, w, CV_8UC3);
  const cv::Vec3b f = world_.floor_color == "carpet" ? options_.carpet : color_rgb(world_.floor_color, options_.carpet);
  floor_.setTo(cv::Scalar(f[0], f[1], f[2]));
  // Lines at their true width: cv::line with round caps joins the chords
  // of arcs; 16x sub-pixel precision for the end points.
  const int thick = std::max(1, static_cast<int>(std::lround(world_.line_width / res)));
  const cv::Scalar white(options_.line[0], options_.line[1], options_.line[2]);
  auto px = [&](const Point2D& p) {
    return cv::Point(static_cast<int>(std::lround((p.x - floor_x0_) / res * 16.0)),
                     static_cast<int>(std::lround((p.y - floor_y0_) / res * 16.0)));
  };
  for (const Segment& s : world_.field_lines) cv::line(floor_, px(s.a), px(s.b), white, thick, cv::LINE_8, 4);
  if (options_.effects.illumination > 0.0) {
    for (int r = 0; r < h; ++r) {
      cv::Vec3b* row = floor_.ptr<cv::Vec3b>(r);
      for (int c = 0; c < w; ++c) row[c] = scaled(row[c], illumination(floor_x0_ + c * res, floor_y0_ + r * res));
    }
  }
}

void CameraRenderer::render(const Pose2D& robot, const std::vector<OtherRobot>& others, double time, cv::Mat& rgb,
                            const Twist2D& velocity) {
  rgb.create(camera_.height_px, camera_.width, CV_8UC3);
  draw_floor(robot, rgb);
  draw_shadow(robot, rgb);
  draw_objects(robot, others, rgb);
  apply_effects(time, velocity, rgb);
}

void CameraRenderer::draw_floor(const Pose2D& robot, cv::Mat& rgb) {
  const double c = std::cos(robot.theta), s = std::sin(robot.theta);
  const double inv = 1.0 / options_.texture_resolution;
  const int tw = floor_.cols, th = floor_.rows;
  const cv::Vec3b black(0, 0, 0);
  const int w = camera_.width;
  for (int v = 0; v < camera_.height_px; ++v) {
    cv::Vec3b* out = rgb.ptr<cv::Vec3b>(v);
    for (int u = 0; u < w; ++u) {
      const int i = v * w + u;
      switch (kind_[i]) {
        case kFloor: {
          const double wx = robot.x + c * gx_[i] - s * gy_[i];
          const double wy = robot.y + s * gx_[i] + c * gy_[i];
          const int tx = static_cast<int>(std::floor((wx - floor_x0_) * inv + 0.5));
          const int ty = static_cast<int>(std::floor((wy - floor_y0_) * inv + 0.5));
          out[u] = (tx >= 0 && ty >= 0 && tx < tw && ty < th) ? floor_.at<cv::Vec3b>(ty, tx) : options_.outside;
          depth_[i] = tfloor_[i];
          break;
        }
        case kAbove:
          out[u] = options_.sky;
          depth_[i] = kInf;
          break;
        default:  // outside the mirror or the own body: black, never drawn over
          out[u] = black;
          depth_[i] = -1.f;
      }
    }
  }
}

namespace {

// Image bounding box of a set of points (viewpoint frame) through the
// mirror, with points beyond the mirror's field of view clamped to its rim.
class BoundingBox {
 public:
  explicit BoundingBox(const mrt::common::OmniCamera& cam) : cam_(cam), tilt_t_(cam.tilt().transpose()) {}
  void add(const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = tilt_t_ * p;
    const double rho = std::hypot(q.x(), q.y());
    double r = 0.0, phi = 0.0;
    if (rho > 1e-9) {
      const double th = std::min(std::atan2(rho, -q.z()), cam_.profile.max_theta());
      r = cam_.profile.radius(th);
      phi = std::atan2(q.y(), q.x());
    }
    const double u = cam_.cx - r * std::sin(phi), v = cam_.cy - r * std::cos(phi);
    u0_ = std::min(u0_, u), u1_ = std::max(u1_, u), v0_ = std::min(v0_, v), v1_ = std::max(v1_, v);
  }
  // Pixel range, padded, clipped to the image; false if empty.
  bool range(int& u0, int& u1, int& v0, int& v1) const {
    constexpr double kPad = 4.0;
    u0 = std::max(0, static_cast<int>(std::floor(u0_ - kPad)));
    v0 = std::max(0, static_cast<int>(std::floor(v0_ - kPad)));
    u1 = std::min(cam_.width - 1, static_cast<int>(std::ceil(u1_ + kPad)));
    v1 = std::min(cam_.height_px - 1, static_cast<int>(std::ceil(v1_ + kPad)));
    return u0 <= u1 && v0 <= v1;
  }

 private:
  const mrt::common::OmniCamera& cam_;
  Eigen::Matrix3d tilt_t_;
  double u0_ = 1e18, u1_ = -1e18, v0_ = 1e18, v1_ = -1e18;
};

Shape cylinder(double x, double y, double r, double height, cv::Vec3b color) {
  Shape s;
  s.type = Shape::kCylinder, s.x = x, s.y = y, s.r = r, s.height = height, s.color = s.top = color;
  return s;
}

Shape wall(const Segment& seg, double height, cv::Vec3b color) {
  Shape s;
  s.type = Shape::kWall, s.ax = seg.a.x, s.ay = seg.a.y, s.bx = seg.b.x, s.by = seg.b.y;
  s.height = height, s.color = s.top = color;
  return s;
}

}  // namespace

void CameraRenderer::draw_shadow(const Pose2D& robot, cv::Mat& rgb) {
  const Ball& b = world_.ball;
  if (!b.enabled || options_.shadow >= 1.0) return;
  const double c = std::cos(robot.theta), s = std::sin(robot.theta);
  const double r0 = 0.8 * b.radius, r1 = 1.3 * b.radius;
  // the shadow's disc on the floor, in the viewpoint frame
  BoundingBox box(camera_);
  const double bx = c * (b.position.x - robot.x) + s * (b.position.y - robot.y) - options_.mount_x;
  const double by = -s * (b.position.x - robot.x) + c * (b.position.y - robot.y) - options_.mount_y;
  for (int k = 0; k < 16; ++k)
    box.add({bx + r1 * std::cos(k * kPi / 8), by + r1 * std::sin(k * kPi / 8), -camera_.height});
  int u0, u1, v0, v1;
  if (!box.range(u0, u1, v0, v1)) return;
  for (int v = v0; v <= v1; ++v) {
    cv::Vec3b* out = rgb.ptr<cv::Vec3b>(v);
    for (int u = u0; u <= u1; ++u) {
      const int i = v * camera_.width + u;
      if (kind_[i] != kFloor) continue;
      const double d = std::hypot(gx_[i] - options_.mount_x - bx, gy_[i] - options_.mount_y - by);
      if (d >= r1) continue;
      const double a = d <= r0 ? 0.0 : (d - r0) / (r1 - r0);  // soft edge
      out[u] = scaled(out[u], options_.shadow + a * (1.0 - options_.shadow));
    }
  }
}

void CameraRenderer::draw_objects(const Pose2D& robot, const std::vector<OtherRobot>& others, cv::Mat& rgb) {
  const CameraOptions& o = options_;
  std::vector<Shape> shapes;
  auto lit = [&](cv::Vec3b col, double x, double y) { return scaled(col, illumination(x, y)); };
  for (const Segment& w : world_.walls)
    shapes.push_back(wall(w, o.wall_height, lit(o.wall, 0.5 * (w.a.x + w.b.x), 0.5 * (w.a.y + w.b.y))));
  for (const Goal& g : world_.goals) {
    const cv::Vec3b col = lit(color_rgb(g.color, o.wall), g.pose.x, g.pose.y);
    for (const Segment& w : goal_walls(g)) shapes.push_back(wall(w, o.goal_height, col));
    for (const Point2D& p : goal_posts(g)) shapes.push_back(cylinder(p.x, p.y, o.goal_post_radius, o.goal_height, col));
  }
  for (const Post& p : world_.posts)
    shapes.push_back(cylinder(p.center.x, p.center.y, p.radius, o.post_height,
                              lit(color_rgb(p.color), p.center.x, p.center.y)));
  auto robot_shape = [&](double x, double y, double r, const std::string& color) {
    Shape sh = cylinder(x, y, r, o.robot_height, lit(o.robot_body, x, y));
    sh.top = lit(color_rgb(color, o.robot_body), x, y);
    sh.band = o.marker_band;
    return sh;
  };
  for (const Mover& m : world_.movers) {
    if (m.membership_class == "Robot")
      shapes.push_back(robot_shape(m.position.x, m.position.y, m.radius, m.color));
    else
      shapes.push_back(cylinder(m.position.x, m.position.y, m.radius, o.person_height,
                                lit(color_rgb(m.color, cv::Vec3b(200, 160, 130)), m.position.x, m.position.y)));
  }
  for (const OtherRobot& r : others) shapes.push_back(robot_shape(r.center.x, r.center.y, r.radius, r.color));
  if (world_.ball.enabled) {
    const Ball& b = world_.ball;
    Shape sh;
    sh.type = Shape::kSphere, sh.x = b.position.x, sh.y = b.position.y, sh.r = b.radius, sh.height = 2 * b.radius;
    sh.color = sh.top = lit(color_rgb(b.color, cv::Vec3b(255, 120, 0)), b.position.x, b.position.y);
    shapes.push_back(sh);
  }
  for (const Shape& sh : shapes) draw_shape(robot, sh, rgb);
}

void CameraRenderer::draw_shape(const Pose2D& robot, const Shape& sh, cv::Mat& rgb) {
  const double c = std::cos(robot.theta), s = std::sin(robot.theta);
  const double mx = options_.mount_x, my = options_.mount_y, h = camera_.height;
  auto to_view = [&](double x, double y, double z) {
    return Eigen::Vector3d(c * (x - robot.x) + s * (y - robot.y) - mx, -s * (x - robot.x) + c * (y - robot.y) - my,
                           z - h);
  };
  BoundingBox box(camera_);
  if (sh.type == Shape::kWall) {
    const int n = std::min(400, static_cast<int>(std::hypot(sh.bx - sh.ax, sh.by - sh.ay) / 0.1) + 2);
    for (int k = 0; k < n; ++k) {
      const double a = static_cast<double>(k) / (n - 1);
      const double x = sh.ax + a * (sh.bx - sh.ax), y = sh.ay + a * (sh.by - sh.ay);
      box.add(to_view(x, y, 0.0));
      box.add(to_view(x, y, sh.height));
    }
  } else {
    for (int k = 0; k < 24; ++k) {
      const double x = sh.x + sh.r * std::cos(k * kPi / 12), y = sh.y + sh.r * std::sin(k * kPi / 12);
      box.add(to_view(x, y, 0.0));
      box.add(to_view(x, y, sh.height));
    }
  }
  int u0, u1, v0, v1;
  if (!box.range(u0, u1, v0, v1)) return;
  Ray ray{robot.x + c * mx - s * my, robot.y + s * mx + c * my, h, 0, 0, 0};
  // A pixel whose nearest hit so far is closer (horizontally) than the
  // whole shape cannot see it: skip it without the intersection.
  double reach = 0.0;
  if (sh.type == Shape::kWall)
    reach = distance_to_segment({ray.ox, ray.oy}, Segment{{sh.ax, sh.ay}, {sh.bx, sh.by}});
  else
    reach = std::max(0.0, std::hypot(ray.ox - sh.x, ray.oy - sh.y) - sh.r);
  const float min_reach = static_cast<float>(reach - 1e-6);
  for (int v = v0; v <= v1; ++v) {
    cv::Vec3b* out = rgb.ptr<cv::Vec3b>(v);
    for (int u = u0; u <= u1; ++u) {
      const int i = v * camera_.width + u;
      if (kind_[i] < kFloor || depth_[i] * dxy_[i] < min_reach) continue;
      ray.dx = c * dx_[i] - s * dy_[i], ray.dy = s * dx_[i] + c * dy_[i], ray.dz = dz_[i];
      bool top = false;
      double shade = 1.0, t = kInf;
      switch (sh.type) {
        case Shape::kCylinder: t = hit_cylinder(ray, sh, top); break;
        case Shape::kSphere: t = hit_sphere(ray, sh, shade); break;
        case Shape::kWall: t = hit_wall(ray, sh); break;
      }
      if (!(t < depth_[i])) continue;
      depth_[i] = static_cast<float>(t);
      out[u] = shade == 1.0 ? (top ? sh.top : sh.color) : scaled(sh.color, shade);
    }
  }
}

void CameraRenderer::apply_effects(double time, const Twist2D& velocity, cv::Mat& rgb) {
  const CameraEffects& e = options_.effects;
  const double speed = std::hypot(velocity.vx, velocity.vy);
  if (e.exposure > 0.0 && speed > 0.0) {
    // Blur at speed: the floor slides by v * exposure during the exposure;
    // near the robot the mirror maps the floor like a top view, so the
    // blur is a line along the image direction of the motion, as long as
    // that slide in pixels (image scale taken at 2 m). Rotation is not
    // blurred.
    const double h = camera_.height;
    const double ppm = (camera_.profile.radius(std::atan2(2.1, h)) - camera_.profile.radius(std::atan2(1.9, h))) / 0.2;
    const double len = speed * e.exposure * (std::isfinite(ppm) ? ppm : 0.0);
    if (len >= 1.0) {
      const int half = static_cast<int>(std::ceil(len / 2.0));
      cv::Mat k = cv::Mat::zeros(2 * half + 1, 2 * half + 1, CV_32F);
      const double du = -velocity.vy / speed * len / 2.0, dv = -velocity.vx / speed * len / 2.0;
      cv::line(k, cv::Point(static_cast<int>(std::lround(half - du)), static_cast<int>(std::lround(half - dv))),
               cv::Point(static_cast<int>(std::lround(half + du)), static_cast<int>(std::lround(half + dv))),
               cv::Scalar(1.0), 1, cv::LINE_AA);
      k /= cv::sum(k)[0];
      cv::filter2D(rgb, rgb, -1, k, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
    }
  }
  const double flicker = 1.0 + e.flicker * std::sin(2.0 * kPi * time / e.flicker_period);
  if (flicker != 1.0 || e.white_balance_drift > 0.0) {
    cv::Mat lut(1, 256, CV_8UC3);
    for (int ch = 0; ch < 3; ++ch) {
      const double wb = 1.0 + e.white_balance_drift * std::sin(2.0 * kPi * time / e.white_balance_period + ch * 2.0 * kPi / 3.0);
      for (int k = 0; k < 256; ++k) lut.at<cv::Vec3b>(0, k)[ch] = cv::saturate_cast<uchar>(k * flicker * wb);
    }
    cv::LUT(rgb, lut, rgb);
  }
  if (!noise_pos_.empty()) {
    std::uniform_int_distribution<int> off(0, 31);
    const int ou = off(rng_) * 3, ov = off(rng_);
    const cv::Rect roi(ou, ov, camera_.width * 3, camera_.height_px);
    cv::Mat flat = rgb.reshape(1);
    cv::add(flat, noise_pos_(roi), flat);
    cv::subtract(flat, noise_neg_(roi), flat);
  }
}

}  // namespace mrt::sim
