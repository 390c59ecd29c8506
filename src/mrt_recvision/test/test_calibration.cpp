// The calibration file: the shipped file loads, errors name file:line.
#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"
#include "mrt_recvision/calibration.h"

using mrt::common::ParseError;
using mrt::recvision::Calibration;
using mrt::recvision::ColorClass;
using mrt::recvision::ColorTable;
using mrt::recvision::parse_calibration;

namespace {
const char* kCamera =
    "camera:\n"
    "  viewpoint_height: 0.6\n"
    "  mirror: {type: hyperbolic, gamma: 200, xi: 0.8, theta_max: 1.9}\n";

int error_line(const std::string& text) {
  try {
    parse_calibration(text, "cal.yaml");
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "cal.yaml");
    return e.line();
  }
  return -1;
}
}  // namespace

TEST(Calibration, ShippedFileLoads) {
  const Calibration c = mrt::recvision::load_calibration(MRT_RECVISION_CONFIG_DIR "/msl_omni.yaml");
  EXPECT_EQ(c.camera.width, 640);
  EXPECT_DOUBLE_EQ(c.camera.height, 0.7);
  // Isometric inner part, 2 cm per pixel: 1 m on the floor is 50 px out.
  double u = 0, v = 0;
  ASSERT_TRUE(c.camera.project_ground(1.0, 0.0, u, v));
  EXPECT_NEAR(v, 240.0 - 50.0, 0.05);
  EXPECT_EQ(c.colors.classify(40, 140, 40), ColorClass::kGreen);
  EXPECT_EQ(c.colors.classify(255, 120, 0), ColorClass::kOrange);
  EXPECT_EQ(c.detector.radial_lines, 360);
}

TEST(Calibration, MountAndDetectorOptions) {
  const Calibration c = parse_calibration(std::string(kCamera) +
                                              "mount: [0.1, -0.02, 0.5]\n"
                                              "colors:\n  - {class: green, samples: [[40, 140, 40]]}\n"
                                              "detector: {radial_lines: 90, max_distance: 5}\n",
                                          "cal.yaml");
  EXPECT_DOUBLE_EQ(c.mount_x, 0.1);
  EXPECT_DOUBLE_EQ(c.mount_y, -0.02);
  EXPECT_DOUBLE_EQ(c.mount_yaw, 0.5);
  EXPECT_EQ(c.detector.radial_lines, 90);
  EXPECT_DOUBLE_EQ(c.detector.max_distance, 5.0);
  EXPECT_EQ(c.colors.count(ColorClass::kGreen), 1);  // one sample, one bin
}

TEST(Calibration, ErrorsNameTheLine) {
  const std::string c(kCamera);  // 3 lines
  EXPECT_EQ(error_line(c + "colors:\n  - {class: violet, hsv: [0, 10, 0, 1, 0, 1]}\n"), 5);
  EXPECT_EQ(error_line(c + "colors:\n  - {class: green,\n     hsv: [0, 10, 0, 2, 0, 1]}\n"), 6);
  EXPECT_EQ(error_line(c + "colors:\n  - {class: green}\n"), 5);
  EXPECT_EQ(error_line(c + "colors:\n  - {class: green, rgb: [0, 10, 0, 1, 0]}\n"), 5);
  EXPECT_EQ(error_line(c + "colors: []\ndetector: {max_distance: 0.1}\n"), 5);
  EXPECT_EQ(error_line(c + "colors: []\nlut: /nonexistent/t.png\n"), 5);
  EXPECT_EQ(error_line(c + "colours: []\n"), 4);
  EXPECT_EQ(error_line("camera: {viewpoint_height: 0.6}\ncolors: []\n"), 1);  // mirror missing
}

TEST(Calibration, LutFileIsRelativeToTheCalibrationFile) {
  ColorTable t;
  t.set(1, 2, 3, ColorClass::kCyan);
  const std::string dir = ::testing::TempDir();
  t.save(dir + "/recv_lut.png");
  const Calibration c =
      parse_calibration(std::string(kCamera) + "colors: []\nlut: recv_lut.png\n", dir + "/cal.yaml");
  EXPECT_EQ(c.colors.classify(1, 2, 3), ColorClass::kCyan);
  EXPECT_EQ(c.colors.count(ColorClass::kCyan), 1);
}

// The museum's file: no MSL finder, the object finder with its three
// kinds, and the colours mrt_sim's renderer paints (mrt_sim/src/camera.cpp,
// color_rgb: RGB values copied from there) in their classes.
TEST(Calibration, MuseumFileClassifiesTheRenderedColours) {
  const Calibration c = mrt::recvision::load_calibration(MRT_RECVISION_CONFIG_DIR "/museum.yaml");
  EXPECT_FALSE(c.detector.find_lines || c.detector.find_ball || c.detector.find_goals || c.detector.find_robots);
  ASSERT_TRUE(c.objects.enabled);
  ASSERT_EQ(c.objects.kinds.size(), 3u);
  EXPECT_EQ(c.objects.kinds[0].membership_class, "Landmark");
  EXPECT_DOUBLE_EQ(c.objects.kinds[0].radius, 0.08);
  EXPECT_EQ(c.objects.kinds[1].membership_class, "Person");
  EXPECT_DOUBLE_EQ(c.objects.kinds[1].radius, 0.25);
  EXPECT_DOUBLE_EQ(c.objects.kinds[2].radius, 0.0);  // exhibits: measured
  EXPECT_EQ(c.objects.wall, ColorClass::kGrey);
  const auto& t = c.colors;
  EXPECT_EQ(t.classify(190, 175, 150), ColorClass::kBeige);   // floor
  EXPECT_EQ(t.classify(110, 110, 110), ColorClass::kGrey);    // walls
  EXPECT_EQ(t.classify(128, 128, 128), ColorClass::kNone);    // the column (no colour)
  EXPECT_EQ(t.classify(130, 40, 180), ColorClass::kPurple);   // the guest's badge
  EXPECT_EQ(t.classify(240, 0, 200), ColorClass::kMagenta);
  EXPECT_EQ(t.classify(255, 120, 0), ColorClass::kOrange);
  EXPECT_EQ(t.classify(170, 120, 60), ColorClass::kBronze);
  EXPECT_EQ(t.classify(0, 200, 60), ColorClass::kGreen);
  EXPECT_EQ(t.classify(220, 20, 20), ColorClass::kRed);
  EXPECT_EQ(t.classify(255, 220, 0), ColorClass::kYellow);
  EXPECT_EQ(t.classify(0, 70, 255), ColorClass::kBlue);
  EXPECT_EQ(t.classify(0, 220, 255), ColorClass::kCyan);
  EXPECT_EQ(t.classify(255, 255, 255), ColorClass::kWhite);
  // Pixel noise of 6 levels (3 sigma of the world's 2) keeps the floor and the badge.
  EXPECT_EQ(t.classify(184, 181, 144), ColorClass::kBeige);
  EXPECT_EQ(t.classify(136, 34, 186), ColorClass::kPurple);
}

TEST(Calibration, ObjectsAndFindErrorsNameTheLine) {
  const std::string c = std::string(kCamera) + "colors: []\n";  // 4 lines
  EXPECT_EQ(error_line(c + "detector: {find: [ball, goal]}\n"), 5);
  EXPECT_EQ(error_line(c + "objects:\n  kinds: []\n"), 6);  // floor missing: the map begins on line 6
  EXPECT_EQ(error_line(c + "objects:\n  floor: [violet]\n"), 6);
  EXPECT_EQ(error_line(c + "objects:\n  floor: [beige]\n  kinds:\n    - {class: Person, colors: [purple], width: [0.8, 0.3]}\n"), 8);
  EXPECT_EQ(error_line(c + "objects:\n  floor: [beige]\n  kinds:\n    - {class: Person, colors: []}\n"), 8);
  EXPECT_EQ(error_line(c + "objects:\n  floor: [beige]\n  wall_step: 0\n"), 7);
  const Calibration ok = parse_calibration(c + "detector: {find: [ball]}\nobjects: {floor: [beige, white]}\n", "cal.yaml");
  EXPECT_TRUE(ok.detector.find_ball);
  EXPECT_FALSE(ok.detector.find_lines);
  EXPECT_EQ(ok.objects.floor.size(), 2u);
  EXPECT_TRUE(ok.objects.kinds.empty());
}
