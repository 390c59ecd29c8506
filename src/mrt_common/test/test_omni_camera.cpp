// Omnidirectional camera model: profiles against hand-computed radii,
// radius <-> angle round trips, pixel <-> ground round trips, tilt.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/omni_camera.h"

using mrt::common::MirrorProfile;
using mrt::common::OmniCamera;

TEST(MirrorProfile, HyperbolicMatchesUnifiedModel) {
  const auto p = MirrorProfile::hyperbolic(200.0, 0.8, 2.0);
  // theta = 45 deg: r = 200 sin45 / (0.8 + cos45) = 141.421 / 1.507107 = 93.837
  EXPECT_NEAR(p.radius(M_PI / 4), 93.837, 0.01);
  // theta = 90 deg (horizon): r = 200 / 0.8 = 250
  EXPECT_NEAR(p.radius(M_PI / 2), 250.0, 0.05);
  EXPECT_NEAR(p.theta(93.837), M_PI / 4, 1e-4);
  EXPECT_TRUE(std::isnan(p.radius(2.1)));
  EXPECT_TRUE(std::isnan(p.theta(-1.0)));
}

TEST(MirrorProfile, IsometricInnerPartHasConstantGroundResolution) {
  // 0.6 m high viewpoint, 1 cm per pixel up to 2 m: d = 1 m -> 100 px, 2 m -> 200 px.
  const auto p = MirrorProfile::isometric(0.6, 0.01, 2.0, 100.0, 1.75);
  EXPECT_NEAR(p.radius(std::atan2(1.0, 0.6)), 100.0, 0.02);
  EXPECT_NEAR(p.radius(std::atan2(2.0, 0.6)), 200.0, 0.02);
  // outer part: 0.1 rad beyond the break -> 200 + 10 px
  EXPECT_NEAR(p.radius(std::atan2(2.0, 0.6) + 0.1), 210.0, 0.02);
}

TEST(MirrorProfile, RejectsNonMonotoneTables) {
  EXPECT_THROW(MirrorProfile({{0.0, 0.0}, {0.1, 5.0}, {0.2, 4.0}}), std::invalid_argument);
  EXPECT_THROW(MirrorProfile({{0.0, 0.0}}), std::invalid_argument);
  EXPECT_THROW(MirrorProfile::hyperbolic(200.0, 0.8, 2.6), std::invalid_argument);  // beyond acos(-0.8)=2.498
}

TEST(OmniCamera, GroundPointsLandWhereTheConventionSays) {
  OmniCamera cam;
  cam.height = 0.6;
  cam.profile = MirrorProfile::isometric(0.6, 0.01, 2.0, 100.0, 1.75);
  double u = 0, v = 0;
  ASSERT_TRUE(cam.project_ground(1.0, 0.0, u, v));  // 1 m ahead: straight up, 100 px
  EXPECT_NEAR(u, 320.0, 1e-6);
  EXPECT_NEAR(v, 140.0, 0.02);
  ASSERT_TRUE(cam.project_ground(0.0, 1.5, u, v));  // 1.5 m to the left: left, 150 px
  EXPECT_NEAR(u, 170.0, 0.02);
  EXPECT_NEAR(v, 240.0, 1e-6);
}

TEST(OmniCamera, PixelGroundRoundTripWithTilt) {
  OmniCamera cam;
  cam.height = 0.6;
  cam.cx = 322.5;
  cam.cy = 238.0;
  cam.roll = 0.02;
  cam.pitch = -0.015;
  cam.profile = MirrorProfile::hyperbolic(200.0, 0.8, 1.9);
  for (double x : {-3.0, -0.7, 0.4, 2.5}) {
    for (double y : {-2.0, 0.3, 1.1}) {
      double u = 0, v = 0, gx = 0, gy = 0;
      ASSERT_TRUE(cam.project_ground(x, y, u, v)) << x << " " << y;
      ASSERT_TRUE(cam.pixel_to_ground(u, v, gx, gy));
      EXPECT_NEAR(gx, x, 1e-6 * (1 + std::hypot(x, y)));
      EXPECT_NEAR(gy, y, 1e-6 * (1 + std::hypot(x, y)));
    }
  }
  // A point above the viewpoint height is above the horizon: no ground point.
  double u = 0, v = 0, gx = 0, gy = 0;
  ASSERT_TRUE(cam.project(Eigen::Vector3d(0.0, 2.0, 0.05), u, v));
  EXPECT_FALSE(cam.pixel_to_ground(u, v, gx, gy));
}

// ---- YAML form (omni_camera_yaml.h) ----
#include "mrt_common/omni_camera_yaml.h"

namespace {
OmniCamera read_cam(const std::string& text) {
  mrt::common::YamlReader r("cam.yaml");
  return mrt::common::read_omni_camera(r, r.load(text)["camera"]);
}
}  // namespace

TEST(OmniCameraYaml, ReadsTheIsometricBlock) {
  const auto cam = read_cam(
      "camera:\n  width: 320\n  height: 240\n  viewpoint_height: 0.6\n"
      "  mirror: {type: isometric, metres_per_px: 0.02, inner_range: 2.0, px_per_rad: 50, theta_max: 1.7}\n");
  EXPECT_EQ(cam.width, 320);
  EXPECT_DOUBLE_EQ(cam.cx, 160.0);  // default: image centre
  // 1 m at 2 cm/px -> 50 px
  EXPECT_NEAR(cam.profile.radius(std::atan2(1.0, 0.6)), 50.0, 0.01);
}

TEST(OmniCameraYaml, ErrorsNameFileAndLine) {
  try {
    read_cam("camera:\n  viewpoint_height: 0.6\n  mirror:\n    type: parabolic\n");
    FAIL() << "expected a ParseError";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("cam.yaml:4:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hyperbolic, isometric or table"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_cam("camera:\n  mirror: {type: table, samples: [[0, 0], [0.5, 3], [0.4, 9]]}\n"),
               mrt::common::ParseError);
  EXPECT_THROW(read_cam("camera:\n  focal: 3\n  mirror: {type: hyperbolic, gamma: 1, xi: 1, theta_max: 1}\n"),
               mrt::common::ParseError);
}
