// Upright coloured objects standing on the floor (ROS-free): FollowMe's
// museum landmarks, visitors and exhibits, and points at the foot of the
// walls. Configured by the calibration's `objects:` block (ObjectOptions).
//
// The camera looks from below the objects' tops (a 0.7 m viewpoint, the
// mirror seeing only below the horizon; the museum's posts are 1 m, people
// 1.7 m, walls 1 m tall), so along each radial scan line the first run
// that is not floor is the nearest object on that bearing and its first
// pixel is the object's foot: the floor point half-way between the last
// floor pixel and the first object pixel is where the object stands.
// Neighbouring lines whose feet have the same colour and lie close
// together make one object; the bearings it covers give its centre's
// bearing (their middle) and its apparent width; its kind (calibration
// `kinds`) comes from its colour and width; its centre's distance D from
// the feet and the kind's radius R: a line at angle delta from the centre
// meets the circle at t = D cos(delta) - sqrt(R^2 - D^2 sin^2(delta)), so
// D = t cos(delta) + sqrt(R^2 - t^2 sin^2(delta)), averaged over the
// central lines. An object partly hidden by a nearer one on one side is
// placed from its free edge (centre asin(R / D) inside it); hidden on both
// sides, it is not reported.
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_recvision/calibration.h"
#include "mrt_recvision/scan_lines.h"

namespace mrt::recvision {

/// An object found: its kind, colour and centre (viewpoint frame).
struct FoundObject {
  int kind = 0;               // index into ObjectOptions::kinds
  ColorClass color = ColorClass::kNone;
  double x = 0, y = 0;        // centre, m
  double radius = 0;          // m (the kind's, or measured)
  int lines = 0, pixels = 0;  // radial lines covered, object pixels on them
  bool occluded = false;      // one side hidden by a nearer object
};

/// The first object on one radial line.
struct FirstRun {
  bool hit = false;       // an object's foot was seen
  bool blocked = false;   // the line starts on an object (nothing of the floor seen)
  ColorClass color = ColorClass::kNone;
  int length = 0;         // object pixels from the foot outwards
  float x = 0, y = 0;     // foot point (viewpoint frame)
  double t = 0;           // its distance
};

class ObjectFinder {
 public:
  explicit ObjectFinder(const ObjectOptions& options);

  /// Objects and wall foot points from the colour classes along each radial
  /// line of `grid` (`cls[i][k]`: class of point k of radial line i).
  void find(const ScanGrid& grid, const std::vector<std::vector<std::uint8_t>>& cls,
            std::vector<FoundObject>& objects, std::vector<LinePoint>& walls);

  const ObjectOptions& options() const { return o_; }

  /// The first runs of the last find(), one per radial line.
  const std::vector<FirstRun>& runs() const { return runs_; }

 private:
  FirstRun first_run(const ScanLine& line, const std::vector<std::uint8_t>& cls) const;
  // Lines [first, first + n) (cyclic) as one object, if it is one.
  void measure(int first, int n, std::vector<FoundObject>& out) const;
  double centre_distance(int first, int n, double bearing, double radius) const;

  ObjectOptions o_;
  std::vector<bool> is_floor_;
  std::vector<FirstRun> runs_;
};

}  // namespace mrt::recvision
