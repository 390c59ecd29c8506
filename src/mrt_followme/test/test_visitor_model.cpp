// The visitor behaviour model, decision by decision, against hand-worked
// positions.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_followme/visitor_model.h"

using namespace mrt::followme;

namespace {

VisitorOptions options(int wander_after = 0) {
  VisitorOptions o;
  o.comfortable = 1.1;
  o.return_distance = 1.2;
  o.walk_speed = 0.7;
  o.look_time = 6.0;
  o.wander_after = wander_after;
  o.wander_stay = 25.0;
  return o;
}

const Exhibit kA{"a", {5.0, 0.0}, {5.0, 2.0}};
const Exhibit kB{"b", {9.0, 8.0}, {9.0, 9.0}};

}  // namespace

TEST(VisitorModel, FollowsAtAComfortableDistance) {
  VisitorModel v(options(), {kA}, kB);
  // Robot at the origin, visitor 3 m along +x: walk to the point 1.1 m from
  // the robot on the line between them, (1.1, 0), at 0.7 m/s.
  VisitorStep s = v.update(0.0, {3.0, 0.0}, Pose2D(0, 0, 0));
  EXPECT_NEAR(s.target.x, 1.1, 1e-12);
  EXPECT_NEAR(s.target.y, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.speed, 0.7);
  // 1.3 m away is within comfortable + 0.25 = 1.35 m: stand.
  s = v.update(0.1, {1.3, 0.0}, Pose2D(0, 0, 0));
  EXPECT_DOUBLE_EQ(s.speed, 0.0);
  EXPECT_EQ(v.state(), VisitorState::kFollow);
}

TEST(VisitorModel, FollowsTheRobotsTrailRoundACorner) {
  VisitorModel v(options(), {kA}, kB);
  // The robot goes east 2 m, then north 3 m (through a door at (2, 1), say);
  // the visitor stays at (-1, 0).
  const Pose2D path[] = {Pose2D(0, 0, 0), Pose2D(1, 0, 0), Pose2D(2, 0, 0),
                         Pose2D(2, 1, 0), Pose2D(2, 2, 0), Pose2D(2, 3, 0)};
  VisitorStep s;
  for (const Pose2D& p : path) s = v.update(0.0, {-1.0, 0.0}, p);
  // The way along the trail is 1 m to (0, 0) plus the robot's 5 m: far more
  // than comfortable + 0.25. Its nearest trail point is (0, 0); the next,
  // (1, 0), is more than 0.5 m on, so it walks there — along the robot's
  // path, where a straight line to the robot would cut the corner (through
  // a wall, were there one) to (1.22, 2.22).
  EXPECT_NEAR(s.target.x, 1.0, 1e-12);
  EXPECT_NEAR(s.target.y, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.speed, 0.7);
  // At (1.9, 0.95), 1.15 m from the robot in a straight line but 2.11 m
  // along the trail from its nearest point (2, 1): it walks on, but not
  // past (2, 1), the last trail point at least 1.1 m (here 2 m) from the
  // robot along the trail.
  s = v.update(0.1, {1.9, 0.95}, Pose2D(2, 3, 0));
  EXPECT_NEAR(s.target.x, 2.0, 1e-12);
  EXPECT_NEAR(s.target.y, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.speed, 0.7);
}

TEST(VisitorModel, FollowsTheRobotsLatestPassWhereItsTrailDoublesBack) {
  VisitorModel v(options(), {kA}, kB);
  // The robot goes north along x = 0 to (0, 6), turns back and comes south
  // along x = 0.0625 to (0.0625, 1), in steps of 0.125 m (every one a
  // trail point). The visitor stands at (0.025, 3): 0.025 m from the first
  // pass's (0, 3), 0.0375 m from the second pass's (0.0625, 3), 2 m along
  // the trail from the robot that way (8.14 m by the first pass).
  for (int i = 0; i <= 48; ++i) v.update(0.0, {0.025, 3.0}, Pose2D(0.0, 0.125 * i, 0));
  VisitorStep s;
  for (int i = 1; i <= 40; ++i) s = v.update(0.0, {0.025, 3.0}, Pose2D(0.0625, 6.0 - 0.125 * i, 0));
  // 2 m > comfortable + 0.25 = 1.35 m: it walks, towards the robot along
  // the second pass, to its point 0.5 m on, (0.0625, 2.5) — not north along
  // the first pass to (0, 3.5), the robot's old way.
  EXPECT_NEAR(s.target.x, 0.0625, 1e-12);
  EXPECT_NEAR(s.target.y, 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(s.speed, 0.7);
  // Near the robot (1 m behind it on the second pass, (0.0625, 2)): stands.
  s = v.update(0.1, {0.0625, 2.0}, Pose2D(0.0625, 1.0, 0));
  EXPECT_DOUBLE_EQ(s.speed, 0.0);
}

TEST(VisitorModel, LooksAtTheExhibitThenComesBack) {
  VisitorModel v(options(), {kA}, kB);
  // The robot waits 0.3 m from the stop (5, 0): the visitor goes to the spot.
  VisitorStep s = v.update(1.0, {3.9, 0.0}, Pose2D(5.3, 0, 0));
  EXPECT_EQ(v.state(), VisitorState::kGoToExhibit);
  EXPECT_DOUBLE_EQ(s.target.x, 5.0);
  EXPECT_DOUBLE_EQ(s.target.y, 2.0);
  s = v.update(4.0, {5.0, 2.0}, Pose2D(5.3, 0, 0));
  EXPECT_EQ(v.state(), VisitorState::kLook);
  s = v.update(9.9, {5.0, 2.0}, Pose2D(5.3, 0, 0));  // 5.9 s < 6 s of looking
  EXPECT_EQ(v.state(), VisitorState::kLook);
  EXPECT_DOUBLE_EQ(s.speed, 0.0);
  s = v.update(10.0, {5.0, 2.0}, Pose2D(5.3, 0, 0));
  EXPECT_EQ(v.state(), VisitorState::kReturn);
  EXPECT_EQ(v.looked(), 1u);
  EXPECT_DOUBLE_EQ(s.target.x, 5.3);
  // back within return_distance = 1.2 m of the robot: following again
  s = v.update(12.0, {5.3, 1.15}, Pose2D(5.3, 0, 0));
  EXPECT_EQ(v.state(), VisitorState::kFollow);
  EXPECT_FALSE(v.wandered());
}

TEST(VisitorModel, WandersAndComesBackWhenCalledOrAfterAWhile) {
  for (bool call : {true, false}) {
    VisitorModel v(options(1), {kA}, kB);
    v.update(1.0, {3.9, 0.0}, Pose2D(5.0, 0, 0));
    v.update(4.0, {5.0, 2.0}, Pose2D(5.0, 0, 0));
    VisitorStep s = v.update(10.0, {5.0, 2.0}, Pose2D(5.0, 0, 0));
    ASSERT_EQ(v.state(), VisitorState::kWander);
    EXPECT_DOUBLE_EQ(s.target.x, 9.0);  // the wander exhibit's spot
    EXPECT_DOUBLE_EQ(s.target.y, 9.0);
    v.update(20.0, {9.0, 9.0}, Pose2D(5.0, 0, 0));
    ASSERT_EQ(v.state(), VisitorState::kStay);
    v.update(44.9, {9.0, 9.0}, Pose2D(8.0, 7.8, 0));  // 24.9 s < 25 s
    if (call) v.call();
    s = v.update(45.0 - (call ? 0.05 : 0.0), {9.0, 9.0}, Pose2D(8.0, 7.8, 0));
    EXPECT_EQ(v.state(), VisitorState::kReturn) << "called " << call;
    EXPECT_EQ(v.came_back_called(), call);
    EXPECT_DOUBLE_EQ(s.target.x, 8.0);
    EXPECT_TRUE(v.wandered());
  }
}

TEST(VisitorModel, WalksRoundTheRobot) {
  VisitorModel v(options(), {kA}, kB);
  // The robot waits at (5.3, 0), the visitor comes from (5.2, -1.5):
  // straight to the spot (5, 2) would pass 0.185 m from the robot's centre
  // (closest point at t = 5.23 / 12.29 of the way), closer than 1 m. First
  // to the point 1.2 m from the robot along the way's normal
  // (-3.5, -0.2) / 3.5057 on the side of that closest point:
  // (5.3 - 1.198, -0.0685).
  const VisitorStep s = v.update(0.0, {5.2, -1.5}, Pose2D(5.3, 0, 0));
  EXPECT_EQ(v.state(), VisitorState::kGoToExhibit);
  const double l = std::hypot(0.2, 3.5);
  EXPECT_NEAR(s.target.x, 5.3 - 1.2 * 3.5 / l, 1e-9);
  EXPECT_NEAR(s.target.y, -1.2 * 0.2 / l, 1e-9);
  // from there the way to the spot passes 1.07 m from the robot: straight on
  const VisitorStep s2 = v.update(0.1, {s.target.x, s.target.y}, Pose2D(5.3, 0, 0));
  EXPECT_DOUBLE_EQ(s2.target.x, 5.0);
  EXPECT_DOUBLE_EQ(s2.target.y, 2.0);
}
