// The guide's jobs and exceptions on a scripted visitor track.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_followme/guide.h"

using namespace mrt::followme;

namespace {

const Exhibit kA{"a", {5.0, 0.0}, {5.0, 2.0}};
const Exhibit kB{"b", {10.0, 0.0}, {10.0, 2.0}};

VisitorTrack at(double x, double y, double t, double vx = 0.0, double vy = 0.0) {
  VisitorTrack v;
  v.position = {x, y};
  v.velocity = {vx, vy};
  v.last_seen = t;
  return v;
}

std::vector<Point2D> line(double x0, double x1) {
  std::vector<Point2D> p;
  for (double x = x0; x <= x1 + 1e-9; x += 1.0) p.push_back({x, 0.0});
  return p;
}

// Drives the guide from the request of a plan to the exhibit's arrival.
void guide_to(Guide& g, double& t, double x0, double x1) {
  GuideOutput out = g.update({t, Pose2D(x0, 0, 0), at(x0 - 1.0, 0, t)});
  ASSERT_TRUE(out.plan_request.has_value());
  EXPECT_DOUBLE_EQ(out.plan_request->x, x1);
  g.set_plan(line(x0, x1), t);
  ASSERT_EQ(g.job(), Job::kGuide);
  t += 0.1;
  out = g.update({t, Pose2D(x1 - 0.2, 0, 0), at(x1 - 1.2, 0, t)});
  ASSERT_EQ(g.job(), Job::kWaitVisitor);
}

// The visitor stands at the spot (x, 2) for 2.1 s: looked at it.
void look(Guide& g, double& t, double x) {
  for (int i = 0; i < 21; ++i) {
    t += 0.1;
    g.update({t, Pose2D(x - 0.2, 0, 0), at(x, 2.0, t)});
  }
}

}  // namespace

TEST(Guide, RequestsAPlanOnceAndFollowsItWithLookahead) {
  Guide g(GuideOptions{}, {kA});
  GuideOutput out = g.update({0.0, Pose2D(0, 0, 0), at(-1, 0, 0.0)});
  ASSERT_TRUE(out.plan_request.has_value());
  EXPECT_DOUBLE_EQ(out.plan_request->x, 5.0);
  EXPECT_FALSE(g.update({0.1, Pose2D(0, 0, 0), at(-1, 0, 0.1)}).plan_request.has_value());
  g.set_plan(line(0, 5), 0.1);
  ASSERT_EQ(g.job(), Job::kGuide);
  // (0,0) is within the 0.7 m lookahead, (1,0) is not: the goal is (1, 0).
  out = g.update({0.2, Pose2D(0, 0, 0), at(-1, 0, 0.2)});
  ASSERT_TRUE(out.goal.has_value());
  EXPECT_DOUBLE_EQ(out.goal->x, 1.0);
  // Robot at (1.5, 0): (1,0) is 0.5 m away, (2,0) 0.5 m, (3,0) 1.5 m.
  out = g.update({0.3, Pose2D(1.5, 0, 0), at(0.5, 0, 0.3)});
  EXPECT_DOUBLE_EQ(out.goal->x, 3.0);
}

TEST(Guide, WaitsForAVisitorLaggingBehind) {
  Guide g(GuideOptions{}, {kA});
  g.update({0.0, Pose2D(0, 0, 0), at(-1, 0, 0.0)});
  g.set_plan(line(0, 5), 0.0);
  // 3 m behind (> keep_max 2.8): stand
  GuideOutput out = g.update({0.1, Pose2D(0, 0, 0), at(-3, 0, 0.1)});
  EXPECT_FALSE(out.goal.has_value());
  EXPECT_TRUE(g.waiting_for_visitor());
  // 2.5 m (> keep_resume 2.2): still waiting; 1.5 m: go on
  EXPECT_FALSE(g.update({0.2, Pose2D(0, 0, 0), at(-2.5, 0, 0.2)}).goal.has_value());
  EXPECT_TRUE(g.update({0.3, Pose2D(0, 0, 0), at(-1.5, 0, 0.3)}).goal.has_value());
  // out of sight for 4.1 s (> lost_time 4): FollowVisitor to where it was
  g.update({4.4, Pose2D(0, 0, 0), at(-1.5, 0, 0.3)});
  EXPECT_EQ(g.job(), Job::kFollowVisitor);
  EXPECT_EQ(g.events().back().what, "lost");
}

TEST(Guide, WaitsAtTheExhibitUntilTheVisitorIsReady) {
  Guide g(GuideOptions{}, {kA, kB});
  double t = 0.0;
  guide_to(g, t, 0.0, 5.0);
  // the visitor near the robot but not yet at the spot: nothing happens
  t += 0.1;
  g.update({t, Pose2D(4.8, 0, 0), at(4.5, 0.8, t)});
  EXPECT_EQ(g.job(), Job::kWaitVisitor);
  look(g, t, 5.0);
  EXPECT_EQ(g.job(), Job::kWaitVisitor);
  // walking by at 0.7 m/s (on its way elsewhere): not ready
  t += 0.1;
  g.update({t, Pose2D(4.8, 0, 0), at(4.5, 0.8, t, 0.7, 0.0)});
  EXPECT_EQ(g.job(), Job::kWaitVisitor);
  // standing at (4.5, 0.8): 1.30 m from the spot (> 0.5), 0.85 m from the
  // robot (< ready_distance 2.4): visited, re-plan for b
  t += 0.1;
  g.update({t, Pose2D(4.8, 0, 0), at(4.5, 0.8, t)});
  EXPECT_EQ(g.job(), Job::kReplan);
  ASSERT_EQ(g.visited().size(), 1u);
  EXPECT_EQ(g.visited()[0], "a");
  EXPECT_EQ(g.current(), 1u);
}

TEST(Guide, FollowsAWanderingVisitorCallsItAndReplans) {
  Guide g(GuideOptions{}, {kA, kB});
  double t = 0.0;
  guide_to(g, t, 0.0, 5.0);
  look(g, t, 5.0);
  // off to (5, 6): 4 m from the spot, 6 m from the robot (> 3 both)
  t += 0.1;
  g.update({t, Pose2D(4.8, 0, 0), at(5.0, 6.0, t, 0.0, 0.7)});
  ASSERT_EQ(g.job(), Job::kFollowVisitor);
  EXPECT_EQ(g.visited().size(), 1u);  // it had looked at a
  // follow: the point 2.8 m short of the visitor on the line from the robot
  t += 0.1;
  GuideOutput out = g.update({t, Pose2D(4.8, 0, 0), at(5.0, 6.0, t)});
  ASSERT_TRUE(out.goal.has_value());
  const double d = std::hypot(0.2, 6.0), k = (d - 2.8) / d;
  EXPECT_NEAR(out.goal->x, 4.8 + 0.2 * k, 1e-9);
  EXPECT_NEAR(out.goal->y, 6.0 * k, 1e-9);
  // 2.8 m from it, the visitor standing: no call before 6 s, then one
  int calls = 0;
  double first_call = -1.0;
  for (int i = 0; i < 70; ++i) {
    t += 0.1;
    if (g.update({t, Pose2D(5.0, 3.2, 0), at(5.0, 6.0, t)}).call_visitor) {
      ++calls;
      if (first_call < 0) first_call = t;
    }
  }
  EXPECT_EQ(calls, 1);
  EXPECT_NEAR(first_call - (t - 7.0), 6.0, 0.11);
  EXPECT_EQ(g.job(), Job::kFollowVisitor);  // called, not yet back
  // it comes back to 2.3 m (< ready_distance 2.4): re-plan the tour from
  // here, one wander handled
  for (int i = 0; i < 11 && g.job() == Job::kFollowVisitor; ++i) {
    t += 0.1;
    g.update({t, Pose2D(5.0, 3.2, 0), at(5.0, 5.5, t)});
  }
  EXPECT_EQ(g.job(), Job::kReplan);
  EXPECT_EQ(g.wanders(), 1u);
  EXPECT_EQ(g.current(), 1u);
  const auto out2 = g.update({t + 0.1, Pose2D(5.0, 3.2, 0), at(5.0, 5.5, t + 0.1)});
  ASSERT_TRUE(out2.plan_request.has_value());
  EXPECT_DOUBLE_EQ(out2.plan_request->x, 10.0);
}
