// The rendered omnidirectional camera (ROS-free): what a robot's
// catadioptric camera (mrt_common/omni_camera.h) sees of the simulated
// world, as an RGB image in the image convention of omni_camera.h (robot
// forward up, left left).
//
// Rendering is a per-pixel ray cast with a depth buffer: the rays of every
// pixel are computed once (in base_link), the floor (carpet and field lines
// at their true width) is pre-rendered once into a texture, and each frame
// transforms the floor points by the robot pose, then draws every object
// (walls, goals, posts, ball, movers, other robots) only inside its image
// bounding box, keeping the nearest hit; the robot's own body (a black disc
// of its radius) covers the centre.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "mrt_common/omni_camera.h"
#include "mrt_sim/kinematics.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

namespace mrt::sim {

namespace detail {
struct CameraShape;  // one object to draw (src/camera.cpp)
}  // namespace detail

/// RGB of a symbolic colour of the world file (`orange`, `yellow`, `blue`,
/// `cyan`, `magenta`, `red`, `green`, `white`, `black`, `grey`/`gray`,
/// `brown`, `purple`, `pink`, `beige`, `bronze`); `fallback` for "" or an
/// unknown name.
cv::Vec3b color_rgb(const std::string& name, cv::Vec3b fallback = cv::Vec3b(128, 128, 128));

/// The colours and sizes the renderer draws with (RGB). The defaults are
/// those mrt_recvision's default calibration expects.
struct CameraOptions {
  double mount_x = 0.0, mount_y = 0.0;  // m, viewpoint in base_link (height: OmniCamera::height)
  double own_body_radius = 0.25;        // m, the robot's own body (black disc at the centre)
  double own_body_height = 0.4;         // m, its top (kept below the viewpoint)
  CameraEffects effects;
  std::uint64_t seed = 1;               // of the pixel noise

  double texture_resolution = 0.01;     // m per texel of the pre-rendered floor
  double wall_height = 1.0;             // m
  double goal_height = 1.0;             // m, goal walls and posts
  double goal_post_radius = 0.0625;     // m (MSL posts are 12.5 cm thick)
  double post_height = 1.0;             // m, landmarks, obstacles and other posts
  double robot_height = 0.6;            // m, other robots (black body)
  double marker_band = 0.15;            // m, coloured band around the top of a robot's side
  double person_height = 1.7;           // m, movers of class Person

  cv::Vec3b carpet{30, 140, 40};        // green
  cv::Vec3b line{255, 255, 255};        // white
  cv::Vec3b outside{90, 90, 90};        // floor outside the world's bounds
  cv::Vec3b wall{110, 110, 110};
  cv::Vec3b sky{70, 70, 80};            // above the walls
  cv::Vec3b robot_body{0, 0, 0};        // black
  double shadow = 0.45;                 // brightness under the ball (1 = no shadow)
};

/// The options of a robot's camera from its world-file configuration
/// (mount, effects, body radius, seed).
CameraOptions camera_options(const RobotConfig& robot, std::uint64_t seed);

/// Renders frames of one camera. Keeps a reference to `world`: its movers
/// and ball are read at each render (pass Simulator::world(), which must
/// outlive the renderer); its static geometry is pre-rendered at
/// construction.
class CameraRenderer {
 public:
  CameraRenderer(const World& world, const mrt::common::OmniCamera& camera, const CameraOptions& options = {});

  const mrt::common::OmniCamera& camera() const { return camera_; }
  const CameraOptions& options() const { return options_; }

  /// Renders the view from `robot` (pose of base_link in the world) at
  /// sim time `time` (s; drives flicker and white-balance drift) into `rgb`
  /// (CV_8UC3, RGB order, camera width x height). `others` are the other
  /// robots (black bodies with a marker in their colour); `velocity` the
  /// robot's body twist (blur at speed when effects.exposure > 0).
  void render(const Pose2D& robot, const std::vector<OtherRobot>& others, double time, cv::Mat& rgb,
              const Twist2D& velocity = Twist2D());

 private:
  void build_rays();
  void build_floor();
  void draw_floor(const Pose2D& robot, cv::Mat& rgb);
  void draw_shadow(const Pose2D& robot, cv::Mat& rgb);
  void draw_objects(const Pose2D& robot, const std::vector<OtherRobot>& others, cv::Mat& rgb);
  void draw_shape(const Pose2D& robot, const detail::CameraShape& shape, cv::Mat& rgb);
  void apply_effects(double time, const Twist2D& velocity, cv::Mat& rgb);
  double illumination(double x, double y) const;

  const World& world_;
  mrt::common::OmniCamera camera_;
  CameraOptions options_;
  // per pixel (row-major), in base_link: unit ray and floor point
  std::vector<float> dx_, dy_, dz_, dxy_, gx_, gy_, tfloor_;  // dxy_: horizontal part of the ray
  std::vector<std::uint8_t> kind_;       // 0 outside the mirror, 1 own body, 2 floor, 3 above the horizon
  std::vector<float> depth_;             // per frame: ray length to the nearest hit
  cv::Mat floor_;                        // CV_8UC3 RGB, texture of the floor
  double floor_x0_ = 0.0, floor_y0_ = 0.0;
  cv::Mat noise_pos_, noise_neg_;        // CV_8UC1 pool of pixel noise: positive and negative parts
  std::mt19937_64 rng_;
};

}  // namespace mrt::sim
