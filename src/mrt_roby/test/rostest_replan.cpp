// A path point made unreachable (fenced in by walls the planner does not
// know): its task times out, the plan is aborted, a new plan is requested
// from the current pose, and the planner's new plan is taken up.
#include <mrt_msgs/PlanRequest.h>
#include <nav_msgs/Path.h>

#include "roby_observer.h"

TEST(RobyReplan, TimeoutAbortAndReplanFromCurrentPose) {
  ros::NodeHandle nh, pnh("~");
  std::string world;
  ASSERT_TRUE(pnh.getParam("world", world));
  roby_test::Observer obs(world);
  std::vector<mrt_msgs::PlanRequest> requests;
  double truth_x_at_request = 0, truth_y_at_request = 0;
  std::vector<nav_msgs::Path> paths;
  auto rsub = nh.subscribe<mrt_msgs::PlanRequest>("replan_request", 10, [&](const mrt_msgs::PlanRequestConstPtr& r) {
    requests.push_back(*r);
    truth_x_at_request = obs.x_;
    truth_y_at_request = obs.y_;
  });
  auto psub = nh.subscribe<nav_msgs::Path>("path", 10, [&](const nav_msgs::PathConstPtr& p) { paths.push_back(*p); });
  ASSERT_TRUE(obs.wait([&] { return obs.truths_ > 0 && !obs.statuses_.empty(); }, 20.0, 60.0));
  // Path point 1 (12, 0): 8 s + 2 s/m of a ~6 m leg, ~20 s.
  ASSERT_TRUE(obs.wait([&] { return !requests.empty(); }, 90.0, 100.0)) << "no re-plan request";
  EXPECT_TRUE(obs.saw_event("task_succeeded"));  // path point 0 first
  EXPECT_TRUE(obs.saw_event("task_failed"));
  EXPECT_TRUE(obs.saw_event("plan_aborted"));
  EXPECT_TRUE(obs.saw_event("replan_requested"));
  const auto& r = requests.front();
  EXPECT_EQ(r.failed_index, 1u);
  EXPECT_NEAR(r.failed_x, 12.0, 1e-9);
  EXPECT_NEAR(r.failed_y, 0.0, 1e-9);
  // From the current pose: the localizer's estimate, within its error of the truth.
  EXPECT_NEAR(r.x, truth_x_at_request, 0.4);
  EXPECT_NEAR(r.y, truth_y_at_request, 0.4);
  // The failed task had been active for its whole timeout.
  mrt_msgs::TaskStatus failed;
  for (const auto& s : obs.statuses_)
    if (s.event == "task_failed") failed = s;
  EXPECT_EQ(failed.index, 1u);
  EXPECT_GT(failed.elapsed, failed.timeout);
  EXPECT_LT(failed.elapsed, failed.timeout + 0.5);
  // The planner answers with a new plan from there, which SCARE takes up.
  ASSERT_TRUE(obs.wait([&] { return paths.size() >= 2; }, 5.0, 20.0)) << "no new plan";
  ASSERT_EQ(paths.back().poses.size(), 1u);
  EXPECT_NEAR(paths.back().poses[0].pose.position.x, 8.0, 1e-9);
  EXPECT_NEAR(paths.back().poses[0].pose.position.y, 6.0, 1e-9);
  ASSERT_TRUE(obs.wait([&] {
    return obs.last_.state == mrt_msgs::TaskStatus::RUNNING && obs.last_.plan_size == 1 &&
           std::fabs(obs.last_.goal_x - 8.0) < 1e-9;
  }, 5.0, 20.0)) << "the new plan was not taken up";
  EXPECT_EQ(obs.last_.replans, 1u);
  RecordProperty("failed_after_s", std::to_string(failed.elapsed));
  RecordProperty("request_error_m", std::to_string(std::hypot(r.x - truth_x_at_request, r.y - truth_y_at_request)));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "roby_replan_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
