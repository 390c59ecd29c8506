// FollowMe's museum (mrt_world/worlds/museum.yaml): four rooms joined by four
// doors 1.0-1.2 m wide; closing a door with an obstacle makes SPIKE re-plan
// through the other three.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mrt_spike/world_planner.h"

using namespace mrt::spike;

namespace {

const std::string kMuseum = std::string(MRT_WORLDS_DIR) + "/museum.yaml";

// The closest a plan's poses come to (x, y).
double closest(const WorldPlan& p, double x, double y) {
  double d = 1e9;
  for (const Pose& q : p.poses) d = std::min(d, std::hypot(q.x - x, q.y - y));
  return d;
}

}  // namespace

TEST(Museum, ClosingADoorReplansThroughTheOthers) {
  // robot 0.3 m + safety 0.1 m at 0.05 m (at 0.1 m the cells blocked by
  // the door posts plus the 0.4 m inflation close the 1.0 m doors); the rooms: south-west (x < 10,
  // y < 6), south-east, north-west, north-east. Doors: (10, 2.5-3.5)
  // SW-SE, (10, 8.5-9.6) NW-NE, (4.5-5.5, 6) SW-NW, (14.4-15.6, 6) SE-NE.
  WorldPlanner wp(load_any_map(kMuseum, 0.05), {});
  const WorldPlan open = wp.plan(1.5, 2.0, 18.5, 2.0);
  ASSERT_TRUE(open.solved) << open.reason;
  // through the SW-SE door: the straight 17 m plus the climb to the door
  // (y 2.925-3.075 free) and back; far from the other doors
  EXPECT_LT(closest(open, 10.0, 3.0), 0.15);
  EXPECT_GE(open.length, 17.0);
  EXPECT_LE(open.length, 18.5);
  EXPECT_GT(closest(open, 5.0, 6.0), 2.0);
  // the door closed: a disc of 0.6 m on its centre (1.0 m wide)
  wp.set_obstacle(0, 10.0, 3.0, 0.6, 0.0, 0.0);
  EXPECT_FALSE(wp.still_valid(open));
  const WorldPlan round = wp.plan(1.5, 2.0, 18.5, 2.0);
  ASSERT_TRUE(round.solved) << round.reason;
  // SW -> NW -> NE -> SE: through the three other doors (within half their
  // width of their centres), never near the closed one; at least the
  // polyline through the nearest door ends (5.5, 6), (10, 8.5), (14.4, 6):
  // sqrt(32) + sqrt(26.5) + sqrt(25.61) + sqrt(32.81) = 21.59 m
  EXPECT_LT(closest(round, 5.0, 6.0), 0.6);
  EXPECT_LT(closest(round, 10.0, 9.05), 0.6);
  EXPECT_LT(closest(round, 15.0, 6.0), 0.65);
  EXPECT_GT(closest(round, 10.0, 3.0), 0.6 + 0.4 - 0.036);
  EXPECT_GE(round.length, 21.59 - 0.01);
  EXPECT_LE(round.length, 25.0);
  EXPECT_NEAR(round.poses.back().x, 18.5, 0.026);
  EXPECT_NEAR(round.poses.back().y, 2.0, 0.026);
  // closing the NW-NE door too leaves no way: "no path", and the nearest
  // reachable point is on the start's side
  wp.set_obstacle(1, 10.0, 9.05, 0.7, 0.0, 0.0);
  const WorldPlan none = wp.plan(1.5, 2.0, 18.5, 2.0);
  EXPECT_FALSE(none.solved);
  EXPECT_FALSE(none.reason.empty());
  EXPECT_LT(none.nearest_x, 10.0);
  // opened again: the short way back
  wp.remove_obstacle(0);
  wp.remove_obstacle(1);
  EXPECT_NEAR(wp.plan(1.5, 2.0, 18.5, 2.0).length, open.length, 1e-9);
}
