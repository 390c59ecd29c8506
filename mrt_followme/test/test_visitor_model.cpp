// The visitor behaviour model, decision by decision, against hand-worked
// positions.
#include <gtest/gtest.h>

#include "mrt_followme/visitor_model.h"

using namespace mrt::followme;

namespace {

VisitorOptions options(int wander_after = 0) {
  VisitorOptions o;
  o.comfortable = 1.1;
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
  // Trail from the newest point: (2,3)-(2,2) is 1 m < 1.1, plus (2,2)-(2,1)
  // makes 2 m: the point (2, 1), 3.16 m from the visitor, nearer than the
  // robot (4.24 m). A straight line would cut the corner to (1.22, 2.22).
  EXPECT_NEAR(s.target.x, 2.0, 1e-12);
  EXPECT_NEAR(s.target.y, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.speed, 0.7);
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
  // back within comfortable + 0.1 = 1.2 m of the robot: following again
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
