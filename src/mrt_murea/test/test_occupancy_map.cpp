// MUREA on a map_server map: a hand-made 20 x 10 pixel room (0.1 m pixels,
// origin (-1, -0.5)) written here as a PNG; its walls (mrt_world's
// occupied_walls, tested there) and the FeatureMap's distances worked out
// by hand.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <fstream>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_murea/feature_map.h"
#include "mrt_murea/localizer.h"
#include "mrt_world/occupancy_map.h"
#include "mrt_world/world_loader.h"

using namespace mrt::murea;
using mrt::world::load_map_world;

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
TEST(OccupancyMap, HandMadeRoom) {
  room_png();
  const mrt::world::World w = load_map_world(write("murea_room.yaml", kYaml));
  EXPECT_EQ(w.walls.size(), 5u);
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
  // A world file loads as itself.
  EXPECT_EQ(load_map_world(MRT_MUREA_DATA "/room.yaml").name, mrt::world::load_world(MRT_MUREA_DATA "/room.yaml").name);
}
