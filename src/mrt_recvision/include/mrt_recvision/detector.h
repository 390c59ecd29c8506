// Processing sub-module of RecVision (ROS-free): one frame in, percepts
// out. Colours are looked up in the calibration's table; field-line points
// come from green-white-green transitions on the radial and circular scan
// lines; goals, their posts and robots from colour runs along the radial
// lines; the ball from a connected component of orange (found on a
// half-resolution class image, then measured at full resolution).
// Positions are in base_link: the viewpoint frame moved by the mount.
#pragma once

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_common/percept.h"
#include "mrt_recvision/calibration.h"
#include "mrt_recvision/frame.h"
#include "mrt_recvision/objects.h"
#include "mrt_recvision/scan_lines.h"

namespace mrt::recvision {

/// One perceived object, classes and attributes as the simulator's percepts.
struct Detection {
  std::string membership_class;  // "Line", "Ball", "Goal", "GoalPost", "Robot"; objects: their kind's, "Wall"
  ColorClass color = ColorClass::kNone;
  double x = 0, y = 0;            // base_link, m
  double distance = 0, bearing = 0;  // from the base_link origin; rad counter-clockwise from x
  double sigma_distance = 0, sigma_bearing = 0;  // one standard deviation (m, rad)
  double reliability = 1.0;
  double vx = 0, vy = 0;          // floor point in the viewpoint frame (for drawing)
};

/// A detection as an object of the stack's percept type (mrt_common/
/// percept.h): distance, bearing, x and y (base_link; x/y deviation
/// hypot(sigma_distance, distance sigma_bearing)) and the colour's name.
mrt::common::PerceptObject to_percept_object(const Detection& d);

/// Counts of the last frame, for diagnostics and the benchmark.
struct DetectorStats {
  int line_points_found = 0;  // before thinning
  int ball_candidates = 0;
};

/// Display colour (RGB) of a colour class, for the debug image and markers.
cv::Scalar color_rgb(ColorClass c);

class Detector {
 public:
  explicit Detector(const Calibration& cal);

  /// Pose of the viewpoint in base_link (the node takes it from tf).
  void set_mount(double x, double y, double yaw);

  /// True if the frame has the calibrated size; else false and why.
  bool accepts(const Frame& f, std::string& why) const;

  /// Everything seen in the frame; throws std::invalid_argument for a frame
  /// accepts() refuses.
  std::vector<Detection> process(const Frame& f);

  /// `f` with the detections drawn over it (RGB).
  void draw(const Frame& f, const std::vector<Detection>& dets, cv::Mat& out) const;

  const DetectorStats& stats() const { return stats_; }
  const ScanGrid& grid() const { return grid_; }
  const Calibration& calibration() const { return cal_; }
  const ObjectFinder& objects() const { return objects_; }

 private:
  void find_lines(const std::uint8_t* img, std::vector<Detection>& out);
  void find_ball(const Frame& f, std::vector<Detection>& out);
  void find_goals(std::vector<Detection>& out);
  void find_robots(std::vector<Detection>& out);
  void find_objects(std::vector<Detection>& out);
  // Mean ray of the orange pixels in `roi` (solid-angle weighted), their
  // count and their smallest and largest image radius.
  bool ball_direction(const Frame& f, const cv::Rect& roi, Eigen::Vector3d& dir, int& count, double& r_min,
                      double& r_max) const;
  // A detection at floor point (x, y) of the viewpoint frame, with the
  // radial spread of `px` pixels there.
  Detection make(const char* cls, ColorClass c, double x, double y, double px) const;

  Calibration cal_;
  ScanGrid grid_;
  ObjectFinder objects_;
  std::vector<double> m_per_px_, rad_per_px_;  // per cm of floor distance
  double r_inner_ = 0;     // image radius of detector.min_distance (the body's blind zone)
  cv::Mat valid_half_;     // half-resolution mask of the annulus scanned for blobs
  cv::Mat cls_half_, mask_, labels_, stats_cc_, centroids_;
  std::vector<std::vector<std::uint8_t>> radial_cls_;  // classes along each radial line
  std::vector<std::uint8_t> cls_;  // scratch: classes along one circle
  DetectorStats stats_;
};

}  // namespace mrt::recvision
