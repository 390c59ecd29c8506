// recvision_node in robot1's namespace: a ray-cast frame with a ball at
// (2, -0.5) m from the viewpoint, which is 0.1 m ahead of base_link (tf),
// gives a Ball percept at (2.1, -0.5) in robot1/base_link; a 32FC1 frame
// (cv_bridge refuses it) and a 320x240 frame are dropped and counted in
// the diagnostics; the
// debug image comes out at the camera's size. Reconfigured through
// /robot1/recvision/set_parameters, a max_distance short of the ball hides it.
// The encodings and camera_info tests: rostest_encodings.cpp.
#include <gtest/gtest.h>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <mrt_msgs/Percept.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <cmath>

#include "mrt_common_ros/rostest_helpers.h"
#include "mrt_recvision/calibration.h"
#include "synthetic_scene.h"

namespace ts = mrt::recvision::testing;
using mrt::ros_common::wait_for;

namespace {

sensor_msgs::Image to_msg(const cv::Mat& rgb, const std::string& encoding) {
  sensor_msgs::Image m;
  m.header.stamp = ros::Time::now();
  m.header.frame_id = "robot1/omni_mirror";
  m.encoding = encoding;
  m.width = rgb.cols;
  m.height = rgb.rows;
  m.step = rgb.cols * rgb.elemSize();
  m.data.assign(rgb.data, rgb.data + rgb.total() * rgb.elemSize());
  return m;
}

double attr(const mrt_msgs::PerceptObject& o, const std::string& name) {
  for (const auto& a : o.attributes)
    if (a.name == name) return a.value;
  return NAN;
}

std::string value_of(const diagnostic_msgs::DiagnosticStatus& s, const std::string& key) {
  for (const auto& kv : s.values)
    if (kv.key == key) return kv.value;
  return "";
}

}  // namespace

TEST(RecVisionNode, PerceptsDebugImageAndDroppedFrames) {
  ros::NodeHandle nh;
  mrt_msgs::Percept last;
  int percepts = 0, debug = 0;
  diagnostic_msgs::DiagnosticStatus diag;
  auto p_sub = nh.subscribe<mrt_msgs::Percept>("/robot1/percepts", 10, [&](const mrt_msgs::PerceptConstPtr& m) {
    last = *m;
    ++percepts;
  });
  auto d_sub = nh.subscribe<sensor_msgs::Image>("/robot1/camera/debug_image", 10, [&](const sensor_msgs::ImageConstPtr& m) {
    EXPECT_EQ(m->width, 640u);
    EXPECT_EQ(m->encoding, "rgb8");
    ++debug;
  });
  auto g_sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArrayConstPtr& m) {
    for (const auto& s : m->status)
      if (s.name.find("frames") != std::string::npos) diag = s;
  });
  tf2_ros::StaticTransformBroadcaster tf;
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "robot1/base_link";
  t.child_frame_id = "robot1/omni_mirror";
  t.transform.translation.x = 0.1;
  t.transform.translation.z = 0.6;
  t.transform.rotation.w = 1.0;
  tf.sendTransform(t);
  auto pub = nh.advertise<sensor_msgs::Image>("/robot1/camera/image_raw", 5);
  ASSERT_TRUE(wait_for([&] { return pub.getNumSubscribers() > 0 && d_sub.getNumPublishers() > 0; }, 20.0));

  const auto cal = mrt::recvision::load_calibration(MRT_RECVISION_TEST_DATA "/hyperbolic.yaml");
  ts::Scene s;
  s.ball = ts::SceneBall{Eigen::Vector2d(2.0, -0.5), 0.11};
  const cv::Mat frame = ts::render(cal.camera, s, 0, 0, 0);
  // Frames until the mount from tf has been used (the first may precede the tf).
  bool ok = false;
  for (int i = 0; i < 20 && !ok; ++i) {
    const int before = percepts;
    pub.publish(to_msg(frame, "rgb8"));
    ASSERT_TRUE(wait_for([&] { return percepts > before; }, 10.0));
    for (const auto& o : last.objects)
      if (o.membership_class == "Ball" && std::abs(attr(o, "x") - 2.1) < 0.05) ok = true;
  }
  ASSERT_TRUE(ok);
  EXPECT_EQ(last.header.frame_id, "robot1/base_link");
  EXPECT_EQ(last.robot, "robot1");
  ASSERT_EQ(last.objects.size(), 1u);
  const auto& ball = last.objects[0];
  // (2.1, -0.5): distance 2.1587 m, bearing atan2(-0.5, 2.1) = -0.2337 rad.
  EXPECT_NEAR(attr(ball, "y"), -0.5, 0.02);
  EXPECT_NEAR(attr(ball, "distance"), 2.1587, 0.04);
  EXPECT_NEAR(attr(ball, "bearing"), -0.2337, 0.01);
  EXPECT_EQ(ball.attributes.back().symbol, "orange");
  EXPECT_TRUE(wait_for([&] { return debug > 0; }, 10.0));
  // Bad frames, once the connection is known to carry messages.
  const int before = percepts;
  pub.publish(to_msg(cv::Mat(480, 640, CV_32FC1, cv::Scalar(0)), "32FC1"));
  pub.publish(to_msg(cv::Mat(240, 320, CV_8UC3, cv::Scalar(0)), "rgb8"));
  EXPECT_TRUE(wait_for([&] { return value_of(diag, "dropped: wrong size") == "1"; }, 10.0));
  EXPECT_EQ(value_of(diag, "dropped: wrong encoding"), "1");
  EXPECT_EQ(percepts, before);  // nothing published for them
}

// dynamic_reconfigure: the ball at (2, -0.5) m from the viewpoint is 2.06 m
// away and every ray through it meets the floor beyond 2 m (its centre's at
// 2.06 * 0.6 / (0.6 - 0.11) = 2.52 m, the viewpoint 0.6 m up): with
// max_distance 1.5 m nothing of it is scanned, so the percepts hold no Ball
// and nothing beyond 1.5 m (+ the 0.1 m mount); back at the file's 8 m the
// Ball returns.
TEST(RecVisionNode, ReconfiguredMaxDistanceHidesTheFartherBall) {
  ros::NodeHandle nh;
  mrt_msgs::Percept last;
  int percepts = 0;
  auto p_sub = nh.subscribe<mrt_msgs::Percept>("/robot1/percepts", 10, [&](const mrt_msgs::PerceptConstPtr& m) {
    last = *m;
    ++percepts;
  });
  auto pub = nh.advertise<sensor_msgs::Image>("/robot1/camera/image_raw", 5);
  ASSERT_TRUE(wait_for([&] { return pub.getNumSubscribers() > 0 && p_sub.getNumPublishers() > 0; }, 20.0));
  ASSERT_TRUE(ros::service::waitForService("/robot1/recvision/set_parameters", ros::Duration(20)));
  const auto cal = mrt::recvision::load_calibration(MRT_RECVISION_TEST_DATA "/hyperbolic.yaml");
  ts::Scene s;
  s.ball = ts::SceneBall{Eigen::Vector2d(2.0, -0.5), 0.11};
  const cv::Mat frame = ts::render(cal.camera, s, 0, 0, 0);
  // one frame, its percept's balls (-1: no percept)
  const auto balls_seen = [&] {
    const int before = percepts;
    pub.publish(to_msg(frame, "rgb8"));
    if (!wait_for([&] { return percepts > before; }, 10.0)) return -1;
    int n = 0;
    for (const auto& o : last.objects) n += o.membership_class == "Ball";
    return n;
  };
  const auto set_max_distance = [&](double value) -> double {
    dynamic_reconfigure::Reconfigure srv;
    dynamic_reconfigure::DoubleParameter p;
    p.name = "max_distance";
    p.value = value;
    srv.request.config.doubles.push_back(p);
    if (!ros::service::call("/robot1/recvision/set_parameters", srv)) return NAN;
    for (const auto& d : srv.response.config.doubles)
      if (d.name == "max_distance") return d.value;
    return NAN;
  };
  EXPECT_EQ(balls_seen(), 1);
  EXPECT_DOUBLE_EQ(set_max_distance(1.5), 1.5);
  EXPECT_EQ(balls_seen(), 0);
  for (const auto& o : last.objects) EXPECT_LE(attr(o, "distance"), 1.5 + 0.1 + 0.05) << o.membership_class;
  EXPECT_DOUBLE_EQ(set_max_distance(8.0), 8.0);
  EXPECT_EQ(balls_seen(), 1);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "recvision_node_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
