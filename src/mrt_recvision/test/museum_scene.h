// Ground truth for RecVision in FollowMe's museum (test and benchmark
// support, header-only): every landmark, person and exhibit of the world
// relative to the robot, whether the camera sees all of it, and the match
// of detections against it.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mrt_common/omni_camera.h"
#include "mrt_recvision/detector.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

namespace mrt::recvision::museum {

constexpr double kBearingBound = 2.0 * M_PI / 180.0;  // rad

struct Truth {
  std::string name, cls, color;
  double distance = 0, bearing = 0, radius = 0;  // centre, from the robot; rad in (-pi, pi]
  bool full = false;  // all of its width in sight, its foot beyond the body, within 8.5 m
};

// A ray from the robot at `angle` (world) reaches at least `t` (nothing nearer in the way).
inline bool clear(const mrt::sim::World& w, const mrt::sim::Pose2D& r, double angle, double t) {
  const auto hit = mrt::sim::ray_cast(w, {}, {r.x, r.y}, angle, t + 1.0);
  return !hit || *hit >= t - 0.01;
}

inline Truth make_truth(const mrt::sim::World& w, const mrt::sim::Pose2D& r, const std::string& name,
                        const std::string& cls, const std::string& color, mrt::sim::Point2D c, double radius,
                        double min_distance) {
  Truth t{name, cls, color};
  t.radius = radius;
  const double dx = c.x - r.x, dy = c.y - r.y;
  t.distance = std::hypot(dx, dy);
  const double world_bearing = std::atan2(dy, dx);
  t.bearing = std::remainder(world_bearing - r.theta, 2.0 * M_PI);
  if (t.distance - radius < min_distance + 0.05 || t.distance > 8.5) return t;
  // The centre ray and two rays just inside the tangents reach the object,
  // and two rays outside them by one scan line (1 degree) and the zigzag of
  // the lines' pixels (0.3 degree: half a pixel 100 px from the centre)
  // reach as far as its foot: objects closer together in bearing read as one
  // hiding the other (doc/method.md, "Museum").
  const double a = std::asin(std::min(1.0, radius / t.distance)), line = 1.3 * M_PI / 180.0;
  t.full = true;
  for (double off : {-0.95 * a, 0.0, 0.95 * a}) {
    const double s = t.distance * std::sin(off);
    const double reach = t.distance * std::cos(off) - std::sqrt(std::max(0.0, radius * radius - s * s));
    t.full = t.full && clear(w, r, world_bearing + off, reach);
  }
  for (double off : {-a - line, a + line}) t.full = t.full && clear(w, r, world_bearing + off, t.distance - radius);
  return t;
}

/// Every Landmark and Exhibit post and every Person of the world, seen from `robot`.
inline std::vector<Truth> truth(const mrt::sim::World& w, const mrt::sim::Pose2D& robot, double min_distance) {
  std::vector<Truth> out;
  for (const auto& p : w.posts)
    if (p.membership_class == "Landmark" || p.membership_class == "Exhibit")
      out.push_back(make_truth(w, robot, p.name, p.membership_class, p.color, p.center, p.radius, min_distance));
  for (const auto& m : w.movers)
    if (m.membership_class == "Person")
      out.push_back(make_truth(w, robot, m.name, "Person", m.color, m.position, m.radius, min_distance));
  return out;
}

/// The distance bound: 3 cm (the radius model and the feet's averaging)
/// plus one pixel of image radius at that distance (the foot lies between
/// two pixels of a radial line, and the mirror's pixels grow with distance:
/// 2 cm up to 3 m, 6.6 cm at 5 m, 16.5 cm at 8 m).
inline double distance_bound(const mrt::common::OmniCamera& cam, double d) {
  const double th = std::atan2(d, cam.height);
  const double r = cam.profile.radius(th);
  const double th2 = cam.profile.theta(r + 1.0);
  const double px = std::isfinite(th2) && th2 < M_PI / 2 ? cam.height * std::tan(th2) - d : 1.0;
  return 0.03 + px;
}

struct Tally {
  int required = 0, found = 0, reported = 0, false_positives = 0;
  std::vector<double> distance_error, relative_error, bearing_error;  // of the required objects found
  std::vector<std::string> missed, spurious;
};

inline bool matches(const Detection& d, const Truth& t, const mrt::common::OmniCamera& cam) {
  return d.membership_class == t.cls && color_name(d.color) == t.color &&
         std::abs(d.distance - t.distance) <= distance_bound(cam, t.distance) &&
         std::abs(std::remainder(d.bearing - t.bearing, 2.0 * M_PI)) <= kBearingBound;
}

/// Adds one frame's detections of class `cls` to `tally`: each fully seen
/// object of that class must be matched, and each detection must match an
/// object of the world.
inline void evaluate(const std::vector<Detection>& dets, const std::vector<Truth>& truth, const std::string& cls,
                     const mrt::common::OmniCamera& cam, Tally& tally) {
  for (const Truth& t : truth) {
    if (t.cls != cls || !t.full) continue;
    ++tally.required;
    const Detection* best = nullptr;
    for (const Detection& d : dets)
      if (matches(d, t, cam) && (!best || std::abs(d.distance - t.distance) < std::abs(best->distance - t.distance)))
        best = &d;
    if (!best) {
      tally.missed.push_back(t.name);
      continue;
    }
    ++tally.found;
    tally.distance_error.push_back(std::abs(best->distance - t.distance));
    tally.relative_error.push_back(std::abs(best->distance - t.distance) / t.distance);
    tally.bearing_error.push_back(std::abs(std::remainder(best->bearing - t.bearing, 2.0 * M_PI)));
  }
  for (const Detection& d : dets) {
    if (d.membership_class != cls) continue;
    ++tally.reported;
    const bool real = std::any_of(truth.begin(), truth.end(), [&](const Truth& t) { return matches(d, t, cam); });
    if (!real) {
      ++tally.false_positives;
      tally.spurious.push_back(std::string(color_name(d.color)) + " at " + std::to_string(d.distance) + " m, " +
                               std::to_string(d.bearing * 180.0 / M_PI) + " deg");
    }
  }
}

inline double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

}  // namespace mrt::recvision::museum
