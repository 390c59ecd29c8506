// recvision_node: camera images in, percepts and a debug image out.
// Thin ROS layer over the core (mrt_recvision/detector.h): parameters are
// read once into the calibration, each sensor_msgs/Image becomes a Frame
// through cv_bridge (image_decode.h), camera/camera_info is checked against
// the calibration (camera_info_check.h), and each Detection becomes a
// percept object of the ontology (to_percept_object).
// The viewpoint's mount is taken from tf (base_frame <- the image's
// frame_id), falling back to the calibration file's `mount:`.
// With ~device set, the driver sub-module reads a V4L2 camera (or a video
// file) itself and publishes its frames on camera/image_raw.
// Topics, parameters and diagnostics: README.md. dynamic_reconfigure
// (cfg/RecVision.cfg): the detector's thresholds (a new detector, the mount
// kept); one mutex serializes every callback with the reconfiguration.
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <image_transport/image_transport.h>
#include <mrt_msgs/Percept.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_common_ros/percept_conversions.h"
#include "mrt_recvision/RecVisionConfig.h"
#include "mrt_recvision/detector.h"
#include "mrt_recvision/frame.h"
#include "camera_info_check.h"
#include "image_decode.h"

namespace mrt::recvision::node {
namespace {

mrt_msgs::Percept to_percept(const std::vector<Detection>& dets, const std_msgs::Header& image_header,
                             const std::string& frame, const std::string& robot) {
  mrt_msgs::Percept p;
  p.header.stamp = image_header.stamp;
  p.header.frame_id = frame;
  p.sensor = "omnivision";
  p.robot = robot;
  for (const Detection& d : dets) p.objects.push_back(mrt::ros_common::to_msg(to_percept_object(d)));
  return p;
}

// rviz view of the percepts: one marker per detection in base_link, in its colour.
visualization_msgs::MarkerArray to_markers(const std::vector<Detection>& dets, const std_msgs::Header& h,
                                           const std::string& frame) {
  visualization_msgs::MarkerArray arr;
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  arr.markers.push_back(clear);
  visualization_msgs::Marker lines;
  lines.header.stamp = h.stamp;
  lines.header.frame_id = frame;
  lines.ns = "lines";
  lines.type = visualization_msgs::Marker::POINTS;
  lines.scale.x = lines.scale.y = 0.05;
  lines.color.r = lines.color.g = lines.color.b = lines.color.a = 1.0f;
  lines.pose.orientation.w = 1.0;
  int id = 0;
  for (const Detection& d : dets) {
    geometry_msgs::Point p;
    p.x = d.x;
    p.y = d.y;
    if (d.membership_class == "Line") {
      lines.points.push_back(p);
      continue;
    }
    visualization_msgs::Marker m;
    m.header = lines.header;
    m.ns = d.membership_class;
    m.id = id++;
    m.type = d.membership_class == "Ball" ? visualization_msgs::Marker::SPHERE : visualization_msgs::Marker::CYLINDER;
    const double size = d.membership_class == "Ball" ? 0.22 : d.membership_class == "Robot" ? 0.5 : 0.15;
    m.scale.x = m.scale.y = size;
    m.scale.z = d.membership_class == "Ball" ? 0.22 : 0.4;
    m.pose.position = p;
    m.pose.position.z = 0.5 * m.scale.z;
    m.pose.orientation.w = 1.0;
    const cv::Scalar c = color_rgb(d.color);
    m.color.r = float(c[0] / 255.0);
    m.color.g = float(c[1] / 255.0);
    m.color.b = float(c[2] / 255.0);
    m.color.a = 0.8f;
    arr.markers.push_back(m);
  }
  arr.markers.push_back(lines);
  return arr;
}

sensor_msgs::Image to_image(const cv::Mat& rgb, const std_msgs::Header& h) {
  sensor_msgs::Image img;
  img.header = h;
  img.encoding = "rgb8";
  img.width = rgb.cols;
  img.height = rgb.rows;
  img.step = rgb.cols * 3;
  img.data.assign(rgb.data, rgb.data + rgb.total() * 3);
  return img;
}

class RecVisionNode {
 public:
  RecVisionNode(ros::NodeHandle nh, ros::NodeHandle pnh) : it_(nh), tf_listener_(tf_buffer_), updater_(nh, pnh) {
    std::string calib_file;
    mrt::ros_common::ParamReader params(pnh);
    params.require("calib_file", calib_file, "the calibration file (camera, colours, detector)");
    std::string prefix = ros::this_node::getNamespace();
    while (!prefix.empty() && prefix[0] == '/') prefix.erase(0, 1);
    robot_ = prefix;
    if (!prefix.empty()) prefix += "/";
    params.get("frame_prefix", prefix).get("robot", robot_).get("use_tf", use_tf_).get("debug_image", debug_);
    base_frame_ = prefix + "base_link";
    params.get("base_frame", base_frame_);
    // ~scale: the images are the calibrated camera's scaled by this factor
    // (mrt_sim's ~camera_scale): one calibration file, scaled in code.
    params.get_positive("scale", scale_);
    mrt::ros_common::ParamReader::check(scale_ <= 4.0, "scale", "a number in (0, 4]");
    calibration_ = load_calibration(calib_file);  // ParseError -> run_node exits 1
    detector_ = std::make_unique<Detector>(scale_calibration(calibration_, scale_));
    percepts_pub_ = nh.advertise<mrt_msgs::Percept>("percepts", 10);
    if (debug_) debug_pub_ = it_.advertise("camera/debug_image", 1);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("vision_markers", 2);
    std::string device;
    double rate = 30.0;
    params.get("device", device).get_positive("device_rate", rate);
    camera_frame_ = prefix + "omni_mirror";
    params.get("camera_frame", camera_frame_);
    if (device.empty()) {
      image_sub_ = it_.subscribe("camera/image_raw", 2, &RecVisionNode::on_image, this);
      info_sub_ = nh.subscribe("camera/camera_info", 2, &RecVisionNode::on_camera_info, this);
    } else {  // the driver sub-module reads the camera (or a video file) itself
      const auto& cam = detector_->calibration().camera;
      source_ = std::make_unique<CameraSource>(device, cam.width, cam.height_px);  // throws naming the device
      raw_pub_ = it_.advertise("camera/image_raw", 2);
      grab_timer_ = nh.createWallTimer(ros::WallDuration(1.0 / rate), [this](const ros::WallTimerEvent&) { grab(); });
    }
    updater_.setHardwareID("recvision");
    updater_.add("frames", this, &RecVisionNode::diagnose);
    diag_timer_ = nh.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) {
      const std::lock_guard<std::mutex> lock(mutex_);
      updater_.update();
    });
    // the thresholds start from the calibration file
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<mrt_recvision::RecVisionConfig>>(reconfigure_mutex_, pnh);
    reconfigure_->updateConfig(current_config());
    reconfigure_->setCallback([this](mrt_recvision::RecVisionConfig& c, uint32_t) { on_reconfigure(c); });
  }

 private:
  mrt_recvision::RecVisionConfig current_config() const {
    mrt_recvision::RecVisionConfig c = mrt_recvision::RecVisionConfig::__getDefault__();
    const DetectorTuning t = tuning_of(calibration_.detector);
    c.min_distance = t.min_distance;
    c.max_distance = t.max_distance;
    c.line_max_distance = t.line_max_distance;
    c.min_ball_pixels = t.min_ball_pixels;
    c.min_goal_pixels = t.min_goal_pixels;
    c.min_robot_pixels = t.min_robot_pixels;
    return c;
  }

  // New thresholds: a new detector from the (unscaled) calibration with
  // them, scaled by ~scale, at the current mount (tf's or the file's).
  // Refused values are logged and `c` gets the current ones back.
  void on_reconfigure(mrt_recvision::RecVisionConfig& c) {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      Calibration cal = calibration_;
      cal.detector = retuned(cal.detector, {c.min_distance, c.max_distance, c.line_max_distance, c.min_ball_pixels,
                                            c.min_goal_pixels, c.min_robot_pixels});
      auto fresh = std::make_unique<Detector>(scale_calibration(cal, scale_));
      const Calibration& now = detector_->calibration();
      fresh->set_mount(now.mount_x, now.mount_y, now.mount_yaw);
      detector_ = std::move(fresh);
      calibration_ = std::move(cal);
      ROS_INFO("recvision: detector thresholds: %.3f to %.3f m (lines to %.3f m), ball %d, goal %d, robot %d px",
               c.min_distance, c.max_distance, c.line_max_distance, c.min_ball_pixels, c.min_goal_pixels,
               c.min_robot_pixels);
    } catch (const std::exception& e) {
      ROS_WARN("recvision: reconfiguration refused: %s", e.what());
    }
    c = current_config();
  }

  // cv_bridge decodes every encoding it converts to rgb8 (image_decode.h);
  // an rgb8 message is processed in place, read only, without a copy.
  void on_image(const sensor_msgs::ImageConstPtr& msg) {
    const std::lock_guard<std::mutex> lock(mutex_);
    Frame f;
    std::string why;
    bool colourless = false;
    const ros_layer::Decoded d = ros_layer::decode_image(msg, f, colourless, why);
    if (d != ros_layer::Decoded::kOk) {
      ++(d == ros_layer::Decoded::kMalformed ? dropped_malformed_ : dropped_encoding_);
      ROS_WARN_THROTTLE(5.0, "recvision: frame dropped: %s", why.c_str());
      return;
    }
    if (colourless) {
      ++colourless_;
      ROS_WARN_ONCE("recvision: %s images have no colour: only the black and white classes "
                    "match (no ball, goals, markers nor field lines, which need green)", msg->encoding.c_str());
    }
    process(f, msg->header);
  }

  // The camera's description against the calibration (camera_info_check.h).
  void on_camera_info(const sensor_msgs::CameraInfoConstPtr& msg) {
    const std::lock_guard<std::mutex> lock(mutex_);
    using R = ros_layer::CameraInfoCheck::Result;
    info_check_ = ros_layer::check_camera_info(*msg, detector_->calibration().camera);
    ++infos_;
    if (info_check_.result == R::kSizeMismatch || info_check_.result == R::kModelMismatch) {
      ++(info_check_.result == R::kSizeMismatch ? info_size_mismatches_ : info_model_mismatches_);
      ROS_WARN_THROTTLE(5.0, "recvision: camera_info disagrees with the calibration: %s", info_check_.why.c_str());
    }
  }

  // Device mode: one frame from the camera (blocks until it arrives),
  // published raw for recording, then processed like a topic's frame.
  void grab() {
    const std::lock_guard<std::mutex> lock(mutex_);
    // A video file is played once, from when someone listens to the percepts.
    if (source_->is_file() && percepts_pub_.getNumSubscribers() == 0) return;
    Frame f;
    if (!source_->next(f)) {
      ++device_failures_;
      if (source_->is_file()) {
        ROS_INFO("recvision: end of the video");
        grab_timer_.stop();
      } else {
        ROS_WARN_THROTTLE(5.0, "recvision: the camera gave no frame");
      }
      return;
    }
    std_msgs::Header h;
    h.stamp = ros::Time::now();
    h.frame_id = camera_frame_;
    if (raw_pub_.getNumSubscribers() > 0) raw_pub_.publish(to_image(f.rgb, h));
    process(f, h);
  }

  void process(const Frame& f, const std_msgs::Header& header) {
    std::string why;
    if (!detector_->accepts(f, why)) {
      ++dropped_size_;
      ROS_WARN_THROTTLE(5.0, "recvision: frame dropped: %s", why.c_str());
      return;
    }
    update_mount(header.frame_id);
    const auto t0 = std::chrono::steady_clock::now();
    const auto dets = detector_->process(f);
    last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    ++frames_;
    percepts_pub_.publish(to_percept(dets, header, base_frame_, robot_));
    if (debug_ && debug_pub_.getNumSubscribers() > 0) publish_debug(f, dets, header);
    if (markers_pub_.getNumSubscribers() > 0) markers_pub_.publish(to_markers(dets, header, base_frame_));
    updater_.update();
  }

  // The mount is static: looked up until found once.
  void update_mount(const std::string& image_frame) {
    if (!use_tf_ || mount_from_tf_ || image_frame.empty()) return;
    try {
      const auto t = tf_buffer_.lookupTransform(base_frame_, image_frame, ros::Time(0));
      detector_->set_mount(t.transform.translation.x, t.transform.translation.y, mrt::ros_common::quaternion_to_yaw(t.transform.rotation));
      mount_from_tf_ = true;
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "recvision: no tf %s <- %s yet (%s); using the calibration's mount", base_frame_.c_str(),
                        image_frame.c_str(), e.what());
    }
  }

  void publish_debug(const Frame& f, const std::vector<Detection>& dets, const std_msgs::Header& h) {
    cv::Mat out;
    detector_->draw(f, dets, out);
    debug_pub_.publish(to_image(out, h));
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    using R = ros_layer::CameraInfoCheck::Result;
    const bool info_bad = infos_ > 0 && (info_check_.result == R::kSizeMismatch || info_check_.result == R::kModelMismatch);
    if (dropped_encoding_ + dropped_malformed_ + dropped_size_ > 0)
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "frames dropped (wrong size or encoding)");
    else if (info_bad)
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "camera_info disagrees with the calibration");
    else if (frames_ == 0)
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no frame yet");
    else
      s.summary(diagnostic_msgs::DiagnosticStatus::OK, "processing");
    s.add("frames processed", frames_);
    s.add("frames without colour (mono)", colourless_);
    s.add("dropped: wrong encoding", dropped_encoding_);
    s.add("dropped: malformed", dropped_malformed_);
    s.add("dropped: wrong size", dropped_size_);
    s.add("last processing time (ms)", last_ms_);
    s.add("mount from tf", mount_from_tf_);
    if (source_) s.add("device read failures", device_failures_);
    s.add("camera_info received", infos_);
    s.add("camera_info: size mismatches", info_size_mismatches_);
    s.add("camera_info: model mismatches", info_model_mismatches_);
    s.add("camera_info: last check", infos_ == 0 ? std::string("none received")
                                     : info_check_.why.empty() ? std::string("matches") : info_check_.why);
  }

  std::mutex mutex_;  // every callback's: the reconfiguration replaces detector_
  image_transport::ImageTransport it_;
  image_transport::Subscriber image_sub_;
  ros::Subscriber info_sub_;
  ros_layer::CameraInfoCheck info_check_;
  long infos_ = 0, info_size_mismatches_ = 0, info_model_mismatches_ = 0;
  image_transport::Publisher debug_pub_, raw_pub_;
  std::unique_ptr<CameraSource> source_;
  ros::WallTimer grab_timer_;
  std::string camera_frame_;
  ros::Publisher percepts_pub_, markers_pub_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diag_timer_;
  Calibration calibration_;  // as loaded (unscaled), with the reconfigured thresholds
  double scale_ = 1.0;       // ~scale
  std::unique_ptr<Detector> detector_;
  std::string base_frame_, robot_;
  bool use_tf_ = true, debug_ = true, mount_from_tf_ = false;
  long frames_ = 0, colourless_ = 0, dropped_encoding_ = 0, dropped_malformed_ = 0, dropped_size_ = 0;
  long device_failures_ = 0;
  double last_ms_ = 0;
  boost::recursive_mutex reconfigure_mutex_;  // the server's own, held around on_reconfigure
  std::unique_ptr<dynamic_reconfigure::Server<mrt_recvision::RecVisionConfig>> reconfigure_;
};

}  // namespace
}  // namespace mrt::recvision::node

int main(int argc, char** argv) {
  ros::init(argc, argv, "recvision_node");
  return mrt::ros_common::run_node([] {
    mrt::recvision::node::RecVisionNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
    return 0;
  });
}
