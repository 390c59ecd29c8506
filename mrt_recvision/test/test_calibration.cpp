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
  EXPECT_EQ(error_line(c + "colors:\n  - {class: purple, hsv: [0, 10, 0, 1, 0, 1]}\n"), 5);
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
