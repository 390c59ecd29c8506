// The calibration file of RecVision (ROS-free): the camera model (the
// shared `camera:` block of mrt_common/omni_camera_yaml.h), the colour
// classes, the viewpoint's mount on the robot and the detector's options.
// Format (README.md, "Calibration file"):
//
//   camera: {...}                    # as in the simulator's world files
//   mount: [0.0, 0.0, 0.0]           # viewpoint in base_link: x, y (m), yaw (rad)
//   colors:                          # in order of precedence
//     - {class: white, hsv: [0, 360, 0, 0.2, 0.65, 1]}   # h deg, s, v in [0, 1]
//     - {class: orange, rgb: [200, 255, 60, 170, 0, 60]} # r, g, b min/max
//     - {class: cyan, samples: [[0, 200, 220]]}          # labelled RGB samples
//   lut: table.png                   # optional (recvision_calibrate); relative to this file
//   detector: {...}                  # DetectorOptions, all optional
//   objects: {...}                   # ObjectOptions (optional; the museum's)
//
// Every error is a mrt::common::ParseError naming file:line:column.
#pragma once

#include <string>
#include <vector>

#include "mrt_common/omni_camera.h"
#include "mrt_recvision/color_table.h"

namespace mrt::recvision {

/// What the detector looks for and how far (distances in metres on the floor).
struct DetectorOptions {
  // The MSL finders to run (`find: [lines, ball, goals, robots]`, the default).
  bool find_lines = true, find_ball = true, find_goals = true, find_robots = true;
  int radial_lines = 360;            // radial scan lines, evenly spaced in bearing
  std::vector<double> circles = {0.8, 1.2, 1.6, 2.0, 2.5, 3.0};  // circular scan lines at these distances
  double min_distance = 0.35;        // the robot's own body hides everything closer
  double max_distance = 8.0;         // nothing is reported farther
  double line_max_distance = 4.0;    // field-line points only up to here
  double line_min_width = 0.03;      // a white run between green is a line if its ground
  double line_max_width = 0.25;      //   width lies in [min, max]
  int line_gap = 2;                  // unclassified pixels allowed between green and white
  int max_line_points = 400;         // evenly thinned beyond this
  double ball_radius = 0.11;
  double robot_radius = 0.25;
  int min_ball_pixels = 3;           // connected-component areas, full-resolution pixels
  int min_goal_pixels = 40;
  int min_robot_pixels = 60;
};

/// One kind of object the object finder reports: an upright cylinder
/// standing on the floor, of one of `colors`, whose apparent width
/// (2 D sin(half the angle it covers), D its centre's distance) lies in
/// [min_width, max_width].
struct ObjectKind {
  std::string membership_class;  // "Landmark", "Person", "Exhibit", ...
  std::vector<ColorClass> colors;
  double radius = 0.0;           // m; 0: measured from the apparent width
  double min_width = 0.0, max_width = 1e9;  // m
};

/// The object finder (calibration `objects:`, ObjectFinder in objects.h):
/// along each radial line the first run that is not floor is the foot of
/// the nearest object standing there.
struct ObjectOptions {
  bool enabled = false;            // the calibration has an `objects:` block
  std::vector<ColorClass> floor;   // classes of the floor
  double max_jump = 0.3;           // m: neighbouring lines' feet farther apart are different objects
  int min_pixels = 2;              // shorter runs (off the floor) are noise
  std::vector<ObjectKind> kinds;
  ColorClass wall = ColorClass::kNone;  // class of the walls; kNone: no Wall points
  int wall_step = 5;               // one Wall point every wall_step radial lines
  double wall_max_distance = 5.0;  // m
};

struct Calibration {
  std::string file;
  mrt::common::OmniCamera camera;
  ColorTable colors;
  double mount_x = 0.0, mount_y = 0.0, mount_yaw = 0.0;
  DetectorOptions detector;
  ObjectOptions objects;
};

Calibration load_calibration(const std::string& path);

/// The detector's thresholds recvision_node's dynamic_reconfigure tunes;
/// pixels at the calibrated camera's resolution (scale_calibration scales
/// them with the image, as the file's).
struct DetectorTuning {
  double min_distance = 0.35, max_distance = 8.0, line_max_distance = 4.0;  // m
  int min_ball_pixels = 3, min_goal_pixels = 40, min_robot_pixels = 60;
};
DetectorTuning tuning_of(const DetectorOptions& o);
/// `o` with the thresholds of `t`, checked as the file's keys are
/// (distances finite, min_distance >= 0, max_distance > min_distance,
/// line_max_distance > 0, pixel counts >= 1): throws std::invalid_argument
/// naming the first bad key.
DetectorOptions retuned(const DetectorOptions& o, const DetectorTuning& t);

/// The calibration for images scaled by `scale` (the node's ~scale): the
/// camera as OmniCamera::scaled, and the detector's thresholds in pixels scaled
/// with the image: areas (min_ball_pixels) by s^2, counts along scan lines
/// (min_goal_pixels, min_robot_pixels, line_gap, objects.min_pixels) by s,
/// each rounded and at least 1 (line_gap at least 0). Distances in metres
/// and the colour table are unchanged. scale 1 returns `cal` unchanged.
Calibration scale_calibration(const Calibration& cal, double scale);
/// Same from YAML text; `file` names it in errors and anchors a relative `lut:`.
Calibration parse_calibration(const std::string& yaml_text, const std::string& file);

}  // namespace mrt::recvision
