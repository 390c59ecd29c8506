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

#include "mrt_common_ros/omni_camera_info.h"
#include "mrt_sim/camera.h"
#include "mrt_sim/simulator.h"

namespace mrt::sim::node {

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
