// Occupancy maps: map_server images made here with every pixel known, their
// cells and walls worked out by hand; rasterized worlds counted by hand;
// malformed YAML named by file and line.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <fstream>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_world/occupancy_map.h"

using namespace mrt::world;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// The room: a one-pixel border of black (occupied) pixels, white inside,
// one black pixel at column 5, row 5 (a pillar), one grey (128: p = 0.498)
// pixel at column 12, row 3.
void room_png() {
  cv::Mat img(10, 20, CV_8U, cv::Scalar(255));
  img.row(0).setTo(0);
  img.row(9).setTo(0);
  img.col(0).setTo(0);
  img.col(19).setTo(0);
  img.at<uchar>(5, 5) = 0;
  img.at<uchar>(3, 12) = 128;
  cv::imwrite(::testing::TempDir() + "world_room.png", img);
}

const char* kYaml =
    "image: world_room.png\nresolution: 0.1\norigin: [-1.0, -0.5, 0.0]\nnegate: 0\n"
    "occupied_thresh: 0.65\nfree_thresh: 0.196\n";

int occupied_count(const OccupancyMap& m) { return static_cast<int>(m.count_occupied()); }

}  // namespace

// Pixel (col, row) has its centre at x = -1 + (col + 0.5) 0.1, y = -0.5 +
// (9 - row + 0.5) 0.1: the top row at y = 0.45, the bottom at -0.45, the
// left column at x = -0.95, the right at 0.95, the pillar at (-0.45, -0.05).
// Occupied: 2 x 20 + 2 x 8 + 1 = 57 pixels (the grey one is not). Walls: the
// two full rows (2), then the columns' remaining 8 pixels as vertical runs
// (2), the pillar alone (1).
TEST(OccupancyMap, HandMadeRoom) {
  room_png();
  const OccupancyMap m = load_occupancy_map(write("world_room.yaml", kYaml));
  EXPECT_EQ(m.width, 20);
  EXPECT_EQ(m.height, 10);
  EXPECT_EQ(occupied_count(m), 57);
  // The image's row 3 is the grid's row 6 (bottom up).
  EXPECT_NEAR(m.at(12, 6), 127.0 / 255.0, 1e-6);
  EXPECT_FALSE(m.free(12, 6));
  EXPECT_FALSE(m.occupied(12, 6));
  EXPECT_EQ(m.value(12, 6), -1);  // trinary: between the thresholds is unknown
  EXPECT_EQ(m.value(5, 4), 100);  // the pillar (image row 5)
  EXPECT_EQ(m.value(1, 1), 0);
  const Point2D c = m.cell_center(5, 4);
  EXPECT_NEAR(c.x, -0.45, 1e-12);
  EXPECT_NEAR(c.y, -0.05, 1e-12);
  const World w = occupied_walls(m);
  ASSERT_EQ(w.walls.size(), 5u);
  EXPECT_NEAR(w.walls[0].a.x, -0.95, 1e-12);  // the top row first, left to right
  EXPECT_NEAR(w.walls[0].a.y, 0.45, 1e-12);
  EXPECT_NEAR(w.walls[0].b.x, 0.95, 1e-12);
  EXPECT_DOUBLE_EQ(w.min_x, -1.0);
  EXPECT_DOUBLE_EQ(w.max_x, 1.0);
  EXPECT_DOUBLE_EQ(w.min_y, -0.5);
  EXPECT_DOUBLE_EQ(w.max_y, 0.5);
  // load_map_world tells the two formats apart by the `image` key.
  EXPECT_EQ(load_map_world(::testing::TempDir() + "world_room.yaml").walls.size(), 5u);
  EXPECT_EQ(load_map_world(MRT_WORLD_TEST_DATA "/rooms.yaml").name, "rooms");
}

// negate: 1 reads white as occupied: the 200 - 57 - 1 = 142 white pixels.
TEST(OccupancyMap, Negate) {
  room_png();
  std::string y = kYaml;
  y.replace(y.find("negate: 0"), 9, "negate: 1");
  EXPECT_EQ(occupied_count(load_occupancy_map(write("world_room_neg.yaml", y))), 142);
}

// scale: between the thresholds 1 + 98 (p - free) / (occ - free): the grey
// pixel, p = 127/255, gives 1 + round(98 * 0.30204 / 0.454) = 1 + 65 = 66.
// raw: the grey level is the occupancy in percent (128 > 100: unknown).
TEST(OccupancyMap, ScaleAndRawModes) {
  room_png();
  const OccupancyMap s = load_occupancy_map(write("world_room_scale.yaml", std::string(kYaml) + "mode: scale\n"));
  EXPECT_EQ(s.value(12, 6), 66);
  EXPECT_EQ(s.value(5, 4), 100);
  EXPECT_EQ(s.value(1, 1), 0);
  const OccupancyMap r = load_occupancy_map(write("world_room_raw.yaml", std::string(kYaml) + "mode: raw\n"));
  EXPECT_EQ(r.value(12, 6), -1);
  EXPECT_EQ(r.value(5, 4), 0);    // black: 0 %
  EXPECT_EQ(r.value(1, 1), -1);   // white, 255 > 100: unknown
  EXPECT_TRUE(r.free(5, 4));
}

// A 3 x 2 image; top row: free (254), occupied (0), unknown (205); bottom
// row: free, free, occupied. map_server puts the bottom row at y = 0.
TEST(OccupancyMap, ImageFlippedAndThresholded) {
  cv::Mat img(2, 3, CV_8UC1);
  img.at<unsigned char>(0, 0) = 254, img.at<unsigned char>(0, 1) = 0, img.at<unsigned char>(0, 2) = 205;
  img.at<unsigned char>(1, 0) = 254, img.at<unsigned char>(1, 1) = 254, img.at<unsigned char>(1, 2) = 0;
  ASSERT_TRUE(cv::imwrite(::testing::TempDir() + "world_m.png", img));
  const OccupancyMap m = load_occupancy_map(write("world_m.yaml",
      "image: world_m.png\nresolution: 0.5\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"));
  ASSERT_EQ(m.width, 3);
  ASSERT_EQ(m.height, 2);
  // p = (255 - v) / 255: 254 -> 0.004 free; 205 -> 0.196 not < 0.196: not free
  EXPECT_TRUE(m.free(0, 0));
  EXPECT_TRUE(m.free(1, 0));
  EXPECT_FALSE(m.free(2, 0));
  EXPECT_TRUE(m.free(0, 1));
  EXPECT_FALSE(m.free(1, 1));
  EXPECT_FALSE(m.free(2, 1));
  EXPECT_DOUBLE_EQ(m.cell_center(0, 0).x, -0.75);
  EXPECT_DOUBLE_EQ(m.cell_center(0, 0).y, 2.25);
}

// A map turned by 90 degrees about its origin (1, 2): the 20 x 10 image,
// 2 x 1 m, covers x in [0, 1], y in [2, 4].
TEST(OccupancyMap, RotatedOrigin) {
  room_png();
  std::string y = kYaml;
  y.replace(y.find("[-1.0, -0.5, 0.0]"), 17, "[1.0, 2.0, 1.5707963267948966]");
  const World w = occupied_walls(load_occupancy_map(write("world_room_rot.yaml", y)));
  EXPECT_NEAR(w.min_x, 0.0, 1e-9);
  EXPECT_NEAR(w.max_x, 1.0, 1e-9);
  EXPECT_NEAR(w.min_y, 2.0, 1e-9);
  EXPECT_NEAR(w.max_y, 4.0, 1e-9);
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
  const std::string th = "occupied_thresh: 0.65\nfree_thresh: 0.2\n";
  expect_error("bad1.yaml", "image: world_room.png\nresolution: -0.1\norigin: [0, 0, 0]\n" + th, 2,
               "expected 'resolution' > 0");
  expect_error("bad2.yaml", "image: world_room.png\nresolution: 0.1\norigin: [0, 0]\n" + th, 3, "origin");
  expect_error("bad3.yaml", "image: nowhere.png\nresolution: 0.1\norigin: [0, 0, 0]\n" + th, 1, "cannot read image");
  expect_error("bad4.yaml", "image: world_room.png\nresolution: 0.1\norigin: [0, 0, 0\n", 4, "");
  expect_error("bad5.yaml", "image: world_room.png\nresolution: 0.1\norigin: [0, 0, 0]\nfree_thresh: 0.2\n", 1,
               "occupied_thresh");
  expect_error("bad6.yaml", "image: world_room.png\nresolution: 0.1\norigin: [0, 0, 0]\n" + th + "mode: fancy\n", 6,
               "mode");
  expect_error("bad7.yaml", "image: world_room.png\nresolution: 0.1\norigin: [0, 0, 0]\n" + th + "negate: 2\n", 6,
               "negate");
  expect_error("bad8.yaml", "image: world_room.png\nresolution: 0.1\norigin: [0, 0, 0]\n" + th + "colour: 1\n", 6,
               "unknown key 'colour'");
}

// 2 x 1 m at 0.1 m: 20 x 10 cells, centres at 0.05 + 0.1 k. The wall x = 0.5
// blocks centres within 0.0707 of it: columns 4 (0.45) and 5 (0.55), all 10
// rows = 20 cells. The post at (1.5, 0.5), radius 0.1, blocks centres within
// 0.1707: the 4 at distance 0.0707 and the 8 at 0.158 (one step further in
// x or y); (1.35, 0.35) is at 0.212: 12 cells.
TEST(Rasterize, WallsAndPosts) {
  World w;
  w.min_x = 0, w.min_y = 0, w.max_x = 2, w.max_y = 1;
  w.walls.push_back({{0.5, 0.0}, {0.5, 1.0}});
  Post p;
  p.center = {1.5, 0.5};
  p.radius = 0.1;
  w.posts.push_back(p);
  const OccupancyMap m = rasterize(w, 0.1);
  ASSERT_EQ(m.width, 20);
  ASSERT_EQ(m.height, 10);
  EXPECT_EQ(occupied_count(m), 20 + 12);
  EXPECT_TRUE(m.occupied(4, 0));
  EXPECT_TRUE(m.occupied(5, 9));
  EXPECT_TRUE(m.free(3, 5));
  EXPECT_TRUE(m.occupied(14, 4));  // (1.45, 0.45)
  EXPECT_TRUE(m.free(13, 3));      // (1.35, 0.35)
  EXPECT_EQ(m.value(14, 4), 100);
  EXPECT_EQ(m.value(13, 3), 0);
}

// The two rooms at 0.5 m: 20 x 10 cells. A wall blocks the cells whose
// centre is within 0.354 of it: the outer walls the border cells (2 x 20 +
// 2 x 8 = 56); the middle wall (x = 5, y 0-2.1 and 2.9-5) columns 9 and 10
// (x 4.75, 5.25) in every inner row, the door's too (y 2.25 is 0.29 from
// the end (5, 2.1), y 2.75 as far from (5, 2.9)): 8 x 2 = 16 cells; the
// pillar (2.5, 2.5), r 0.2: the centres within 0.554, the four at 0.354:
// 4 cells.
TEST(Rasterize, RoomsAtHalfMetre) {
  const OccupancyMap m = load_map_grid(MRT_WORLD_TEST_DATA "/rooms.yaml", 0.5);
  ASSERT_EQ(m.width, 20);
  ASSERT_EQ(m.height, 10);
  EXPECT_EQ(occupied_count(m), 56 + 16 + 4);
}
