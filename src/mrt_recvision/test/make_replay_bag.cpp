// Writes the bag the replay rostest plays (test/replay.test): mrt_sim's
// core drives robot1 of the MSL field on an arc (0.5 m/s, 0.25 rad/s) for
// a few seconds and records, as the simulator node would publish them,
// /robot1/mice (50 Hz), /robot1/camera/image_raw (rendered by mrt_sim's
// CameraRenderer, every third camera frame: 10 Hz) and the ground truth
// /robot1/ground_truth (with every mice sample). The same frames also go to
// OUT.avi (MJPG, 10 fps) with the true ball distance and bearing of each
// frame in OUT_ball.csv, for the device (video file) rostest.
// Usage: make_replay_bag WORLD.yaml OUT (writes OUT.bag, OUT.avi, OUT_ball.csv)
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/Image.h>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include "mrt_common_ros/conversions.h"
#include "mrt_msgs/MiceReading.h"
#include "mrt_sim/camera.h"
#include "mrt_sim/simulator.h"

namespace {
constexpr double kStart = 100.0;  // bag time of the simulator's t = 0
constexpr int kFrames = 40;       // camera frames written (of 30 Hz: every third)

mrt_msgs::MiceReading mice_msg(const mrt::sim::MiceSample& m, const ros::Time& stamp) {
  mrt_msgs::MiceReading r;
  r.header.stamp = r.left.header.stamp = r.right.header.stamp = stamp;
  r.header.frame_id = "robot1/base_link";
  r.left.header.frame_id = "robot1/" + m.left_id;
  r.right.header.frame_id = "robot1/" + m.right_id;
  r.left.mouse_id = m.left_id;
  r.right.mouse_id = m.right_id;
  r.left.dx = m.left_dx;
  r.left.dy = m.left_dy;
  r.right.dx = m.right_dx;
  r.right.dy = m.right_dy;
  return r;
}

sensor_msgs::Image image_msg(const cv::Mat& rgb, const ros::Time& stamp) {
  sensor_msgs::Image m;
  m.header.stamp = stamp;
  m.header.frame_id = "robot1/omni_mirror";
  m.encoding = "rgb8";
  m.width = rgb.cols;
  m.height = rgb.rows;
  m.step = rgb.cols * rgb.elemSize();
  m.data.assign(rgb.data, rgb.data + rgb.total() * rgb.elemSize());
  return m;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_replay_bag WORLD.yaml OUT\n";
    return 2;
  }
  try {
    const double seconds = 4.0;
    const std::string out = argv[2];
    mrt::sim::Simulator sim(mrt::sim::load_world(argv[1]));
    const std::size_t robot = sim.robot_index("robot1");
    const auto& config = sim.robots()[robot].config;
    mrt::sim::CameraRenderer renderer(sim.world(), config.sensors.camera.model, mrt::sim::camera_options(config, 7));
    rosbag::Bag bag(out + ".bag", rosbag::bagmode::Write);
    const auto& cam = config.sensors.camera.model;
    cv::VideoWriter video(out + ".avi", cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0,
                          cv::Size(cam.width, cam.height_px));
    if (!video.isOpened()) throw std::runtime_error(out + ".avi: cannot write");
    std::ofstream ball(out + "_ball.csv");
    ball << "frame,distance,bearing\n";
    int camera_frames = 0;
    sim.set_twist(robot, {0.5, 0.0, 0.25});
    while (sim.time() < seconds) {
      sim.step();
      const auto& r = sim.robots()[robot];
      const ros::Time stamp(kStart + sim.time());
      if (r.mice_ready) {
        bag.write("/robot1/mice", stamp, mice_msg(r.mice, stamp));
        bag.write("/robot1/ground_truth", stamp,
                  mrt::ros_common::to_odometry(r.pose, r.twist.vx, r.twist.vy, r.twist.omega, "world",
                                               "robot1/base_link_truth", stamp));
      }
      if (r.camera_ready && camera_frames < 3 * kFrames && camera_frames++ % 3 == 0) {
        cv::Mat rgb;
        renderer.render(r.pose, sim.other_robots(robot), sim.time(), rgb, r.twist);
        bag.write("/robot1/camera/image_raw", stamp, image_msg(rgb, stamp));
        cv::Mat bgr;
        cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
        video.write(bgr);
        const auto& b = sim.world().ball.position;
        ball << camera_frames / 3 << ',' << std::hypot(b.x - r.pose.x, b.y - r.pose.y) << ','
             << std::remainder(std::atan2(b.y - r.pose.y, b.x - r.pose.x) - r.pose.theta, 2 * M_PI) << '\n';
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "make_replay_bag: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
