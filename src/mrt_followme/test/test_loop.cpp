// FollowMe in closed loop (mrt_sim museum, MUREA, SPIKE, the guide, Mr.
// BRIAN with Roby's rules): the two scenarios, measured on the
// simulator's ground truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "mrt_followme/followme_loop.h"

using namespace mrt::followme;

namespace {

FollowMeLoopOptions options() {
  FollowMeLoopOptions o;
  const std::string root = MRT_FOLLOWME_ROOT;
  o.world = MRT_WORLDS_DIR "/museum.yaml";
  o.config = root + "/config/followme.yaml";
  o.brian = root + "/config/brian/BrianConfigs.ini";
  o.packages = {{"mrt_roby", MRT_ROBY_DIR}};
  o.duration = 400.0;
  return o;
}

std::size_t find_event(const FollowMeResult& r, const std::string& what, std::size_t from = 0) {
  for (std::size_t i = from; i < r.events.size(); ++i)
    if (r.events[i].what == what) return i;
  return r.events.size();
}

bool crosses(const std::vector<Point2D>& plan, double x_line, double y0, double y1) {
  for (std::size_t i = 1; i < plan.size(); ++i) {
    const Point2D a = plan[i - 1], b = plan[i];
    if ((a.x - x_line) * (b.x - x_line) > 0 || a.x == b.x) continue;
    const double y = a.y + (b.y - a.y) * (x_line - a.x) / (b.x - a.x);
    if (y >= y0 && y <= y1) return true;
  }
  return false;
}

}  // namespace

// A 4-exhibit tour; the visitor wanders off to the globe after the second.
TEST(FollowMeLoop, TourWithOneWander) {
  const FollowMeResult r = run_followme_loop(options());
  for (const auto& e : r.events) std::printf("%7.1f %-12s %s\n", e.t, e.what.c_str(), e.exhibit.c_str());
  ASSERT_TRUE(r.completed) << "visitor " << r.visitor_state << " at t " << r.time;
  // every exhibit, in the order of the tour
  const std::vector<std::string> tour{"statue", "pedestal", "sculpture", "vase"};
  EXPECT_EQ(r.visited, tour);
  // it waited at each: one WaitVisitor per exhibit, each at least the 2 s
  // of looking the guide asks for
  ASSERT_EQ(r.waits.size(), 4u);
  for (double w : r.waits) EXPECT_GE(w, 2.0);
  // the wander: noticed, followed (goals given while following), called,
  // back, then a new plan
  EXPECT_EQ(r.wanders, 1u);
  EXPECT_GT(r.follow_goals, 0u);
  const std::size_t wander = find_event(r, "wander");
  const std::size_t call = find_event(r, "call", wander);
  const std::size_t back = find_event(r, "back", call);
  ASSERT_LT(back, r.events.size());
  EXPECT_LT(find_event(r, "guide", back), r.events.size());
  EXPECT_GE(r.plans.size(), 4u);
  // the bounds
  EXPECT_LE(r.max_unseen, 10.0);
  EXPECT_GE(r.min_person_gap, 0.3) << r.nearest_person;
  EXPECT_LT(r.max_pose_error, 0.10);
  std::printf("time %.1f s, unseen %.1f s, person gap %.2f m, clearance %.2f m, pose error %.3f m\n", r.time,
              r.max_unseen, r.min_person_gap, r.min_clearance, r.max_pose_error);
}

// The north door (between the pedestal's and the sculpture's rooms) closes
// as the leg to the sculpture starts: SPIKE re-plans through the others.
TEST(FollowMeLoop, ClosedDoorReplansThroughAnotherDoor) {
  FollowMeLoopOptions o = options();
  o.tour = {"pedestal", "sculpture"};
  o.wander_after = 0;
  o.close_door = "north_door";
  o.close_at_leg = 1;
  const FollowMeResult r = run_followme_loop(o);
  for (const auto& e : r.events) std::printf("%7.1f %-12s %s\n", e.t, e.what.c_str(), e.exhibit.c_str());
  ASSERT_TRUE(r.completed) << "at t " << r.time;
  ASSERT_GE(r.plans.size(), 3u);
  // the first plan to the sculpture went through the north door (x = 10,
  // y in [8.5, 9.6]); the one after the closing through the south door
  // (y in [2.5, 3.5]).
  const std::size_t closed = find_event(r, "door_closed");
  ASSERT_LT(closed, r.events.size());
  EXPECT_TRUE(crosses(r.plans[1], 10.0, 8.5, 9.6));
  EXPECT_FALSE(crosses(r.plans[2], 10.0, 8.5, 9.6));
  EXPECT_TRUE(crosses(r.plans[2], 10.0, 2.5, 3.5));
  // and the robot went that way
  std::vector<std::string> doors;
  for (const auto& d : r.doors) doors.push_back(d.door);
  EXPECT_EQ(std::count(doors.begin(), doors.end(), "north_door"), 0);
  EXPECT_GE(std::count(doors.begin(), doors.end(), "south_door"), 1);
  EXPECT_EQ(r.visited, (std::vector<std::string>{"pedestal", "sculpture"}));
  EXPECT_GE(r.min_person_gap, 0.3) << r.nearest_person;
}
