#include "camera_interface.h"

#include <chrono>

#include <boost/make_shared.hpp>
#include <sensor_msgs/image_encodings.h>

namespace mrt::sim::node {

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
  if (!r.camera_ready) return;
  // camera_info is cheap: it goes out whenever a frame is due; the image
  // is rendered only while someone subscribes to it.
  if (info_pub_.getNumSubscribers() > 0) info_pub_.publish(mrt::ros_common::to_camera_info(renderer_.camera(), frame_, stamp));
  if (image_pub_.getNumSubscribers() == 0) return;
  // Render straight into the message's buffer (no copy through cv_bridge).
  const mrt::common::OmniCamera& cam = renderer_.camera();
  sensor_msgs::ImagePtr msg = boost::make_shared<sensor_msgs::Image>();
  msg->header.stamp = stamp;
  msg->header.frame_id = frame_;
  msg->encoding = sensor_msgs::image_encodings::RGB8;
  msg->width = static_cast<std::uint32_t>(cam.width);
  msg->height = static_cast<std::uint32_t>(cam.height_px);
  msg->step = msg->width * 3;
  msg->data.resize(std::size_t(msg->step) * msg->height);
  cv::Mat image(cam.height_px, cam.width, CV_8UC3, msg->data.data());
  const auto t0 = std::chrono::steady_clock::now();
  renderer_.render(r.pose, sim_.other_robots(index_), sim_.time(), image, r.twist);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  render_ms_ = frames_ == 0 ? ms : 0.9 * render_ms_ + 0.1 * ms;
  ++frames_;
  image_pub_.publish(msg);
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
