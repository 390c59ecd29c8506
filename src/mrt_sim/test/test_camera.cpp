// The rendered omnidirectional camera: hand-placed objects land where
// omni_camera.h (and a hand calculation) puts them, in their colours, with
// occlusion, the own body, line widths and the image effects.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrt_sim/camera.h"

using namespace mrt::sim;
using mrt::common::MirrorProfile;
using mrt::common::OmniCamera;

namespace {

// Viewpoint 0.6 m high; isometric 2 cm/px up to 3 m (150 px), then
// 560 px/rad up to 1.5 rad: a ground point at distance d <= 3 m in
// direction phi is at radius d / 0.02 px, u = 320 - r sin(phi),
// v = 240 - r cos(phi).
OmniCamera test_camera() {
  OmniCamera c;
  c.height = 0.6;
  c.profile = MirrorProfile::isometric(0.6, 0.02, 3.0, 560.0, 1.5);
  return c;
}

World empty_world() {
  World w;
  w.name = "camera_test";
  w.min_x = -6, w.min_y = -6, w.max_x = 6, w.max_y = 6;
  return w;
}

// Pixel (u, v) is centred on integer coordinates (OpenCV): the nearest one.
cv::Vec3b at(const cv::Mat& m, double u, double v) {
  return m.at<cv::Vec3b>(static_cast<int>(std::lround(v)), static_cast<int>(std::lround(u)));
}

cv::Vec3b ground_pixel(const cv::Mat& m, const OmniCamera& c, double x, double y) {
  double u = 0, v = 0;
  EXPECT_TRUE(c.project_ground(x, y, u, v));
  return at(m, u, v);
}

bool is_orange(const cv::Vec3b& p) { return p[0] > 150 && p[1] > 50 && p[1] < 140 && p[2] < 30; }

}  // namespace

TEST(Camera, BallOneMetreAheadIsOrangeWherePredicted) {
  World w = empty_world();
  w.ball.enabled = true;
  w.ball.position = {1.0, 0.0};
  const OmniCamera cam = test_camera();
  CameraRenderer r(w, cam);
  cv::Mat img;
  r.render(Pose2D(0, 0, 0), {}, 0.0, img);
  ASSERT_EQ(img.type(), CV_8UC3);
  ASSERT_EQ(img.cols, 640);
  ASSERT_EQ(img.rows, 480);
  // Ball centre (1, 0, 0.11): 0.49 m below the viewpoint, 1 m ahead:
  // theta = atan(1 / 0.49) in the isometric part, r = 0.6 tan(theta) / 0.02
  // = 0.6 / 0.49 / 0.02 = 61.22 px straight up: (320, 178.78).
  double u = 0, v = 0;
  ASSERT_TRUE(cam.project(Eigen::Vector3d(1.0, 0.0, 0.11 - 0.6), u, v));
  EXPECT_NEAR(u, 320.0, 1e-6);
  EXPECT_NEAR(v, 240.0 - 61.2245, 1e-3);
  EXPECT_TRUE(is_orange(at(img, u, v))) << at(img, u, v);
  // Floor beyond the ball is carpet green (the ray to (2, 0) passes
  // 0.18 m from the ball centre).
  const cv::Vec3b far = ground_pixel(img, cam, 2.0, 0.0);
  EXPECT_EQ(far, cv::Vec3b(30, 140, 40));
  // Its shadow: the floor point (1, 0.12) is 0.12 m from the ball's foot,
  // in the soft edge (0.088 .. 0.143 m): factor 0.45 + (0.12 - 0.088) /
  // 0.055 * 0.55 = 0.77 -> green 108 (the ray there passes 0.119 m from the
  // ball centre, so the ball does not hide it).
  const cv::Vec3b shade = ground_pixel(img, cam, 1.0, 0.12);
  EXPECT_NEAR(shade[1], 108, 6);
}

TEST(Camera, OwnBodyIsBlackAtTheCentre) {
  const OmniCamera cam = test_camera();
  World w = empty_world();
  CameraOptions o;
  o.own_body_radius = 0.25;
  o.own_body_height = 0.4;
  CameraRenderer r(w, cam, o);
  cv::Mat img;
  r.render(Pose2D(1, 1, 0.3), {}, 0.0, img);
  EXPECT_EQ(at(img, 320, 240), cv::Vec3b(0, 0, 0));
  // A ray to the floor at distance d crosses the body's top (0.2 m below
  // the viewpoint) at d / 3: black up to d = 0.75 m, i.e. radius 37.5 px.
  EXPECT_EQ(at(img, 320, 240 - 35), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(at(img, 320 + 35, 240), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(at(img, 320, 240 - 41), cv::Vec3b(30, 140, 40));
  EXPECT_EQ(at(img, 320 - 41, 240), cv::Vec3b(30, 140, 40));
  // Outside the mirror (radius 150 + 560 (1.5 - atan(5)) = 238.3 px): black.
  EXPECT_EQ(at(img, 5, 5), cv::Vec3b(0, 0, 0));
}

TEST(Camera, FloorColourOfIndoorWorlds) {
  World w = empty_world();
  w.floor_color = "beige";
  const OmniCamera cam = test_camera();
  cv::Mat img;
  CameraRenderer(w, cam).render(Pose2D(), {}, 0.0, img);
  EXPECT_EQ(ground_pixel(img, cam, 2.0, 0.0), cv::Vec3b(190, 175, 150));
  // Beyond the world's bounds (6 m): the `outside` grey, at 7 m behind
  // (isometric part ends at 3 m: this is in the outer part of the mirror).
  EXPECT_EQ(ground_pixel(img, cam, -7.0, 0.0), cv::Vec3b(90, 90, 90));
}

TEST(Camera, WallOccludesPost) {
  World w = empty_world();
  w.posts.push_back({"p", "Landmark", "yellow", {3.0, 0.0}, 0.1});
  const OmniCamera cam = test_camera();
  cv::Mat open, hidden;
  CameraRenderer(w, cam).render(Pose2D(0, 0, 0), {}, 0.0, open);
  w.walls.push_back({{2.0, -0.5}, {2.0, 0.5}});
  CameraRenderer(w, cam).render(Pose2D(0, 0, 0), {}, 0.0, hidden);
  // The post's near face at (2.9, 0, 0.2), seen 0.4 m below the viewpoint
  // (atan(2.9 / 0.4) = 1.434 rad, inside the 1.5 rad mirror), is yellow
  // without the wall and wall grey behind it (that ray crosses x = 2 at
  // 0.6 - 0.4 * 2 / 2.9 = 0.32 m, below the wall's 1 m top).
  double u = 0, v = 0;
  ASSERT_TRUE(cam.project(Eigen::Vector3d(2.9, 0.0, 0.2 - 0.6), u, v));
  EXPECT_EQ(at(open, u, v), cv::Vec3b(255, 220, 0));
  EXPECT_EQ(at(hidden, u, v), cv::Vec3b(110, 110, 110));
  int yellow = 0;
  for (int y = 0; y < hidden.rows; ++y)
    for (int x = 0; x < hidden.cols; ++x) yellow += hidden.at<cv::Vec3b>(y, x) == cv::Vec3b(255, 220, 0);
  EXPECT_EQ(yellow, 0);
  // The post in view: it rotates with the robot (robot turned +90 deg: the
  // post is on its right, u > 320).
  cv::Mat turned;
  w.walls.clear();
  CameraRenderer(w, cam).render(Pose2D(0, 0, M_PI / 2), {}, 0.0, turned);
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0.0, -2.9, 0.2 - 0.6), u, v));
  EXPECT_GT(u, 320.0);
  EXPECT_EQ(at(turned, u, v), cv::Vec3b(255, 220, 0));
}

TEST(Camera, OtherRobotBlackWithMarkerAndLineWidth) {
  World w = empty_world();
  w.field_lines.push_back({{1.5, -1.0}, {1.5, 1.0}});
  w.line_width = 0.125;
  const OmniCamera cam = test_camera();
  CameraRenderer r(w, cam);
  cv::Mat img;
  r.render(Pose2D(0, 0, 0), {{"mate", {0.0, 1.5}, 0.25, "cyan"}}, 0.0, img);
  // Robot 0.6 m high: band 0.45..0.6 m in its colour, black below.
  double u = 0, v = 0;
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0.0, 1.25, 0.5 - 0.6), u, v));
  EXPECT_LT(u, 320.0);  // on the left
  EXPECT_EQ(at(img, u, v), cv::Vec3b(0, 220, 255));
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0.0, 1.25, 0.2 - 0.6), u, v));
  EXPECT_EQ(at(img, u, v), cv::Vec3b(0, 0, 0));
  // A 0.5 m robot 0.8 m ahead (its top is visible from 0.6 m): the top's
  // centre (0.8, 0, 0.5) is black body, its near side at 0.4 m in the band
  // (0.35 .. 0.5) magenta (that ray is at x = 0.275 when at the top's
  // height, short of the top's edge at 0.55).
  CameraOptions low;
  low.robot_height = 0.5;
  CameraRenderer(w, cam, low).render(Pose2D(0, 0, 0), {{"opp", {0.8, 0.0}, 0.25, "magenta"}}, 0.0, img);
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0.8, 0.0, 0.5 - 0.6), u, v));
  EXPECT_EQ(at(img, u, v), cv::Vec3b(0, 0, 0));
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0.55, 0.0, 0.4 - 0.6), u, v));
  EXPECT_EQ(at(img, u, v), cv::Vec3b(240, 0, 200));
  img = cv::Mat();
  r.render(Pose2D(0, 0, 0), {{"mate", {0.0, 1.5}, 0.25, "cyan"}}, 0.0, img);
  // The line x = 1.5 is 12.5 cm wide: white at 1.5 and 1.55, green at 1.6
  // (radius 75, 77.5, 80 px ahead).
  EXPECT_EQ(ground_pixel(img, cam, 1.5, 0.0), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(ground_pixel(img, cam, 1.55, 0.3), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(ground_pixel(img, cam, 1.6, 0.0), cv::Vec3b(30, 140, 40));
  EXPECT_EQ(ground_pixel(img, cam, 1.4, 0.0), cv::Vec3b(30, 140, 40));
}

TEST(Camera, EffectsNoiseFlickerAndDeterminism) {
  const World w = empty_world();
  const OmniCamera cam = test_camera();
  CameraOptions o;
  o.effects.noise = 4.0;
  o.seed = 3;
  cv::Mat a, b, c;
  CameraRenderer(w, cam, o).render(Pose2D(), {}, 0.0, a);
  CameraRenderer(w, cam, o).render(Pose2D(), {}, 0.0, b);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);  // same seed, same frame
  // Green channel of a carpet patch (rows 300..400): mean 140, std-dev the
  // configured 4 levels (within 10 %).
  cv::Scalar mean, sd;
  std::vector<cv::Mat> ch;
  cv::split(a(cv::Rect(280, 300, 80, 100)), ch);
  cv::meanStdDev(ch[1], mean, sd);
  EXPECT_NEAR(mean[0], 140.0, 0.5);
  EXPECT_NEAR(sd[0], 4.0, 0.4);
  // Flicker 20 % with a 4 s period: a quarter period in, the carpet is
  // 1.2 x brighter (140 -> 168).
  CameraOptions f;
  f.effects.flicker = 0.2;
  f.effects.flicker_period = 4.0;
  CameraRenderer(w, cam, f).render(Pose2D(), {}, 1.0, c);
  EXPECT_EQ(at(c, 320, 340), cv::Vec3b(36, 168, 48));
  // White-balance drift 20 %, period 12 s, channels a third of a period
  // apart: at t = 3 s the gains are 1 + 0.2 sin(pi/2 + k 2pi/3) = 1.2, 0.9,
  // 0.9, so the carpet (30, 140, 40) becomes (36, 126, 36).
  CameraOptions wb;
  wb.effects.white_balance_drift = 0.2;
  wb.effects.white_balance_period = 12.0;
  CameraRenderer(w, cam, wb).render(Pose2D(), {}, 3.0, c);
  EXPECT_EQ(at(c, 320, 340), cv::Vec3b(36, 126, 36));
}

TEST(Camera, BlurAtSpeedSmearsAlongTheMotion) {
  World w = empty_world();
  w.field_lines.push_back({{1.5, -1.0}, {1.5, 1.0}});  // across the motion
  w.field_lines.push_back({{0.5, 1.5}, {2.5, 1.5}});   // along it
  const OmniCamera cam = test_camera();
  CameraOptions o;
  o.effects.exposure = 0.02;
  cv::Mat still, moving;
  CameraRenderer(w, cam, o).render(Pose2D(), {}, 0.0, still);
  // 2 m/s x 20 ms = 4 cm = 2 px of slide along v: the 12.5 cm (6 px)
  // crossing line's edge softens, the line along the motion does not.
  CameraRenderer(w, cam, o).render(Pose2D(), {}, 0.0, moving, Twist2D{2.0, 0.0, 0.0});
  double u = 0, v = 0;
  ASSERT_TRUE(cam.project_ground(1.5 + 0.0625, 0.0, u, v));  // edge of the crossing line
  // The edge is at v = 240 - 78.125: row 161 sees 1.58 m (green), row 162
  // 1.56 m (white); blurred along v, row 161 mixes with row 162.
  ASSERT_NEAR(v, 161.875, 0.01);  // the profile is a 512-sample table
  const cv::Vec3b s0 = still.at<cv::Vec3b>(161, 320), m0 = moving.at<cv::Vec3b>(161, 320);
  EXPECT_EQ(s0, cv::Vec3b(30, 140, 40));
  EXPECT_NE(s0, m0);
  EXPECT_EQ(ground_pixel(still, cam, 1.5, 1.5), ground_pixel(moving, cam, 1.5, 1.5));
  EXPECT_EQ(ground_pixel(moving, cam, 1.5, 1.5), cv::Vec3b(255, 255, 255));
}

// sim_node's ~camera_scale: the same camera rendering half-size images.
// The ball 1 m ahead (centre 0.49 m below the viewpoint, 1.1136 m away,
// angular radius asin(0.11 / 1.1136) = 0.0989 rad at theta0 = atan(1 /
// 0.49) = 1.1156 rad) is, in the isometric part (r = 0.6 tan(theta) / 0.02
// full size), a perspective ellipse from r = 30 tan(1.0166) = 48.43 to
// 30 tan(1.2145) = 80.51 px: centred at 64.47 px full size, 32.24 px at
// half size. The half image's centre is (320 + 0.5) / 2 - 0.5 = 159.75, so
// the blob's centroid is at u = 159.75, v = 119.75 - 32.24 = 87.51, within
// half a pixel (one full-size pixel: the blob's digitisation), and at the
// full image's centroid scaled the same way within half a pixel.
TEST(Camera, HalfScaleRendersTheBallAtTheScaledPixel) {
  World w = empty_world();
  w.ball.enabled = true;
  w.ball.position = {1.0, 0.0};
  const OmniCamera half = test_camera().scaled(0.5);
  EXPECT_EQ(half.width, 320);
  EXPECT_EQ(half.height_px, 240);
  EXPECT_DOUBLE_EQ(half.cx, 159.75);
  EXPECT_DOUBLE_EQ(half.cy, 119.75);
  auto centroid = [&](const OmniCamera& cam, double& out_u, double& out_v) {
    CameraRenderer r(w, cam);
    cv::Mat img;
    r.render(Pose2D(0, 0, 0), {}, 0.0, img);
    EXPECT_EQ(img.cols, cam.width);
    double su = 0, sv = 0;
    int n = 0;
    for (int v = 0; v < img.rows; ++v)
      for (int u = 0; u < img.cols; ++u)
        if (is_orange(img.at<cv::Vec3b>(v, u))) su += u, sv += v, ++n;
    EXPECT_GT(n, 10);
    out_u = su / std::max(n, 1), out_v = sv / std::max(n, 1);
  };
  double hu = 0, hv = 0, fu = 0, fv = 0;
  centroid(half, hu, hv);
  centroid(test_camera(), fu, fv);
  EXPECT_NEAR(hu, 159.75, 0.5);
  EXPECT_NEAR(hv, 87.51, 0.5);
  EXPECT_NEAR(fv, 240.0 - 64.47, 1.0);
  EXPECT_NEAR(hu, (fu + 0.5) * 0.5 - 0.5, 0.5);
  EXPECT_NEAR(hv, (fv + 0.5) * 0.5 - 0.5, 0.5);
  EXPECT_THROW(test_camera().scaled(0.0), std::invalid_argument);
}
