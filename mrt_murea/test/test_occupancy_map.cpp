// Maps from map_server occupancy images: a hand-made 20 x 10 pixel room
// (0.1 m pixels, origin (-1, -0.5)) written here as a PNG, its walls and
// distances worked out by hand; malformed YAML named by file and line.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <fstream>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_murea/feature_map.h"
#include "mrt_murea/localizer.h"
#include "mrt_murea/occupancy_map.h"

using namespace mrt::murea;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// The room: a one-pixel border of black (occupied) pixels, white inside,
// one black pixel at column 5, row 5 (a pillar), one grey (unknown, 50 %)
// pixel at column 12, row 3.
std::string room_png() {
  cv::Mat img(10, 20, CV_8U, cv::Scalar(255));
  img.row(0).setTo(0);
  img.row(9).setTo(0);
  img.col(0).setTo(0);
  img.col(19).setTo(0);
  img.at<uchar>(5, 5) = 0;
  img.at<uchar>(3, 12) = 128;
  const std::string path = ::testing::TempDir() + "murea_room.png";
  cv::imwrite(path, img);
  return path;
}

const char* kYaml =
    "image: murea_room.png\nresolution: 0.1\norigin: [-1.0, -0.5, 0.0]\nnegate: 0\n"
    "occupied_thresh: 0.65\nfree_thresh: 0.196\n";

}  // namespace

// Pixel (col, row) has its centre at x = -1 + (col + 0.5) 0.1, y = -0.5 +
// (9 - row + 0.5) 0.1: the top row at y = 0.45, the bottom at -0.45, the
// left column at x = -0.95, the right at 0.95, the pillar at (-0.45, -0.05).
// Occupied: 2 x 20 + 2 x 8 + 1 = 57 pixels (the grey one: p = 127/255 =
// 0.498 < 0.65, not occupied). Segments: the two full rows (2), then the
// columns' remaining 8 pixels as vertical runs (2), the pillar alone (1).
TEST(OccupancyMap, HandMadeRoom) {
  room_png();
  OccupancyInfo info;
  const mrt::sim::World w = load_occupancy_map(write("murea_room.yaml", kYaml), &info);
  EXPECT_EQ(info.width, 20);
  EXPECT_EQ(info.height, 10);
  EXPECT_EQ(info.occupied, 57u);
  EXPECT_EQ(info.segments, 5u);
  EXPECT_DOUBLE_EQ(w.min_x, -1.0);
  EXPECT_DOUBLE_EQ(w.max_x, 1.0);
  EXPECT_DOUBLE_EQ(w.min_y, -0.5);
  EXPECT_DOUBLE_EQ(w.max_y, 0.5);
  const FeatureMap map(w);
  const Layer walls = map.layer(FeatureClass::Wall, "");
  ASSERT_NE(walls.grid, nullptr);
  // (0, 0): top and bottom rows 0.45 away, sides 0.95, pillar hypot(0.45, 0.05).
  EXPECT_NEAR(walls.grid->exact(0.0, 0.0), 0.45, 1e-9);
  // (0.5, 0.2): top row 0.25, right column 0.45.
  EXPECT_NEAR(walls.grid->exact(0.5, 0.2), 0.25, 1e-9);
  // (-0.45, 0.1): the pillar 0.15 below.
  EXPECT_NEAR(walls.grid->exact(-0.45, 0.1), 0.15, 1e-9);
  // The grid agrees within half its pixel diagonal.
  EXPECT_NEAR(walls.distance(0.5, 0.2), 0.25, walls.slack() / 2 + 1e-6);
  // load_map tells the two formats apart by the `image` key.
  EXPECT_EQ(load_map(::testing::TempDir() + "murea_room.yaml").walls.size(), 5u);
  EXPECT_EQ(load_map(MRT_MUREA_DATA "/room.yaml").name, mrt::sim::load_world(MRT_MUREA_DATA "/room.yaml").name);
}

// negate: 1 reads white as occupied: the 200 - 57 - 1 = 142 white pixels.
TEST(OccupancyMap, Negate) {
  room_png();
  OccupancyInfo info;
  std::string y = kYaml;
  y.replace(y.find("negate: 0"), 9, "negate: 1");
  load_occupancy_map(write("murea_room_neg.yaml", y), &info);
  EXPECT_EQ(info.occupied, 142u);
}

TEST(OccupancyMap, MalformedYamlNamesFileAndLine) {
  room_png();
  auto expect_error = [](const std::string& name, const std::string& text, int line, const std::string& what) {
    const std::string path = write(name, text);
    try {
      load_occupancy_map(path);
      ADD_FAILURE() << name << ": no error";
    } catch (const mrt::common::ParseError& e) {
      EXPECT_EQ(e.file(), path) << e.what();
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  expect_error("bad1.yaml", "image: murea_room.png\nresolution: -0.1\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.2\n",
               2, "resolution");
  expect_error("bad2.yaml", "image: murea_room.png\nresolution: 0.1\norigin: [0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.2\n",
               3, "origin");
  expect_error("bad3.yaml", "image: nowhere.png\nresolution: 0.1\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.2\n",
               1, "cannot read image");
  expect_error("bad4.yaml", "image: murea_room.png\nresolution: 0.1\norigin: [0, 0, 0\n", 4, "");
  expect_error("bad5.yaml", "image: murea_room.png\nresolution: 0.1\norigin: [0, 0, 0]\nfree_thresh: 0.2\n", 1,
               "occupied_thresh");
  expect_error("bad6.yaml", "image: murea_room.png\nresolution: 0.1\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.2\nmode: raw\n",
               6, "mode");
}
