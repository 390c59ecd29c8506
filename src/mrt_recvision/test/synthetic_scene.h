// A small ray-casting painter of omnidirectional images for the tests and
// the benchmark (header-only, test support): every pixel's ray (from
// mrt_common's OmniCamera) is intersected with the floor (green carpet,
// white lines of a given width, the ball's shadow), the ball (a sphere),
// robots (vertical cylinders with a coloured marker band and top) and goals (posts
// and walls as vertical rectangles); the robot's own body is black at the
// centre. Illumination scales every colour; noise adds Gaussian noise.
#pragma once

#include <opencv2/core.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "mrt_common/omni_camera.h"

namespace mrt::recvision::testing {

struct Seg2 {
  Eigen::Vector2d a, b;
};
struct SceneBall {
  Eigen::Vector2d c;
  double r = 0.11;
};
struct SceneRobot {
  Eigen::Vector2d c;
  double r = 0.25, height = 0.6;
  cv::Vec3b marker{0, 230, 230};
};
struct SceneGoal {
  Eigen::Vector2d mouth;  // mouth centre
  double theta = 0;       // pointing into the goal
  double width = 2.0, depth = 0.5, height = 1.0;
  cv::Vec3b color{230, 210, 0};
};

struct Scene {
  std::vector<Seg2> lines;
  double line_width = 0.125;
  std::optional<SceneBall> ball;
  std::vector<SceneRobot> robots;
  std::vector<SceneGoal> goals;
  double body_radius = 0.3;  // own body hides floor closer than this
  double illumination = 1.0;
  double noise = 0.0;        // std-dev per channel (0..255)
  cv::Vec3b green{40, 140, 40}, white{250, 250, 250}, orange{255, 120, 0}, black{15, 15, 15},
      shadow{20, 75, 20}, sky{120, 120, 130};
};

inline double seg_dist(const Eigen::Vector2d& p, const Seg2& s) {
  const Eigen::Vector2d d = s.b - s.a;
  const double t = std::clamp((p - s.a).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
  return (s.a + t * d - p).norm();
}

// Hit of the ray o + t d with a vertical rectangle over segment s up to
// height h; t or +inf.
inline double hit_wall(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Seg2& s, double h) {
  const Eigen::Vector2d e = s.b - s.a, dd(d.x(), d.y());
  const double den = dd.x() * e.y() - dd.y() * e.x();
  if (std::abs(den) < 1e-12) return INFINITY;
  const Eigen::Vector2d w = s.a - Eigen::Vector2d(o.x(), o.y());
  const double t = (w.x() * e.y() - w.y() * e.x()) / den;
  const double u = (w.x() * dd.y() - w.y() * dd.x()) / den;
  if (t <= 0 || u < 0 || u > 1) return INFINITY;
  const double z = o.z() + t * d.z();
  return z >= 0 && z <= h ? t : INFINITY;
}

inline double hit_cylinder(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector2d& c, double r,
                           double h, bool* top = nullptr) {
  double best = INFINITY;
  const Eigen::Vector2d p(o.x() - c.x(), o.y() - c.y()), q(d.x(), d.y());
  const double a = q.squaredNorm(), b = 2 * p.dot(q), cc = p.squaredNorm() - r * r;
  const double disc = b * b - 4 * a * cc;
  if (a > 1e-12 && disc >= 0) {
    const double t = (-b - std::sqrt(disc)) / (2 * a);
    const double z = o.z() + t * d.z();
    if (t > 0 && z >= 0 && z <= h) best = t;
  }
  if (d.z() < 0 && o.z() > h) {  // the top disc
    const double t = (h - o.z()) / d.z();
    const Eigen::Vector2d x = p + t * q;
    if (x.norm() <= r && t < best) {
      best = t;
      if (top) *top = x.norm() <= 0.6 * r;
    }
  }
  return best;
}

inline cv::Vec3b shade(const cv::Vec3b& c, double k) {
  return cv::Vec3b(cv::saturate_cast<uchar>(c[0] * k), cv::saturate_cast<uchar>(c[1] * k),
                   cv::saturate_cast<uchar>(c[2] * k));
}

// Colour of one ray (viewpoint at `o`, world direction `d`).
inline cv::Vec3b trace(const Scene& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  double best = INFINITY;
  cv::Vec3b col = s.sky;
  if (d.z() < 0) {
    best = -o.z() / d.z();
    const Eigen::Vector2d g(o.x() + best * d.x(), o.y() + best * d.y());
    col = s.green;
    for (const Seg2& l : s.lines)
      if (seg_dist(g, l) <= 0.5 * s.line_width) col = s.white;
    if (s.ball && (g - s.ball->c).norm() < 0.9 * s.ball->r) col = s.shadow;
  }
  if (s.ball) {
    const Eigen::Vector3d c(s.ball->c.x(), s.ball->c.y(), s.ball->r);
    const Eigen::Vector3d oc = o - c;
    const double b = oc.dot(d), cc = oc.squaredNorm() - s.ball->r * s.ball->r, disc = b * b - cc;
    if (disc >= 0) {
      const double t = -b - std::sqrt(disc);
      if (t > 0 && t < best) best = t, col = s.orange;
    }
  }
  for (const SceneRobot& r : s.robots) {
    bool top = false;
    const double t = hit_cylinder(o, d, r.c, r.r, r.height, &top);
    const double z = o.z() + t * d.z();  // marker: the top disc and a band round the body
    if (t < best) best = t, col = top || (z > 0.55 * r.height && z < 0.8 * r.height) ? r.marker : s.black;
  }
  for (const SceneGoal& g : s.goals) {
    const Eigen::Vector2d f(std::cos(g.theta), std::sin(g.theta)), l(-f.y(), f.x());
    const Eigen::Vector2d pl = g.mouth + 0.5 * g.width * l, pr = g.mouth - 0.5 * g.width * l;
    for (const Seg2& w : {Seg2{pl, pl + g.depth * f}, Seg2{pl + g.depth * f, pr + g.depth * f}, Seg2{pr + g.depth * f, pr}}) {
      const double t = hit_wall(o, d, w, g.height);
      if (t < best) best = t, col = g.color;
    }
    for (const Eigen::Vector2d& p : {pl, pr}) {
      const double t = hit_cylinder(o, d, p, 0.06, g.height);
      if (t < best) best = t, col = g.color;
    }
  }
  return col;
}

/// The image seen by `cam` from a viewpoint at (x, y) with heading yaw.
inline cv::Mat render(const mrt::common::OmniCamera& cam, const Scene& s, double x, double y, double yaw,
                      unsigned seed = 1) {
  cv::Mat img(cam.height_px, cam.width, CV_8UC3, cv::Scalar(0, 0, 0));
  const double r_body = cam.profile.radius(std::atan2(s.body_radius, cam.height));
  const Eigen::Vector3d o(x, y, cam.height);
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, s.noise);
  for (int v = 0; v < cam.height_px; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      Eigen::Vector3d d;
      if (!cam.ray(u, v, d)) continue;
      cv::Vec3b c = std::hypot(u - cam.cx, v - cam.cy) < r_body ? s.black : trace(s, o, rot * d);
      c = shade(c, s.illumination);
      if (s.noise > 0)
        for (int k = 0; k < 3; ++k) c[k] = cv::saturate_cast<uchar>(c[k] + n(rng));
      img.at<cv::Vec3b>(v, u) = c;
    }
  }
  return img;
}

}  // namespace mrt::recvision::testing
