// The facts SCARE's task machines read (tour_facts.h), worked out by hand
// with the default GuideOptions: look_radius 1 m, look_time 2 s,
// ready_distance 2.4 m, wander_distance 3 m, keep_max 2.8 m, keep_resume
// 2.2 m, still_speed 0.15 m/s, call_after 6 s, lost_time 4 s.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_followme/tour_facts.h"

namespace mrt::followme {
namespace {

const Exhibit kStatue{"statue", {4.0, 4.0}, {3.0, 2.0}};  // stop, spot

TEST(TourFacts, LookedThenReady) {
  TourFactsTracker f(GuideOptions{});
  f.set_exhibit(kStatue);
  const Pose2D robot(4.0, 4.0, 0.0);
  // Visitor 0.5 m from the spot, hypot(1, 1.5) = 1.803 m from the robot.
  TourFacts a = f.update(0.0, robot, Point2D{3.0, 2.5}, 0.0);
  EXPECT_NEAR(a.exhibit_distance, 0.0, 1e-12);
  EXPECT_NEAR(a.visitor_distance, 1.8028, 1e-4);
  EXPECT_NEAR(a.visitor_bearing, std::atan2(-1.5, -1.0), 1e-12);  // -2.159 rad: behind, right
  EXPECT_TRUE(a.back);
  EXPECT_FALSE(a.looked);
  EXPECT_FALSE(f.update(1.0, robot, Point2D{3.0, 2.5}, 0.0).looked);  // 1 s of 2
  TourFacts c = f.update(2.0, robot, Point2D{3.0, 2.5}, 0.0);        // 2 s: looked
  EXPECT_TRUE(c.looked);
  EXPECT_FALSE(c.ready);  // still on the spot (0.5 m, not more than half the look radius)
  EXPECT_FALSE(c.wandered);
  // Left the spot (hypot(0.5, 1.5) = 1.58 m), stands 0.71 m from the robot: ready.
  EXPECT_TRUE(f.update(3.0, robot, Point2D{3.5, 3.5}, 0.0).ready);
  // ... but not while walking past (0.5 m/s).
  EXPECT_FALSE(f.update(3.1, robot, Point2D{3.5, 3.5}, 0.5).ready);
  f.set_exhibit(kStatue);  // a new exhibit: looked again from 0
  EXPECT_FALSE(f.update(3.5, robot, Point2D{3.0, 2.5}, 0.0).looked);
}

TEST(TourFacts, WanderedLaggingBack) {
  TourFactsTracker f(GuideOptions{});
  f.set_exhibit(kStatue);
  const Pose2D robot(4.0, 4.0, 0.0);
  // 5 m from the robot, hypot(6, 2) = 6.32 m from the spot, standing: wandered, lagging.
  TourFacts w = f.update(3.0, robot, Point2D{9.0, 4.0}, 0.1);
  EXPECT_TRUE(w.wandered);
  EXPECT_TRUE(w.lagging);
  EXPECT_FALSE(w.back);
  EXPECT_FALSE(f.update(3.2, robot, Point2D{9.0, 4.0}, 0.5).wandered);  // walking: not (yet)
  // 2.5 m: neither beyond keep_max nor within keep_resume: still lagging.
  EXPECT_TRUE(f.update(3.5, robot, Point2D{6.5, 4.0}, 0.5).lagging);
  // 2 m: back, no longer lagging.
  TourFacts b = f.update(4.0, robot, Point2D{6.0, 4.0}, 0.5);
  EXPECT_FALSE(b.lagging);
  EXPECT_TRUE(b.back);
  EXPECT_FALSE(b.wandered);
  // Unseen since t = 4: 3 s is not lost, 4.5 s is (lost_time 4 s).
  EXPECT_FALSE(f.update(7.0, robot, std::nullopt, 0.0).wandered);
  const TourFacts lost = f.update(8.5, robot, std::nullopt, 0.0);
  EXPECT_TRUE(lost.wandered);
  EXPECT_TRUE(lost.lost);
  EXPECT_FALSE(b.lost);
}

TEST(TourFacts, NotLostBeforeLostTimeOfLooking) {
  TourFactsTracker f(GuideOptions{});
  f.set_exhibit(kStatue);
  const Pose2D robot(4.0, 4.0, 0.0);
  EXPECT_FALSE(f.update(100.0, robot, std::nullopt, 0.0).lost);  // never seen yet, but just started
  EXPECT_FALSE(f.update(104.0, robot, std::nullopt, 0.0).lost);  // 4 s: not more than lost_time
  EXPECT_TRUE(f.update(104.5, robot, std::nullopt, 0.0).lost);
}

TEST(TourFacts, StillAfterCallAfterAndExhibitDistance) {
  TourFactsTracker f(GuideOptions{});
  f.set_exhibit(kStatue);
  const Pose2D robot(1.0, 0.0, 0.0);  // 5 m from the stop (3-4-5)
  EXPECT_NEAR(f.update(10.0, robot, Point2D{1.0, 2.0}, 0.1).exhibit_distance, 5.0, 1e-12);
  EXPECT_FALSE(f.update(15.9, robot, Point2D{1.0, 2.0}, 0.1).still);  // 5.9 s still
  EXPECT_TRUE(f.update(16.0, robot, Point2D{1.0, 2.0}, 0.1).still);   // 6 s
  EXPECT_FALSE(f.update(16.1, robot, Point2D{1.0, 2.0}, 0.5).still);  // walks
}

}  // namespace
}  // namespace mrt::followme
