// The simulated world: the static world (mrt_world: walls, lines, posts,
// goals, doors, regions) plus what moves and senses: the ball, movers,
// robots with their sensors, floor patches for the mice; loaded from one
// YAML file (ROS-free).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mrt_common/omni_camera.h"
#include "mrt_common/pose2d.h"
#include "mrt_sim/kinematics.h"
#include "mrt_world/world.h"

namespace mrt::sim {

using mrt::common::Point2D;
using mrt::common::Pose2D;
using mrt::world::Goal;
using mrt::world::Post;
using mrt::world::Segment;
using mrt::world::distance_to_segment;
using mrt::world::goal_posts;
using mrt::world::goal_walls;
using mrt::world::solid_segments;

/// The ball: a cylinder rolling with constant deceleration `friction`
/// (m/s^2) until it stops; pushed by robots and bounced by walls with
/// restitution `restitution`.
struct Ball {
  std::string name = "ball";
  Point2D position;
  Point2D velocity;
  double radius = 0.11;
  double friction = 0.4;
  double restitution = 0.6;
  double robot_restitution = 0.0;  // against robots and movers (0: pushed, no bounce)
  std::string color = "orange";
  bool enabled = false;
};

/// A walking person or a scripted robot: a cylinder moving along waypoints
/// at constant speed (looping if `loop`, else stopping at the last one).
struct Mover {
  std::string name;
  std::string membership_class;  // "Person" or "Robot"
  std::string color;
  double radius = 0.25;
  double speed = 0.8;
  bool loop = true;
  std::vector<Point2D> waypoints;
  // state
  Point2D position;     // starts at waypoints[0]
  Point2D velocity;     // m/s, during the last step
  std::size_t next = 1; // index of the waypoint being walked to
  bool done = false;    // reached the last waypoint of an open path
};

/// A patch of floor with its own effect on the optical mice (world file
/// `surfaces`): an axis-aligned rectangle; where patches overlap, the last
/// one listed wins. Elsewhere the floor has resolution 1, clearance 0.
struct Surface {
  std::string name;
  double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;  // m, world frame
  double resolution = 1.0;  // factor on a mouse's counts_per_m over it (carpet < 1)
  double clearance = 0.0;   // m added to a mouse's height above the floor (> 0: a dip, or
                            // the body lifted by a wheel on a bump; < 0: a bump under the mouse)
};

/// The physical mouse model (world file `sensors.mice.model: physical`,
/// mouse_model.h); off, a mouse is the ideal model (the estimator's inverse).
struct MousePhysics {
  bool enabled = false;
  double height = 0.0;        // m above the sensor's focus on a flat floor
  double liftoff = 0.002;     // m: higher than this above focus the sensor sees nothing
  double height_gain = 10.0;  // 1/m: counts scale by 1 - height_gain * height (magnification)
  double max_speed = 1.0;     // m/s: faster, the sensor loses track (that step's counts lost)
  double max_accel = 15.0;    // g: harder, the same
  double report_rate = 125.0; // Hz: reports on the mouse's own clock (USB polling)
  double phase = 0.0;         // s: first report, on that clock
  double drift_ppm = 0.0;     // that clock's rate error (+ runs fast)
};

struct MouseConfig {
  std::string id;             // "left", "right"
  Pose2D mount;               // pose of the mouse frame in base_link
  double counts_per_m = 15748.0;  // 400 cpi
  double noise = 0.0;         // std-dev of a multiplicative length noise per step
  double fault_rate = 0.0;    // probability per step of losing contact (manual §4.2)
  double fault_max_fraction = 0.5;  // a fault loses up to this fraction of the step's length
  MousePhysics physics;
};

struct SonarConfig {
  Pose2D mount;               // in base_link, x along the beam axis
  double fov = 0.4;           // full cone angle, rad
  double min_range = 0.1;     // m
  double max_range = 5.0;     // m
};

/// Image effects of the rendered camera (world file `sensors.camera_render`).
/// Every effect is off at 0.
struct CameraEffects {
  double noise = 0.0;                  // std-dev of additive pixel noise, 8-bit levels
  double illumination = 0.0;           // relative brightness variation over the field (+-)
  double illumination_scale = 6.0;     // m, wavelength of that variation
  double flicker = 0.0;                // relative brightness variation in time (+-)
  double flicker_period = 10.0;        // s
  double exposure = 0.0;               // s; motion during it blurs the image (blur at speed)
  double white_balance_drift = 0.0;    // relative per-channel gain drift (+-)
  double white_balance_period = 30.0;  // s
};

/// The rendered omnidirectional camera of a robot (world file
/// `sensors.camera`, the mrt_common/omni_camera_yaml.h block, plus
/// `sensors.camera_render`). The viewpoint is at (mount_x, mount_y,
/// model.height) in base_link, read from the robot's URDF (link
/// omni_mirror) when mrt_description has one.
struct CameraConfig {
  double rate = 0.0;                   // Hz, 0 = off
  mrt::common::OmniCamera model;
  double mount_x = 0.0, mount_y = 0.0; // m, viewpoint in base_link
  CameraEffects effects;
};

struct SensorsConfig {
  double rate_mice = 50.0;      // Hz, 0 = off
  std::vector<MouseConfig> mice;
  double rate_encoders = 50.0;  // Hz, 0 = off
  int ticks_per_rev = 2000;     // encoder ticks per wheel revolution
  double encoder_noise = 0.0;   // relative std-dev of each step's wheel-angle increment
  double rate_sonar = 10.0;     // Hz, 0 = off
  std::vector<SonarConfig> sonars;
  double sonar_noise = 0.01;    // m, std-dev
  double rate_vision = 10.0;    // Hz, 0 = off
  double vision_range = 6.0;    // m
  double vision_distance_noise = 0.02;  // relative: sigma = noise * distance
  double vision_bearing_noise = 0.01;   // rad
  double line_point_spacing = 0.25;     // m between sampled field-line points
  bool vision_realistic = false;        // `model: realistic` (see realistic_percepts)
  double vision_miss_near = 0.02;       // probability of missing an object at distance 0 ...
  double vision_miss_far = 0.3;         // ... and at `range` (linear in between)
  double vision_false_positives = 0.2;  // mean false objects per frame (Poisson)
  double rate_dgps = 0.0;       // Hz, 0 = off
  double dgps_noise = 0.05;     // m, std-dev per axis
  double datum_latitude = 45.478;   // deg, world origin (for NavSatFix)
  double datum_longitude = 9.227;   // deg
  CameraConfig camera;          // rate 0 = no camera
};

struct RobotConfig {
  std::string name;           // namespace and frame prefix
  std::string color = "black";  // seen by the other robots' vision
  BaseConfig base;
  Pose2D initial_pose;
  SensorsConfig sensors;
};

/// The static world and what the simulation adds to it.
struct World : mrt::world::World {
  std::string floor_color = "carpet";   // the camera's floor: "carpet" (green) or a colour name
  Ball ball;
  std::vector<Mover> movers;
  std::vector<RobotConfig> robots;
  std::vector<Surface> surfaces;       // floor patches seen by the physical mice
  std::uint64_t seed = 1;
};

/// Directory of mrt_description's URDF files built into mrt_sim_core (see
/// description.h).
std::string default_description_dir();

/// Loads a world file: its static sections (mrt_world's loader) and the
/// simulation's. Throws mrt::common::ParseError naming the file, the line
/// (and column) of the offending node and what was expected. The format is
/// documented in mrt_world/README.md and mrt_sim/README.md. Sensor mounts (camera
/// viewpoint, mice) come from `<description_dir>/<base>.urdf` when that
/// file exists and has the link ("" = no URDF).
World load_world(const std::string& path, const std::string& description_dir = default_description_dir());

/// Same, from YAML text; `file` is used in error messages.
World parse_world(const std::string& yaml_text, const std::string& file,
                  const std::string& description_dir = default_description_dir());

}  // namespace mrt::sim
