#include "camera_interface.h"

#include <chrono>

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>

namespace mrt::sim::node {

sensor_msgs::CameraInfo to_camera_info(const mrt::common::OmniCamera& c, const std::string& frame,
                                       const ros::Time& stamp) {
  sensor_msgs::CameraInfo info;
  info.header.stamp = stamp;
  info.header.frame_id = frame;
  info.width = static_cast<std::uint32_t>(c.width);
  info.height = static_cast<std::uint32_t>(c.height_px);
  info.distortion_model = "omni_mirror";
  info.K = {1.0, 0.0, c.cx, 0.0, 1.0, c.cy, 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {1.0, 0.0, c.cx, 0.0, 0.0, 1.0, c.cy, 0.0, 0.0, 0.0, 1.0, 0.0};
  return info;
}

CameraInterface::CameraInterface(ros::NodeHandle& rnh, const Simulator& sim, std::size_t index,
                                 const std::string& frame_prefix)
    : sim_(sim),
      index_(index),
      frame_(frame_prefix + "omni_mirror"),
      renderer_(sim.world(), sim.robots()[index].config.sensors.camera.model,
                camera_options(sim.robots()[index].config, sim.world().seed * 1000003 + index)),
      it_(rnh) {
  image_pub_ = it_.advertise("camera/image_raw", 2);
  info_pub_ = rnh.advertise<sensor_msgs::CameraInfo>("camera/camera_info", 2);
}

void CameraInterface::publish(const ros::Time& stamp) {
  const RobotState& r = sim_.robots()[index_];
  if (!r.camera_ready || (image_pub_.getNumSubscribers() == 0 && info_pub_.getNumSubscribers() == 0)) return;
  const auto t0 = std::chrono::steady_clock::now();
  renderer_.render(r.pose, sim_.other_robots(index_), sim_.time(), image_, r.twist);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  render_ms_ = frames_ == 0 ? ms : 0.9 * render_ms_ + 0.1 * ms;
  ++frames_;
  std_msgs::Header h;
  h.stamp = stamp;
  h.frame_id = frame_;
  image_pub_.publish(cv_bridge::CvImage(h, sensor_msgs::image_encodings::RGB8, image_).toImageMsg());
  info_pub_.publish(to_camera_info(renderer_.camera(), frame_, stamp));
}

geometry_msgs::TransformStamped CameraInterface::mount_transform(const std::string& parent) const {
  const CameraOptions& o = renderer_.options();
  geometry_msgs::TransformStamped t;
  t.header.frame_id = parent;
  t.child_frame_id = frame_;
  t.transform.translation.x = o.mount_x;
  t.transform.translation.y = o.mount_y;
  t.transform.translation.z = renderer_.camera().height;
  t.transform.rotation.w = 1.0;
  return t;
}

}  // namespace mrt::sim::node
