// PlannerCost: times from a planner's path lengths, cached as detour
// factors per target; the numbers are worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_scare/path_cost.h"

namespace mrt::scare {
namespace {

RobotSpec robot(double speed) {
  RobotSpec r;
  r.id = "robot1";
  r.max_speed = speed;
  return r;
}

TEST(PlannerCost, StraightLineUntilPlannedThenTheDetour) {
  PlannerCost c;  // resolution 0.5 m, max_age 2 s
  c.set_time(0.0);
  // (0, 0) -> (3, 4): 5 m at 2 m/s = 2.5 s before any plan.
  EXPECT_DOUBLE_EQ(c.time(robot(2.0), Pose2D(0, 0, 0), {3, 4}), 2.5);
  auto q = c.next_query(0.0);
  ASSERT_TRUE(q);
  EXPECT_EQ(q->second.x, 3.0);
  EXPECT_EQ(q->second.y, 4.0);
  // A 7.5 m path: detour 7.5 / 5 = 1.5, time 5 * 1.5 / 2 = 3.75 s.
  c.record(Pose2D(0, 0, 0), {3, 4}, 7.5, 0.0);
  EXPECT_DOUBLE_EQ(c.detour({3, 4}), 1.5);
  EXPECT_DOUBLE_EQ(c.time(robot(2.0), Pose2D(0, 0, 0), {3, 4}), 3.75);
  EXPECT_FALSE(c.next_query(1.0));  // fresh for 2 s
  // (3.1, 4.2) rounds to the same cell (6, 8) at 0.5 m: same factor;
  // sqrt(3.1^2 + 4.2^2) = 5.22015 m, * 1.5 / 2 = 3.91511 s.
  EXPECT_NEAR(c.time(robot(2.0), Pose2D(0, 0, 0), {3.1, 4.2}), 3.91511, 1e-5);
  // Requested again at 2.5 s, the answer of 0 s is stale: asked again.
  c.set_time(2.5);
  c.time(robot(2.0), Pose2D(1, 1, 0), {3, 4});
  q = c.next_query(2.5);
  ASSERT_TRUE(q);
  EXPECT_EQ(q->first.x, 1.0);  // from the last request's pose
}

TEST(PlannerCost, NeverPlannedFirstUnreachableInfiniteForgottenWhenNotAsked) {
  PlannerCost c;
  c.set_time(0.0);
  c.time(robot(1.0), Pose2D(0, 0, 0), {-7.5, 0});
  c.record(Pose2D(0, 0, 0), {-7.5, 0}, 9.0, 0.0);
  c.set_time(3.0);
  c.time(robot(1.0), Pose2D(0, 0, 0), {-7.5, 0});  // stale answer
  c.time(robot(1.0), Pose2D(0, 0, 0), {2, 1});     // never planned: first
  auto q = c.next_query(3.0);
  ASSERT_TRUE(q);
  EXPECT_EQ(q->second.x, 2.0);
  c.record(q->first, q->second, std::nullopt, 3.0);  // no path
  EXPECT_TRUE(std::isinf(c.time(robot(1.0), Pose2D(0, 0, 0), {2, 1})));
  q = c.next_query(3.0);
  ASSERT_TRUE(q);
  EXPECT_EQ(q->second.x, -7.5);
  // A path shorter than the straight line (grid rounding): no detour.
  c.record(Pose2D(0, 0, 0), {-7.5, 0}, 7.4, 3.0);
  EXPECT_DOUBLE_EQ(c.detour({-7.5, 0}), 1.0);
  // Nothing requested after 3 s: at 5.5 s both are forgotten.
  EXPECT_FALSE(c.next_query(5.5));
  EXPECT_DOUBLE_EQ(c.detour({2, 1}), 1.0);
}

TEST(PlannerCost, CoordinatorUsesItForTheTimes) {
  // robot_view with a detour of 2 on the Defense target (-7.5, 0) from
  // (0, 1): straight sqrt(7.5^2 + 1) = 7.5664 m at 1 m/s, doubled 15.1327 s.
  const ActivitySet set = parse_activities(
      "fuzzy: {shapes: \"(UNIT (TOR (HIGH 0 1)))\", data: \"(Threat UNIT)\"}\n"
      "activities:\n  - {name: Defense, opportunity: 1, target: [-7.5, 0.0]}\n"
      "robots:\n  - {id: robot1, max_speed: 1.0}\n",
      "a.yaml");
  PlannerCost c;
  c.set_time(0.0);
  c.record(Pose2D(0, 1, 0), {-7.5, 0}, 2.0 * std::hypot(7.5, 1.0), 0.0);
  const RobotView v = robot_view(set, set.robot_or_default("robot1"), Pose2D(0, 1, 0), {}, c);
  ASSERT_EQ(v.time.size(), 1u);
  EXPECT_NEAR(v.time[0], 15.1327, 1e-4);
}

}  // namespace
}  // namespace mrt::scare
