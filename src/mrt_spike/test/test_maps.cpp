// SPIKE's grids from worlds and map_server maps (mrt_world loads and
// rasterizes them; its tests check that); cells worked by hand.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "mrt_common/parse_error.h"
#include "mrt_spike/map_sources.h"

using namespace mrt::spike;
namespace fs = std::filesystem;

namespace {
int blocked_count(const OccupancyGrid& g) { return g.width() * g.height() - g.count_free(); }

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("mrt_spike_maps_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST(WorldMap, WallsAndPostsRasterized) {
  // 2 x 1 m at 0.1 m: 20 x 10 cells, centres at 0.05 + 0.1 k. The wall x = 0.5
  // blocks centres within 0.0707 of it: columns 4 (0.45) and 5 (0.55), all 10
  // rows = 20 cells. The post at (1.5, 0.5), radius 0.1, blocks centres within
  // 0.1707: the 4 at distance 0.0707 and the 8 at 0.158 (one step further in
  // x or y); (1.35, 0.35) is at 0.212: 12 cells.
  mrt::world::World w;
  w.min_x = 0, w.min_y = 0, w.max_x = 2, w.max_y = 1;
  w.walls.push_back({{0.5, 0.0}, {0.5, 1.0}});
  mrt::world::Post p;
  p.center = {1.5, 0.5};
  p.radius = 0.1;
  w.posts.push_back(p);
  const WorldGrid m = rasterize_world(w, 0.1);
  ASSERT_EQ(m.grid.width(), 20);
  ASSERT_EQ(m.grid.height(), 10);
  EXPECT_EQ(blocked_count(m.grid), 20 + 12);
  EXPECT_TRUE(m.grid.blocked(4, 0));
  EXPECT_TRUE(m.grid.blocked(5, 9));
  EXPECT_FALSE(m.grid.blocked(3, 5));
  EXPECT_TRUE(m.grid.blocked(14, 4));   // (1.45, 0.45)
  EXPECT_FALSE(m.grid.blocked(13, 3));  // (1.35, 0.35)
  EXPECT_EQ(m.cell_at(1.45, 0.45), (Cell{14, 4}));
}

TEST(OccupancyMap, MapServerImageFlippedAndThresholded) {
  const fs::path d = temp_dir();
  // 3 x 2 image; top row: free (254), occupied (0), unknown (205);
  // bottom row: free, free, occupied. map_server puts the bottom row at y = 0.
  cv::Mat img(2, 3, CV_8UC1);
  img.at<unsigned char>(0, 0) = 254, img.at<unsigned char>(0, 1) = 0, img.at<unsigned char>(0, 2) = 205;
  img.at<unsigned char>(1, 0) = 254, img.at<unsigned char>(1, 1) = 254, img.at<unsigned char>(1, 2) = 0;
  ASSERT_TRUE(cv::imwrite((d / "m.png").string(), img));
  std::ofstream(d / "m.yaml") << "image: m.png\nresolution: 0.5\norigin: [-1.0, 2.0, 0.0]\n"
                                 "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  const WorldGrid m = load_any_map((d / "m.yaml").string(), 1.0);
  ASSERT_EQ(m.grid.width(), 3);
  ASSERT_EQ(m.grid.height(), 2);
  // p = (255 - v) / 255: 254 -> 0.004 free; 205 -> 0.196 not < 0.196: blocked
  EXPECT_FALSE(m.grid.blocked(0, 0));
  EXPECT_FALSE(m.grid.blocked(1, 0));
  EXPECT_TRUE(m.grid.blocked(2, 0));
  EXPECT_FALSE(m.grid.blocked(0, 1));
  EXPECT_TRUE(m.grid.blocked(1, 1));
  EXPECT_TRUE(m.grid.blocked(2, 1));
  // cell (0,0)'s centre: origin + half a cell
  EXPECT_DOUBLE_EQ(m.frame.origin_x, -0.75);
  EXPECT_DOUBLE_EQ(m.frame.origin_y, 2.25);
  // errors name file:line
  std::ofstream(d / "bad.yaml") << "image: m.png\norigin: [0, 0, 0]\nresolution: -1\n";
  try {
    load_any_map((d / "bad.yaml").string(), 1.0);
    FAIL() << "no error";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("expected 'resolution' > 0"), std::string::npos) << e.what();
  }
  std::ofstream(d / "noimg.yaml") << "image: missing.png\nresolution: 1\norigin: [0, 0, 0]\n"
                                       "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  try {
    load_any_map((d / "noimg.yaml").string(), 1.0);
    FAIL() << "no error";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("cannot read image"), std::string::npos) << e.what();
  }
  // a turned map: SPIKE's grids are axis-aligned
  std::ofstream(d / "turned.yaml") << "image: m.png\nresolution: 0.5\norigin: [0, 0, 0.5]\n"
                                       "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  try {
    load_any_map((d / "turned.yaml").string(), 1.0);
    FAIL() << "no error";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("turned.yaml: expected an origin yaw of 0"), std::string::npos) << e.what();
  }
  fs::remove_all(d);
}
