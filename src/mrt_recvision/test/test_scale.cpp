// The camera scale (recvision_node's ~scale, mrt_sim's ~camera_scale): one
// calibration file, scaled in code (OmniCamera::scaled, scale_calibration), must
// find on a half-size image what the full calibration finds on the full one.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

#include "mrt_recvision/detector.h"
#include "synthetic_scene.h"

using namespace mrt::recvision;
namespace ts = mrt::recvision::testing;

namespace {

Calibration cal() { return load_calibration(MRT_RECVISION_TEST_DATA "/hyperbolic.yaml"); }

const Detection* ball_of(const std::vector<Detection>& dets) {
  for (const Detection& d : dets)
    if (d.membership_class == "Ball") return &d;
  return nullptr;
}

Frame frame_of(const cv::Mat& rgb) {
  Frame f;
  f.rgb = rgb;
  return f;
}

}  // namespace

TEST(ScaleCamera, SizeCentreAndRadiiScale) {
  const Calibration c = cal();
  const auto half = c.camera.scaled(0.5);
  EXPECT_EQ(half.width, 320);
  EXPECT_EQ(half.height_px, 240);
  // Pixel centres at integer coordinates (OpenCV): the full image's point
  // 320 is at (320 + 0.5) * 0.5 - 0.5 = 159.75 in the half image.
  EXPECT_DOUBLE_EQ(half.cx, 159.75);
  EXPECT_DOUBLE_EQ(half.cy, 119.75);
  EXPECT_DOUBLE_EQ(half.height, 0.6);
  // hyperbolic mirror r = 200 sin t / (0.8 + cos t); at t = 1: 200 * 0.841471 /
  // (0.8 + 0.540302) = 125.56 px full size, 62.78 px at half size.
  EXPECT_NEAR(c.camera.profile.radius(1.0), 125.56, 0.05);
  EXPECT_NEAR(half.profile.radius(1.0), 62.78, 0.03);
  EXPECT_THROW(c.camera.scaled(0.0), std::invalid_argument);
  EXPECT_THROW(c.camera.scaled(-1.0), std::invalid_argument);
  EXPECT_THROW(c.camera.scaled(0.001), std::invalid_argument);  // 1 x 0 pixels
}

TEST(ScaleCalibration, PixelThresholdsScaleWithTheImage) {
  Calibration c = cal();
  c.detector.min_ball_pixels = 12;
  c.detector.min_goal_pixels = 40;
  c.detector.min_robot_pixels = 60;
  c.detector.line_gap = 2;
  const Calibration h = scale_calibration(c, 0.5);
  EXPECT_EQ(h.camera.width, 320);
  EXPECT_EQ(h.detector.min_ball_pixels, 3);   // an area: 12 * 0.25
  EXPECT_EQ(h.detector.min_goal_pixels, 20);  // along scan lines: 40 * 0.5
  EXPECT_EQ(h.detector.min_robot_pixels, 30);
  EXPECT_EQ(h.detector.line_gap, 1);
  EXPECT_DOUBLE_EQ(h.detector.ball_radius, c.detector.ball_radius);  // metres stay metres
  EXPECT_DOUBLE_EQ(h.detector.min_distance, c.detector.min_distance);
  const Calibration q = scale_calibration(c, 0.1);
  EXPECT_EQ(q.detector.min_ball_pixels, 1);  // 0.12 rounds to 0: at least 1
  EXPECT_EQ(q.detector.line_gap, 0);
  EXPECT_EQ(scale_calibration(c, 1.0).camera.width, 640);
}

// A ball ray-cast at full size (640 x 480), the image shrunk to half with
// cv::resize (INTER_AREA: independent of the calibration's scaling), and
// RecVision run on it with the scaled calibration: the same ball within
// a tolerance worked out per position.
//
// Tolerance: a blob's centre is found to within half a pixel of its image
// radius in each image, so the two detections differ by at most
// 0.5 + 0.5 / s = 1.5 full-size pixels of radius (s = 0.5). One full-size
// pixel of radius at floor distance d spans dd = (h / cos^2 t) dt metres
// (t = atan(d / h), dt the angle one pixel covers, read off the mirror
// profile), and the ball's centre, R = 0.11 m up on the ray, moves by
// (h - R) / h of it. At 2 m: t = 1.279 rad, dr/dt = 200 (0.8 cos t + 1) /
// (0.8 + cos t)^2 = 208 px/rad, dd = 0.6 / 0.0825 / 208 = 0.0349 m, so
// 1.5 * 0.0349 * 0.49 / 0.6 = 0.043 m. The bearing: half a pixel of
// arc at the blob's radius in each image, 1.5 / r(t) rad.
TEST(ScaleCalibration, HalfScaleImageFindsTheSameBall) {
  const Calibration full = cal();
  const Calibration half = scale_calibration(full, 0.5);
  Detector det_full(full), det_half(half);
  const auto& cam = full.camera;
  const double h = cam.height, R = 0.11, s = 0.5;
  for (const auto& p : {Eigen::Vector2d(1.0, 0.5), Eigen::Vector2d(2.0, 0.0), Eigen::Vector2d(-1.5, 1.5),
                        Eigen::Vector2d(0.5, -2.5)}) {
    ts::Scene scene;
    scene.ball = ts::SceneBall{p, R};
    const cv::Mat img = ts::render(cam, scene, 0, 0, 0);
    cv::Mat small;
    cv::resize(img, small, cv::Size(), s, s, cv::INTER_AREA);
    const auto df = det_full.process(frame_of(img));
    const auto dh = det_half.process(frame_of(small));
    const Detection* bf = ball_of(df);
    const Detection* bh = ball_of(dh);
    ASSERT_NE(bf, nullptr) << p.transpose();
    ASSERT_NE(bh, nullptr) << p.transpose();
    const double t = std::atan2(p.norm(), h);
    const double r = cam.profile.radius(t);
    const double dt = cam.profile.theta(r + 0.5) - cam.profile.theta(r - 0.5);
    const double m_per_px = h / (std::cos(t) * std::cos(t)) * dt * (h - R) / h;
    const double px = 0.5 + 0.5 / s;
    EXPECT_NEAR(bh->distance, bf->distance, px * m_per_px) << p.transpose() << " (tolerance " << px * m_per_px << " m)";
    EXPECT_NEAR(bh->bearing, bf->bearing, px / r) << p.transpose();
    // and both near the truth (the full-size figure of test_detector: 2 %)
    EXPECT_NEAR(bh->distance, p.norm(), 0.02 * p.norm() + px * m_per_px) << p.transpose();
  }
}

// The unscaled calibration on the half image is refused (the node drops
// such frames and says why), so a missing ~scale cannot go unnoticed.
TEST(ScaleCalibration, FullCalibrationRefusesTheHalfImage) {
  Detector det(cal());
  cv::Mat small(240, 320, CV_8UC3, cv::Scalar(40, 140, 40));
  std::string why;
  EXPECT_FALSE(det.accepts(frame_of(small), why));
  EXPECT_NE(why.find("320x240"), std::string::npos) << why;
}
