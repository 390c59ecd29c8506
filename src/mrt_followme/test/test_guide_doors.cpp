// The guide's doors and the distributed bringup's way of driving it
// (guide_node): a door closed on the leg re-planned at once (the in-process
// loop, whose planner has the door's wall) or after a delay (SPIKE told by
// percepts), the closed doors' walls as obstacle discs, and MAP's track of
// the visitor fed to the tracker the guide reads. Expected values by hand,
// default GuideOptions (lookahead 0.7 m, arrive_tolerance 0.3 m, lost_time
// 4 s, follow_distance 2.8 m).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mrt_followme/guide.h"
#include "mrt_followme/visitor_tracker.h"

using namespace mrt::followme;

namespace {

const Exhibit kA{"a", {5.0, 0.0}, {5.0, 2.0}};
const Door kNorth{"north_door", {10.0, 8.5}, {10.0, 9.6}};  // the museum's

VisitorTrack at(double x, double y, double t) {
  VisitorTrack v;
  v.position = {x, y};
  v.last_seen = t;
  return v;
}

std::vector<Point2D> line(double x0, double x1) {
  std::vector<Point2D> p;
  for (double x = x0; x <= x1 + 1e-9; x += 1.0) p.push_back({x, 0.0});
  return p;
}

// A guide on the leg to a: plan (0,0) ... (5,0), the robot at (1, 0).
Guide guiding() {
  Guide g(GuideOptions{}, {kA});
  g.update({0.0, Pose2D(0, 0, 0), at(-1, 0, 0.0)});
  g.set_plan(line(0, 5), 0.0);
  EXPECT_EQ(g.job(), Job::kGuide);
  return g;
}

}  // namespace

// North door: 1.1 m long, ceil(1.1 / 0.25) + 1 = 6 discs, 0.22 m apart, at
// y = 8.5, 8.72, 8.94, 9.16, 9.38, 9.6 on x = 10, named north_door_0 ... 5.
// A 0.1 m door still gets its two ends; a 0.5 m one ceil(2) + 1 = 3.
TEST(GuideDoors, DoorWallAsDiscs) {
  const auto discs = door_discs(kNorth);
  ASSERT_EQ(discs.size(), 6u);
  const double ys[] = {8.5, 8.72, 8.94, 9.16, 9.38, 9.6};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(discs[i].name, "north_door_" + std::to_string(i));
    EXPECT_DOUBLE_EQ(discs[i].center.x, 10.0);
    EXPECT_NEAR(discs[i].center.y, ys[i], 1e-12);
    EXPECT_DOUBLE_EQ(discs[i].radius, 0.2);
  }
  const auto narrow = door_discs(Door{"n", {0.0, 0.0}, {0.1, 0.0}});
  ASSERT_EQ(narrow.size(), 2u);
  EXPECT_DOUBLE_EQ(narrow[1].center.x, 0.1);
  const auto wide = door_discs(Door{"w", {0.0, 0.0}, {0.5, 0.0}}, 0.25, 0.3);
  ASSERT_EQ(wide.size(), 3u);
  EXPECT_DOUBLE_EQ(wide[1].center.x, 0.25);
  EXPECT_DOUBLE_EQ(wide[2].radius, 0.3);
}

// In process: the planner has the door's wall when it is closed, so the leg
// is re-planned at once (the next update asks for the same stop again).
TEST(GuideDoors, DoorClosedOnTheLegReplansAtOnce) {
  Guide g = guiding();
  ASSERT_TRUE(g.update({0.1, Pose2D(1, 0, 0), at(0, 0, 0.1)}).goal.has_value());
  g.close_door(kNorth, 0.2);
  EXPECT_EQ(g.job(), Job::kReplan);
  EXPECT_TRUE(g.plan().empty());
  EXPECT_EQ(g.events().back().what, "door_closed");
  EXPECT_DOUBLE_EQ(g.events().back().t, 0.2);
  ASSERT_EQ(g.closed_doors().size(), 1u);
  EXPECT_EQ(g.closed_doors()[0].name, "north_door");
  const GuideOutput out = g.update({0.3, Pose2D(1, 0, 0), at(0, 0, 0.3)});
  ASSERT_TRUE(out.plan_request.has_value());
  EXPECT_DOUBLE_EQ(out.plan_request->x, 5.0);
  EXPECT_EQ(g.replans(), 1u);  // the re-plan for the door (the first leg was no re-plan)
}

// Distributed: SPIKE learns of the door from its percepts, so the guide
// re-plans 0.5 s later: closed at 1.0, still guiding at 1.4 (goal (2, 0):
// (1, 0) is 0.2 m from the robot at 1.2, within the 0.7 m lookahead, (2, 0)
// 0.8 m), re-planned at
// the first update from 1.5 on, asking at once for the same stop.
TEST(GuideDoors, DoorClosedReplansAfterTheDelay) {
  Guide g = guiding();
  g.close_door(kNorth, 1.0, 0.5);
  EXPECT_EQ(g.job(), Job::kGuide);
  GuideOutput out = g.update({1.4, Pose2D(1.2, 0, 0), at(0.5, 0, 1.4)});
  EXPECT_EQ(g.job(), Job::kGuide);
  ASSERT_TRUE(out.goal.has_value());
  EXPECT_DOUBLE_EQ(out.goal->x, 2.0);
  out = g.update({1.5, Pose2D(1.3, 0, 0), at(0.5, 0, 1.5)});
  EXPECT_EQ(g.job(), Job::kReplan);
  EXPECT_EQ(g.events().back().what, "door_closed");
  EXPECT_DOUBLE_EQ(g.events().back().t, 1.5);
  ASSERT_TRUE(out.plan_request.has_value());
  EXPECT_DOUBLE_EQ(out.plan_request->x, 5.0);
  // Once only: the new plan is followed.
  g.set_plan(line(1, 5), 1.6);
  g.update({1.7, Pose2D(1.3, 0, 0), at(0.5, 0, 1.7)});
  EXPECT_EQ(g.job(), Job::kGuide);
  // A door closed while the robot waits at the exhibit re-plans nothing
  // (the next leg is planned with it).
  Guide w = guiding();
  w.update({0.1, Pose2D(4.9, 0, 0), at(4.0, 0, 0.1)});
  ASSERT_EQ(w.job(), Job::kWaitVisitor);
  w.close_door(kNorth, 0.2, 0.5);
  w.update({0.8, Pose2D(4.9, 0, 0), at(4.0, 0, 0.8)});
  EXPECT_EQ(w.job(), Job::kWaitVisitor);
}

// MAP's track (guide_node): positions observed at 10 Hz become the track the
// guide reads. Walking 0.5 m/s along +x from (0, 0) at t = 0 ... 1.0, then
// MAP loses it: at 4.9 s (3.9 s unseen) the guide still guides, standing
// (out of sight more than 1 s); at 5.1 s (4.1 s > lost_time 4) it follows
// the visitor to where it was last seen, (0.5, 0), keeping 1 m (out of
// sight): the robot at (4, 0), 3.5 m away, heads for (1.5, 0).
TEST(GuideDoors, MapTrackDrivesTheGuide) {
  VisitorTracker map_track("purple");
  for (int i = 0; i <= 10; ++i) map_track.observe(0.1 * i, {0.05 * i, 0.0});
  ASSERT_TRUE(map_track.track().has_value());
  EXPECT_NEAR(map_track.track()->velocity.x, 0.5, 1e-9);  // 0.5 m over 1.0 s
  EXPECT_NEAR(map_track.track()->speed(), 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(map_track.track()->last_seen, 1.0);
  Guide g = guiding();
  GuideOutput out = g.update({4.9, Pose2D(4.0, 0, 0), map_track.track()});
  EXPECT_EQ(g.job(), Job::kGuide);
  EXPECT_FALSE(out.goal.has_value());
  EXPECT_TRUE(g.waiting_for_visitor());
  g.update({5.1, Pose2D(4.0, 0, 0), map_track.track()});
  ASSERT_EQ(g.job(), Job::kFollowVisitor);
  EXPECT_EQ(g.events().back().what, "lost");
  out = g.update({5.2, Pose2D(4.0, 0, 0), map_track.track()});
  ASSERT_TRUE(out.goal.has_value());
  EXPECT_NEAR(out.goal->x, 1.5, 1e-9);
  EXPECT_NEAR(out.goal->y, 0.0, 1e-12);
  EXPECT_TRUE(out.call_visitor);  // lost, not wandering: called at once
}
