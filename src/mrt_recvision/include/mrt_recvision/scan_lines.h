// Radial and circular scan lines (ROS-free), precomputed once per camera
// model: each is a list of image pixels with the floor point (viewpoint
// frame, metres) seen at that pixel, so processing a frame only reads the
// pixels and looks their colour up. Radial lines run outwards from the
// robot's body at evenly spaced bearings, one pixel apart; circular lines
// run around the robot at fixed floor distances, one pixel apart. Field
// lines crossing a radial line are found on it; lines running radially are
// found on the circles.
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_common/omni_camera.h"
#include "mrt_recvision/calibration.h"

namespace mrt::recvision {

struct ScanPoint {
  int offset;   // pixel index v * width + u
  float x, y;   // floor point, viewpoint frame (m)
};

struct ScanLine {
  std::vector<ScanPoint> points;
  double bearing = 0.0;   // radial lines: the bearing (rad); circles: 0
  double distance = 0.0;  // circles: the floor distance (m); radial: 0
};

/// A floor point found on a scan line (viewpoint frame).
struct LinePoint {
  float x, y;
};

class ScanGrid {
 public:
  ScanGrid(const mrt::common::OmniCamera& cam, const DetectorOptions& opt);
  const std::vector<ScanLine>& radial() const { return radial_; }
  const std::vector<ScanLine>& circular() const { return circular_; }

 private:
  std::vector<ScanLine> radial_, circular_;
};

/// Field-line points on one scan line whose colour classes are `cls`
/// (one per point): a run of white with green on both sides, at most
/// opt.line_gap unclassified points between them, whose floor width lies
/// in [line_min_width, line_max_width]; the point is the middle of the run.
void find_line_points(const ScanLine& line, const std::uint8_t* cls, const DetectorOptions& opt,
                      std::vector<LinePoint>& out);

}  // namespace mrt::recvision
