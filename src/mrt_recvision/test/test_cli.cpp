// The command-line tools as programs: --help exits 0, usage errors exit 2
// with "<tool>: " on stderr, calibration errors name file:line, and each
// tool does its job on files made here.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "mrt_common/percept_csv.h"
#include "mrt_common/testing/cli_runner.h"
#include "mrt_recvision/calibration.h"
#include "synthetic_scene.h"

namespace cr = mrt::common::testing;
namespace ts = mrt::recvision::testing;
using namespace mrt::recvision;

namespace {
const std::string kCalib = MRT_RECVISION_TEST_DATA "/hyperbolic.yaml";
const std::string kSimCalib = MRT_RECVISION_CONFIG_DIR "/msl_omni.yaml";  // mrt_sim's MSL camera
std::string tmp(const std::string& name) { return ::testing::TempDir() + "/recvision_cli_" + name; }
void save_rgb(const std::string& path, const cv::Mat& rgb) {
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  ASSERT_TRUE(cv::imwrite(path, bgr));
}
}  // namespace

TEST(Cli, HelpAndUsageErrors) {
  for (const char* tool : {RECVISION_RUN, RECVISION_CALIBRATE, RECVISION_MIRROR_CALIB}) {
    const auto h = cr::help(tool);
    EXPECT_EQ(h.code, 0) << tool;
    EXPECT_NE(h.text.find("--calib"), std::string::npos) << tool;
    const auto e = cr::err(tool, "--no-such-option");
    EXPECT_EQ(e.code, 2) << tool;
    EXPECT_NE(e.text.find(": "), std::string::npos);
    EXPECT_EQ(cr::out(tool, "--no-such-option"), "");
  }
  const auto none = cr::err(RECVISION_RUN, "--calib " + kCalib);
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.text.rfind("recvision_run: ", 0), 0u) << none.text;
  EXPECT_EQ(cr::err(RECVISION_RUN, "--calib " + kCalib + " --bag x.bag a.png").code, 2);  // bag excludes images
  EXPECT_EQ(cr::err(RECVISION_RUN, "--calib " + kCalib + " --topic /t a.png").code, 2);   // --topic needs --bag
}

TEST(Cli, CalibrationErrorNamesFileAndLine) {
  const std::string path = tmp("bad.yaml");
  std::ofstream(path) << "camera:\n  viewpoint_height: 0.6\n  mirror: {type: conic}\ncolors: []\n";
  const auto e = cr::err(RECVISION_RUN, "--calib " + path + " x.png");
  EXPECT_EQ(e.code, 2);
  EXPECT_NE(e.text.find(path + ":3:"), std::string::npos) << e.text;
}

TEST(Cli, RunWritesTheBallOfAnImageAsCsv) {
  const Calibration c = load_calibration(kCalib);
  ts::Scene s;
  s.ball = ts::SceneBall{Eigen::Vector2d(2.0, 1.0), 0.11};
  const std::string img = tmp("ball.png");
  save_rgb(img, ts::render(c.camera, s, 0, 0, 0));
  const auto r = cr::run("'" RECVISION_RUN "' --calib " + kCalib + " " + img + " " + img + " 2>/dev/null");
  ASSERT_EQ(r.code, 0);
  std::istringstream in(r.text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "stamp,class,color,distance,bearing,reliability");  // the contract of issue 14
  int balls = 0;
  while (std::getline(in, line)) {
    double stamp = 0, dist = 0, bearing = 0, rel = 0;
    char cls[32] = {0}, col[32] = {0};
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%31[^,],%31[^,],%lf,%lf,%lf", &stamp, cls, col, &dist, &bearing, &rel), 6)
        << line;
    ASSERT_EQ(std::string(cls), "Ball");
    EXPECT_EQ(std::string(col), "orange");
    EXPECT_EQ(stamp, double(balls));  // the image's position in the list
    EXPECT_NEAR(dist, std::sqrt(5.0), 0.02 * std::sqrt(5.0));  // hypot(2, 1) = 2.236 m
    EXPECT_NEAR(bearing, std::atan2(1.0, 2.0), 0.01);         // 0.4636 rad
    ++balls;
  }
  EXPECT_EQ(balls, 2);
  // The one percept CSV format: what murea_localize reads (its reader is
  // mrt_common's) takes the output as it is: two frames of one ball.
  std::istringstream again(r.text);
  const auto frames = mrt::common::read_percept_csv(again, "recvision_run");
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].id, "1.000000");
  ASSERT_EQ(frames[1].objects.size(), 1u);
  EXPECT_EQ(frames[1].objects[0].membership_class, "Ball");
  EXPECT_NEAR(*frames[1].objects[0].number("distance"), std::sqrt(5.0), 0.02 * std::sqrt(5.0));
  EXPECT_EQ(cr::err(RECVISION_RUN, "--calib " + kCalib + " /nonexistent.png").code, 1);
}

TEST(Cli, CalibrateLearnsTheMarkedColour) {
  cv::Mat rgb(20, 20, CV_8UC3, cv::Scalar(40, 140, 40)), mask(20, 20, CV_8UC1, cv::Scalar(0));
  rgb(cv::Rect(0, 0, 10, 20)).setTo(cv::Scalar(100, 60, 200));  // a purple-ish marker colour
  mask(cv::Rect(0, 0, 10, 20)).setTo(255);
  save_rgb(tmp("sample.png"), rgb);
  cv::imwrite(tmp("mask.png"), mask);
  const std::string lut = tmp("lut.png");
  const auto r = cr::run("'" RECVISION_CALIBRATE "' --out " + lut + " --grow 1 --sample magenta:" + tmp("sample.png") +
                         ":" + tmp("mask.png") + " 2>&1");
  ASSERT_EQ(r.code, 0) << r.text;
  EXPECT_NE(r.text.find("magenta,200,27,0,27"), std::string::npos) << r.text;  // 200 px, 1 bin grown to 3x3x3
  const ColorTable t = ColorTable::load(lut);
  EXPECT_EQ(t.classify(100, 60, 200), ColorClass::kMagenta);
  EXPECT_EQ(t.classify(108, 52, 207), ColorClass::kMagenta);   // a neighbouring bin
  EXPECT_EQ(t.classify(40, 140, 40), ColorClass::kNone);       // not marked, no --calib
  EXPECT_EQ(cr::err(RECVISION_CALIBRATE, "--out " + lut + " --sample violet:a.png:b.png").code, 2);
}

TEST(Cli, MirrorCalibFitsRingsAtKnownDistances) {
  // Rings where the hyperbolic mirror of test/data/hyperbolic.yaml images 0.5 ... 4 m:
  // r = 200 sin t / (0.8 + cos t), t = atan(d / 0.6).
  cv::Mat rgb(480, 640, CV_8UC3, cv::Scalar(40, 140, 40));
  std::string dists;
  for (double d : {0.5, 1.0, 1.5, 2.0, 3.0, 4.0}) {
    const double t = std::atan2(d, 0.6);
    cv::circle(rgb, {320, 240}, int(std::lround(200 * std::sin(t) / (0.8 + std::cos(t)))), cv::Scalar(250, 250, 250), 2);
    dists += (dists.empty() ? "" : ",") + std::to_string(d);
  }
  save_rgb(tmp("rings.png"), rgb);
  const auto r = cr::run("'" RECVISION_MIRROR_CALIB "' --calib " + kCalib + " --image " + tmp("rings.png") +
                         " --ray 0:" + dists + " --ray 90:" + dists + " --theta-max 1.45 2>&1");
  ASSERT_EQ(r.code, 0) << r.text;
  const auto at = r.text.find("# rms: ");
  ASSERT_NE(at, std::string::npos) << r.text;
  EXPECT_LT(std::stod(r.text.substr(at + 7)), 1.0);  // px; rings drawn to the nearest pixel
  EXPECT_NE(r.text.find("type: table"), std::string::npos);
  const auto wrong = cr::err(RECVISION_MIRROR_CALIB, "--calib " + kCalib + " --image " + tmp("rings.png") + " --ray 0:1,2");
  EXPECT_EQ(wrong.code, 1);
  EXPECT_NE(wrong.text.find("found 6 line(s)"), std::string::npos) << wrong.text;
}

// A bag of frames rendered by mrt_sim's camera (robot1 at (-2, 0) facing
// +x, the ball at the centre spot: 2.0 m ahead) plus one mono8 frame,
// replayed through recvision_run.
#include <rosbag/bag.h>
#include <sensor_msgs/Image.h>

#include "mrt_sim/camera.h"

TEST(Cli, RunReplaysABagOfSimulatedFrames) {
  mrt::sim::World w = mrt::sim::load_world(MRT_SIM_WORLD);
  const auto& rc = w.robots.at(0);
  mrt::sim::CameraRenderer renderer(w, rc.sensors.camera.model, mrt::sim::camera_options(rc, 3));
  const std::string path = tmp("sim.bag");
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    for (int i = 0; i < 4; ++i) {
      sensor_msgs::Image m;
      m.header.stamp = ros::Time(10.0 + i);
      m.header.frame_id = "robot1/omni_mirror";
      cv::Mat rgb;
      renderer.render({-2.0, 0.0, 0.0}, {}, 10.0 + i, rgb);
      if (i == 2) rgb = cv::Mat(rgb.rows, rgb.cols, CV_32FC1, cv::Scalar(0));  // cv_bridge: not a colour format
      m.encoding = i == 2 ? "32FC1" : "rgb8";
      m.width = rgb.cols;
      m.height = rgb.rows;
      m.step = rgb.cols * rgb.elemSize();
      m.data.assign(rgb.data, rgb.data + rgb.total() * rgb.elemSize());
      bag.write("/robot1/camera/image_raw", m.header.stamp, m);
    }
  }
  const auto r = cr::run("'" RECVISION_RUN "' --calib " + kSimCalib + " --bag " + path + " 2>&1");
  ASSERT_EQ(r.code, 0) << r.text;
  EXPECT_NE(r.text.find("3 frames from /robot1/camera/image_raw, 1 dropped"), std::string::npos) << r.text;
  std::istringstream in(r.text);
  int balls = 0;
  for (std::string line; std::getline(in, line);) {
    double stamp = 0, dist = 0, bearing = 0, rel = 0;
    char cls[32] = {0}, col[32] = {0};
    if (std::sscanf(line.c_str(), "%lf,%31[^,],%31[^,],%lf,%lf,%lf", &stamp, cls, col, &dist, &bearing, &rel) != 6 ||
        std::string(cls) != "Ball")
      continue;
    EXPECT_NEAR(dist, 2.0, 0.04);  // 2 %
    EXPECT_NEAR(bearing, 0.0, 0.02);
    EXPECT_NE(stamp, 12.0);        // the dropped frame
    ++balls;
  }
  EXPECT_EQ(balls, 3);
}
