// Scan lines and green-white-green transitions, on hand-drawn images
// (cv::circle / cv::line on a green background) and on class sequences.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <cmath>

#include "mrt_recvision/calibration.h"
#include "mrt_recvision/scan_lines.h"

using namespace mrt::recvision;

namespace {
constexpr std::uint8_t G = 1, W = 2, O = 3, N = 0;  // green, white, orange, none

Calibration cal() { return load_calibration(MRT_RECVISION_TEST_DATA "/hyperbolic.yaml"); }

// A straight fake scan line, points 5 cm apart along x.
ScanLine fake(int n) {
  ScanLine l;
  for (int i = 0; i < n; ++i) l.points.push_back({i, 0.05f * i, 0.0f});
  return l;
}

std::vector<LinePoint> points_on(const Calibration& c, const cv::Mat& rgb, bool radial) {
  const ScanGrid g(c.camera, c.detector);
  std::vector<LinePoint> out;
  for (const ScanLine& l : radial ? g.radial() : g.circular()) {
    std::vector<std::uint8_t> cls;
    for (const ScanPoint& p : l.points) cls.push_back(c.colors.lookup(rgb.ptr<std::uint8_t>() + 3 * p.offset));
    find_line_points(l, cls.data(), c.detector, out);
  }
  return out;
}
}  // namespace

TEST(LinePoints, GreenWhiteGreenRunGivesItsMiddle) {
  DetectorOptions o;
  std::vector<LinePoint> out;
  const std::uint8_t a[] = {G, G, W, W, W, G, G};
  find_line_points(fake(7), a, o, out);
  // Edges half-way between points 1|2 (0.075 m) and 4|5 (0.225 m): middle 0.15, width 0.15.
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].x, 0.15, 1e-6);
  out.clear();
  const std::uint8_t b[] = {G, N, W, W, N, G};  // one unclassified point each side: allowed (gap 2)
  find_line_points(fake(6), b, o, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].x, 0.125, 1e-6);  // edges 0.075 and 0.175
}

TEST(LinePoints, RejectsWrongNeighboursGapsAndWidths) {
  DetectorOptions o;
  std::vector<LinePoint> out;
  const std::uint8_t gap[] = {G, N, N, N, W, G};  // three unclassified points > gap 2
  find_line_points(fake(6), gap, o, out);
  const std::uint8_t orange[] = {G, W, O, G};
  find_line_points(fake(4), orange, o, out);
  const std::uint8_t edge[] = {W, W, G, G};  // no green before
  find_line_points(fake(4), edge, o, out);
  const std::uint8_t wide[] = {G, W, W, W, W, W, W, G};  // 6 points = 0.30 m > 0.25
  find_line_points(fake(8), wide, o, out);
  EXPECT_TRUE(out.empty());
}

TEST(ScanGrid, RadialLinesStartAtTheBodyAndEndAtMaxDistance) {
  const Calibration c = cal();
  const ScanGrid g(c.camera, c.detector);
  ASSERT_EQ(g.radial().size(), 360u);
  ASSERT_EQ(g.circular().size(), 6u);
  const ScanLine& fwd = g.radial()[0];  // bearing 0: straight up in the image
  ASSERT_FALSE(fwd.points.empty());
  EXPECT_NEAR(fwd.points.front().x, 0.35, 0.02);
  EXPECT_NEAR(fwd.points.front().y, 0.0, 1e-6);
  EXPECT_NEAR(fwd.points.back().x, 8.0, 0.3);  // 1 px is 0.27 m at 8 m
  EXPECT_EQ(fwd.points.front().offset % 640, 320);
  const ScanLine& left = g.radial()[90];  // bearing 90 deg: left in the image
  EXPECT_LT(left.points.back().offset % 640, 320);
  EXPECT_GT(left.points.back().y, 7.5);
}

TEST(ScanGrid, RingDrawnAtTwoMetresIsFoundOnEveryRadialLine) {
  const Calibration c = cal();
  // r(2 m): theta = atan(2/0.6) = 1.27934; r = 200 sin / (0.8 + cos) = 191.56 / 1.08731 = 176.18 px.
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(40, 140, 40));
  cv::circle(img, {320, 240}, 176, cv::Scalar(250, 250, 250), 3);
  const auto pts = points_on(c, img, true);
  EXPECT_GE(pts.size(), 355u);
  EXPECT_LE(pts.size(), 360u);
  // 1 px is dd/dr = 0.6/cos^2(theta) / (dr/dtheta = 208 px/rad) = 0.035 m there.
  for (const LinePoint& p : pts) EXPECT_NEAR(std::hypot(p.x, p.y), 2.0, 0.05);
  // A 40 px wide ring (about 1.4 m of floor) is no line.
  cv::circle(img, {320, 240}, 176, cv::Scalar(250, 250, 250), 40);
  EXPECT_TRUE(points_on(c, img, true).empty());
}

TEST(ScanGrid, RadialLineIsFoundOnTheCircles) {
  const Calibration c = cal();
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(40, 140, 40));
  // A line to the robot's left: from the centre towards decreasing u, 7 px wide (0.05 m at 0.8 m, 0.11 m at 3 m).
  cv::line(img, {320, 240}, {0, 240}, cv::Scalar(250, 250, 250), 7);
  const auto radial = points_on(c, img, true);
  EXPECT_TRUE(radial.empty());  // runs along the radial line at 90 deg, never crossed green-white-green
  const auto circ = points_on(c, img, false);
  ASSERT_EQ(circ.size(), 6u);  // one per circle (0.8 ... 3 m)
  for (const LinePoint& p : circ) {
    EXPECT_NEAR(p.x, 0.0, 0.03);
    EXPECT_GT(p.y, 0.7);
  }
}
