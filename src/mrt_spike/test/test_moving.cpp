// Moving obstacles: footprints worked by hand, incremental add / move /
// remove, and re-planning around them.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_spike/line_of_sight.h"
#include "mrt_spike/moving_obstacles.h"
#include "mrt_spike/ompl_planner.h"

using namespace mrt::spike;

namespace {
int blocked_count(const OccupancyGrid& g) { return g.width() * g.height() - g.count_free(); }
}  // namespace

TEST(ObstacleLayer, FootprintsBySizeAndSpeed) {
  const OccupancyGrid field(20, 12);
  ObstacleLayer layer(field, 1.0, 1.0);  // inflation 1 cell, horizon 1 s
  // still, radius 1 + 1: the 13 cell centres within 2 of (5,5)
  // (1 + 4 at distance 1 + 4 at sqrt 2 + 4 at 2)
  EXPECT_EQ(layer.footprint({5, 5, 1, 0, 0}).size(), 13u);
  // 2 cells/s along x: the capsule (5,5)-(7,5) of radius 2: columns 5..7
  // five cells each, columns 4 and 8 three (|dy| <= sqrt 3), 3 and 9 one: 23
  EXPECT_EQ(layer.footprint({5, 5, 1, 2, 0}).size(), 23u);
  // clipped at the map's edge: the quarter disc and the two half rows at (0,0)
  // x, y >= 0 with x^2 + y^2 <= 4: 1 + 2 + 1 + 2 = 6 ... listed: (0,0) (1,0)
  // (2,0) (0,1) (1,1) (0,2)
  EXPECT_EQ(layer.footprint({0, 0, 1, 0, 0}).size(), 6u);
}

TEST(ObstacleLayer, AddMoveRemoveIncrementally) {
  OccupancyGrid base(20, 12);
  base.set_blocked(0, 0, true);
  ObstacleLayer layer(base, 1.0, 1.0);
  layer.set(1, {5, 5, 1, 0, 0});
  EXPECT_EQ(blocked_count(layer.grid()), 1 + 13);
  layer.set(1, {12, 5, 1, 0, 0});  // moved: the old disc is free again
  EXPECT_EQ(blocked_count(layer.grid()), 1 + 13);
  EXPECT_TRUE(layer.grid().free(5, 5));
  EXPECT_TRUE(layer.grid().blocked(12, 5));
  layer.set(2, {13, 5, 1, 0, 0});  // overlapping: union of two discs
  // two discs radius 2 one apart: 13 + 13 - overlap; overlap = centres within
  // 2 of both (12,5) and (13,5): x in {12,13} with |dy| <= 1 (6 cells) plus
  // (11,5)? dist to 13 is 2 -> yes; (14,5) dist to 12 is 2 -> yes: 8
  EXPECT_EQ(blocked_count(layer.grid()), 1 + 13 + 13 - 8);
  layer.remove(1);
  EXPECT_EQ(blocked_count(layer.grid()), 1 + 13);
  EXPECT_TRUE(layer.grid().blocked(12, 5));  // still under obstacle 2
  layer.clear();
  EXPECT_EQ(blocked_count(layer.grid()), 1);
  EXPECT_TRUE(layer.grid().blocked(0, 0));  // the static cell stays
}

TEST(DynamicSpike, ReplansAroundAnObstacleOnThePath) {
  const OccupancyGrid field(20, 11);
  DynamicSpike spike(field, 0.5, 1.0);
  PlanResult r = spike.plan({1, 5}, {18, 5});
  ASSERT_TRUE(r.solved);
  EXPECT_EQ(r.reason, "static");
  EXPECT_DOUBLE_EQ(r.length, 17.0);
  spike.obstacles().set(7, {10, 5, 1.5, 0, 0});  // disc of radius 2 across the line
  EXPECT_FALSE(spike.still_valid(r.path));
  r = spike.plan({1, 5}, {18, 5});
  ASSERT_TRUE(r.solved);
  EXPECT_NE(r.reason, "static");
  EXPECT_TRUE(path_valid(spike.obstacles().grid(), r.path, {1, 5}, {18, 5}));
  // around the disc: longer than 17, at most the octile detour 17 + 2*(sqrt2-1)*3
  // (3 diagonal steps up and 3 down replace 6 straight ones: the disc is 5 high)
  EXPECT_GT(r.length, 17.0);
  EXPECT_LE(r.length, 17.0 + 6 * (std::sqrt(2.0) - 1.0) + 1e-9);
  spike.obstacles().remove(7);
  EXPECT_EQ(spike.plan({1, 5}, {18, 5}).reason, "static");
  // a goal inside a footprint: no path, the reason and a nearest point
  spike.obstacles().set(8, {18, 5, 1, 0, 0});
  r = spike.plan({1, 5}, {18, 5});
  EXPECT_FALSE(r.solved);
  EXPECT_EQ(r.reason, "goal (18, 5) is inside an obstacle");
}

TEST(OmplPlanner, RrtStarAndPrmStarOnAnOpenField) {
  // 20 x 20 free: both solve (1,1) -> (18,18); simplified, the path is
  // nearly the diagonal 17*sqrt(2) = 24.04 (at most 5 % longer) and valid.
  const OccupancyGrid g(20, 20);
  for (const char* name : {"rrtstar", "prmstar"}) {
    OmplPlanner p(g, {name, 0.2, 7});
    const PlanResult r = p.plan({1, 1}, {18, 18});
    ASSERT_TRUE(r.solved) << name;
    EXPECT_EQ(r.path.front(), (Cell{1, 1}));
    EXPECT_EQ(r.path.back(), (Cell{18, 18}));
    EXPECT_GE(r.length, 17 * std::sqrt(2.0) - 1e-9);
    EXPECT_LE(r.length, 1.05 * 17 * std::sqrt(2.0)) << name;
    EXPECT_TRUE(path_valid(g, r.path, {1, 1}, {18, 18})) << name;
  }
  EXPECT_THROW(OmplPlanner(g, {"rrt", 0.1, 1}), std::invalid_argument);
  // a blocked goal: no path, with the reason
  OccupancyGrid w(20, 20);
  w.set_blocked(5, 5, true);
  EXPECT_EQ(OmplPlanner(w).plan({1, 1}, {5, 5}).reason, "goal (5, 5) is inside an obstacle");
}
