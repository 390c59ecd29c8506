// The rendered omnidirectional camera of one simulated robot on ROS:
// camera/image_raw (rgb8, image_transport) and camera/camera_info in
// /<robot>/, frame <robot>/omni_mirror (the mirror's viewpoint).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <geometry_msgs/TransformStamped.h>
#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>

#include "mrt_sim/camera.h"
#include "mrt_sim/simulator.h"

namespace mrt::sim::node {

/// distortion_model of the omnidirectional camera's camera_info: not a
/// pinhole model (image_geometry and image_proc treat it as unknown and
/// refuse to rectify), so nothing misreads it as plumb_bob.
inline const char* const kOmniProfileModel = "mrt_omni_profile";

/// camera_info of an omnidirectional camera (README "CameraInfo of the
/// omnidirectional camera"): width, height; K = [0, 0, cx; 0, 0, cy; 0, 0, 1]
/// (the mirror centre; fx = fy = 0, no pinhole focal length exists), R the
/// identity, P = [K | 0]; distortion_model kOmniProfileModel with
/// D = [roll, pitch, theta_0, r_0, theta_1, r_1, ...]: the mirror axis tilt
/// (rad) and the radial profile's samples (angle from the downward vertical
/// rad, image radius px) exactly as OmniCamera holds them. The viewpoint's
/// height is the omni_mirror frame's in tf.
sensor_msgs::CameraInfo to_camera_info(const mrt::common::OmniCamera& c, const std::string& frame,
                                       const ros::Time& stamp);

class CameraInterface {
 public:
  /// `rnh` is the robot's namespace; `frame_prefix` "<prefix><robot>/".
  CameraInterface(ros::NodeHandle& rnh, const Simulator& sim, std::size_t index, const std::string& frame_prefix);

  /// After a step, when a frame is due: publishes camera_info if someone
  /// listens to it, renders and publishes the image if someone listens to
  /// that (nothing is rendered for camera_info alone).
  void publish(const ros::Time& stamp);

  /// <sensor_parent> -> <robot>/omni_mirror at the viewpoint mount.
  geometry_msgs::TransformStamped mount_transform(const std::string& parent) const;

  const std::string& frame() const { return frame_; }
  std::uint64_t frames() const { return frames_; }
  double render_ms() const { return render_ms_; }

 private:
  const Simulator& sim_;
  std::size_t index_;
  std::string frame_;
  mrt::sim::CameraRenderer renderer_;
  image_transport::ImageTransport it_;
  image_transport::Publisher image_pub_;
  ros::Publisher info_pub_;
  std::uint64_t frames_ = 0;
  double render_ms_ = 0.0;  // exponential average of the render time
};

}  // namespace mrt::sim::node
