// Loaders, inflation, the validity rule and poses. Expected values are
// worked by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_spike/grid.h"
#include "mrt_spike/line_of_sight.h"
#include "mrt_spike/movingai.h"
#include "mrt_spike/poses.h"

using namespace mrt::spike;
using mrt::common::ParseError;

namespace {
const std::string kData = MRT_SPIKE_TEST_DATA;

std::string error_of(void (*f)()) {
  try {
    f();
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

OccupancyGrid grid_from(const std::vector<std::string>& rows) {
  std::string text = "type octile\nheight " + std::to_string(rows.size()) + "\nwidth " +
                     std::to_string(rows[0].size()) + "\nmap\n";
  for (const auto& r : rows) text += r + "\n";
  return parse_movingai_map(text, "inline");
}
}  // namespace

TEST(MovingAi, ParsesPassability) {
  // . G S passable; @ O T W blocked.
  const OccupancyGrid g = grid_from({".GS@", "OTW."});
  EXPECT_EQ(g.width(), 4);
  EXPECT_EQ(g.height(), 2);
  EXPECT_TRUE(g.free(0, 0) && g.free(1, 0) && g.free(2, 0) && g.free(3, 1));
  EXPECT_TRUE(g.blocked(3, 0) && g.blocked(0, 1) && g.blocked(1, 1) && g.blocked(2, 1));
  EXPECT_TRUE(g.blocked(-1, 0) && g.blocked(4, 0));  // outside is blocked
  EXPECT_EQ(g.count_free(), 4);
}

TEST(MovingAi, ErrorsNameFileLineAndColumn) {
  // 'x' is on line 6 (4 header lines + row 2), column 2.
  EXPECT_EQ(error_of([] { load_movingai_map(kData + "/bad_char.map"); }),
            kData + "/bad_char.map:6:2: expected one of . G S @ O T W, got 'x'");
  // row 2 (line 6) has 2 characters instead of 3.
  EXPECT_EQ(error_of([] { load_movingai_map(kData + "/short_row.map"); }),
            kData + "/short_row.map:6: expected a row of 3 characters, got 2");
  EXPECT_EQ(error_of([] { parse_movingai_map("type octile\nheight 2\nwidth 3\nmop\n", "m"); }),
            "m:4: expected 'map'");
  EXPECT_EQ(error_of([] { parse_movingai_map("type octile\nheight -2\n", "m"); }),
            "m:2: expected 'height <positive integer>'");
  EXPECT_EQ(error_of([] { parse_movingai_map("type octile\nheight 3\nwidth 2\nmap\n..\n", "m"); }),
            "m:6: expected 3 map rows, got 1");
  EXPECT_EQ(error_of([] { load_movingai_map(kData + "/missing.map"); }),
            kData + "/missing.map: cannot open file");
}

TEST(MovingAi, ScenarioAndIndexErrors) {
  // the second query line (file line 3) has 6 fields instead of 9
  EXPECT_EQ(error_of([] { load_scenario(kData + "/bad.scen"); }),
            kData + "/bad.scen:3: expected 'bucket map width height start_x start_y goal_x goal_y "
                    "optimal_length'");
  EXPECT_EQ(error_of([] { parse_scenario("versio 1\n", "s"); }), "s:1: expected 'version <n>'");
  const auto q = load_scenario(kData + "/passage32.map.scen");
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q[0].start, (Cell{2, 2}));
  EXPECT_EQ(q[0].goal, (Cell{29, 2}));
  EXPECT_DOUBLE_EQ(q[1].optimal_length, 11.07106781);
}

TEST(Inflation, ExactEuclideanDiscs) {
  OccupancyGrid g(7, 7);
  g.set_blocked(3, 3, true);
  const auto d2 = squared_distance_transform(g);
  EXPECT_DOUBLE_EQ(d2[g.index(0, 0)], 18.0);  // 3^2 + 3^2
  EXPECT_DOUBLE_EQ(d2[g.index(5, 4)], 5.0);   // 2^2 + 1^2
  // radius 1: the cell and its 4 side neighbours (distance 1) -> 7*7 - 5 free
  EXPECT_EQ(inflate(g, 1.0).count_free(), 49 - 5);
  // radius 1.5: + the 4 diagonals (sqrt 2 = 1.414) -> 9 blocked
  EXPECT_EQ(inflate(g, 1.5).count_free(), 49 - 9);
  // radius 2: + 4 cells at distance 2 (sqrt 5 = 2.236 stays free) -> 13 blocked
  EXPECT_EQ(inflate(g, 2.0).count_free(), 49 - 13);
  EXPECT_EQ(inflate(g, 0.0).count_free(), 48);
}

TEST(Inflation, StampDiscAddsAndRemoves) {
  OccupancyGrid g(9, 9);
  stamp_disc(g, 4, 4, 1.0, true);  // centre + 4 side neighbours
  EXPECT_EQ(g.count_free(), 81 - 5);
  stamp_disc(g, 4, 4, 1.0, false);
  EXPECT_EQ(g.count_free(), 81);
}

TEST(LineOfSight, HandCases) {
  // 2x2, (1,0) and (0,1) blocked: the diagonal squeezes between them.
  EXPECT_FALSE(line_of_sight(grid_from({".@", "@."}), {0, 0}, {1, 1}));
  // only one of them blocked: the segment only touches its corner, allowed.
  EXPECT_TRUE(line_of_sight(grid_from({".@", ".."}), {0, 0}, {1, 1}));
  // a blocked cell on a straight row
  EXPECT_FALSE(line_of_sight(grid_from({".@."}), {0, 0}, {2, 0}));
  // (0,0)->(2,1) crosses x=0.5 at t=1/4, y=0.5 at t=1/2, x=1.5 at t=3/4:
  // cells (0,0) (1,0) (1,1) (2,1); (2,0) and (0,1) are not crossed.
  EXPECT_TRUE(line_of_sight(grid_from({"..@", "@.."}), {0, 0}, {2, 1}));
  EXPECT_FALSE(line_of_sight(grid_from({"...", ".@."}), {0, 0}, {2, 1}));
  EXPECT_FALSE(line_of_sight(grid_from({".@.", "..."}), {0, 0}, {2, 1}));
  // symmetric
  EXPECT_TRUE(line_of_sight(grid_from({"..@", "@.."}), {2, 1}, {0, 0}));
  EXPECT_FALSE(line_of_sight(grid_from({".@", "@."}), {1, 1}, {0, 0}));
  // endpoints blocked
  EXPECT_FALSE(line_of_sight(grid_from({"@."}), {0, 0}, {1, 0}));
}

TEST(LineOfSight, PathValidity) {
  const OccupancyGrid g = grid_from({"...", ".@.", "..."});
  std::string why;
  EXPECT_TRUE(path_valid(g, {{0, 0}, {2, 0}, {2, 2}}, {0, 0}, {2, 2}, &why));
  EXPECT_FALSE(path_valid(g, {{0, 0}, {2, 2}}, {0, 0}, {2, 2}, &why));  // through the centre
  EXPECT_EQ(why, "segment 0 (0,0)-(2,2) crosses a blocked cell or corner");
  EXPECT_FALSE(path_valid(g, {{0, 0}, {2, 0}}, {0, 0}, {2, 2}, &why));
  EXPECT_EQ(why, "last waypoint is not the goal");
  EXPECT_FALSE(path_valid(g, {}, {0, 0}, {2, 2}, &why));
  // 3 + 4 = 7 along the border
  EXPECT_DOUBLE_EQ(path_length({{0, 0}, {3, 0}, {3, 4}}), 7.0);
  EXPECT_DOUBLE_EQ(path_length({{0, 0}, {3, 4}}), 5.0);
}

TEST(Poses, SpacingAndHeadings) {
  // (0,0)->(4,0): 4 / 1.5 -> 3 equal steps of 4/3; (4,0)->(4,3): 2 steps of
  // 1.5; plus the goal: 6 poses.
  const auto p = to_poses({{0, 0}, {4, 0}, {4, 3}}, 1.5);
  ASSERT_EQ(p.size(), 6u);
  EXPECT_NEAR(p[1].x, 4.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(p[2].yaw, 0.0);
  EXPECT_DOUBLE_EQ(p[3].x, 4.0);
  EXPECT_NEAR(p[4].y, 1.5, 1e-12);
  EXPECT_NEAR(p[4].yaw, M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(p[5].y, 3.0);
  EXPECT_NEAR(p[5].yaw, M_PI / 2, 1e-12);
  // frame: 0.05 m cells, origin (1, 2): cell (4,3) -> (1.2, 2.15)
  const auto q = to_poses({{0, 0}, {4, 3}}, 0.0, GridFrame{0.05, 1.0, 2.0});
  ASSERT_EQ(q.size(), 2u);
  EXPECT_NEAR(q[1].x, 1.2, 1e-12);
  EXPECT_NEAR(q[1].y, 2.15, 1e-12);
  EXPECT_NEAR(q[0].yaw, std::atan2(3.0, 4.0), 1e-12);
}
