// The sequencer's state machines: success, timeout, abort, re-plan, manual
// suspension. Expected values are worked by hand from the task definitions.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_scare/sequencer.h"

using namespace mrt::scare;
using T = SequencerEvent::Type;

namespace {

bool has(const std::vector<SequencerEvent>& ev, T t) {
  for (const auto& e : ev)
    if (e.type == t) return true;
  return false;
}

SequencerOptions opts(double tol = 0.5, double timeout = 10.0, double per_metre = 0.0) {
  SequencerOptions o;
  o.path_task = TaskSpec::reach_path_point(tol, timeout, per_metre);
  return o;
}

}  // namespace

TEST(Task, SucceedsWithinTolerance) {
  Task t(TaskSpec::reach_path_point(0.5, 10.0), {3.0, 4.0}, 0);
  t.activate(0.0, Pose2D(0, 0, 0));
  EXPECT_DOUBLE_EQ(t.start_distance(), 5.0);
  EXPECT_EQ(t.update(1.0, Pose2D(2.0, 4.0, 0)), TaskState::kActive);   // 1 m away
  EXPECT_EQ(t.update(2.0, Pose2D(3.0, 3.5, 0)), TaskState::kSucceeded); // exactly 0.5 m
  EXPECT_EQ(t.update(30.0, Pose2D(0, 0, 0)), TaskState::kSucceeded);    // terminal
}

TEST(Task, FailsAfterTimeoutPlusPerMetre) {
  // 10 s + 2 s/m * 5 m = 20 s.
  Task t(TaskSpec::reach_path_point(0.5, 10.0, 2.0), {3.0, 4.0}, 0);
  t.activate(100.0, Pose2D(0, 0, 0));
  EXPECT_DOUBLE_EQ(t.timeout(), 20.0);
  EXPECT_EQ(t.update(120.0, Pose2D(0, 0, 0)), TaskState::kActive);   // not > 20 yet
  EXPECT_EQ(t.update(120.001, Pose2D(0, 0, 0)), TaskState::kFailed);
}

TEST(Task, SuspendedTimeDoesNotCount) {
  Task t(TaskSpec::reach_path_point(0.5, 10.0), {10.0, 0.0}, 0);
  t.activate(0.0, Pose2D(0, 0, 0));
  t.suspend(5.0);
  EXPECT_EQ(t.update(50.0, Pose2D(0, 0, 0)), TaskState::kActive);  // no timeout while suspended
  EXPECT_DOUBLE_EQ(t.elapsed(50.0), 5.0);
  t.resume(50.0);
  EXPECT_DOUBLE_EQ(t.elapsed(54.0), 9.0);
  EXPECT_EQ(t.update(54.0, Pose2D(0, 0, 0)), TaskState::kActive);
  EXPECT_EQ(t.update(55.5, Pose2D(0, 0, 0)), TaskState::kFailed);  // 10.5 s active
  // Reaching the point while suspended (a person drove there) still succeeds.
  Task u(TaskSpec::reach_path_point(0.5, 10.0), {1.0, 0.0}, 0);
  u.activate(0.0, Pose2D(0, 0, 0));
  u.suspend(1.0);
  EXPECT_EQ(u.update(2.0, Pose2D(0.9, 0, 0)), TaskState::kSucceeded);
}

TEST(Sequencer, ReachesEveryPathPointInOrder) {
  Sequencer s(opts());
  auto ev = s.set_plan({{1, 0}, {2, 0}, {2, 2}}, 0.0, Pose2D(0, 0, 0));
  ASSERT_TRUE(has(ev, T::kPlanAccepted));
  ASSERT_TRUE(has(ev, T::kTaskStarted));
  EXPECT_EQ(s.state(), SequencerState::kRunning);
  ASSERT_NE(s.active(), nullptr);
  EXPECT_EQ(s.active()->index(), 0u);

  ev = s.update(1.0, Pose2D(0.6, 0, 0));
  EXPECT_TRUE(has(ev, T::kTaskSucceeded));
  EXPECT_EQ(s.active()->index(), 1u);
  EXPECT_DOUBLE_EQ(s.active()->goal().x, 2.0);

  s.update(2.0, Pose2D(1.9, 0.1, 0));
  EXPECT_EQ(s.active()->index(), 2u);
  ev = s.update(3.0, Pose2D(2.0, 1.8, 0));
  EXPECT_TRUE(has(ev, T::kRouteCompleted));
  EXPECT_EQ(s.state(), SequencerState::kDone);
  EXPECT_EQ(s.reached(), 3u);
  EXPECT_EQ(s.active(), nullptr);
}

TEST(Sequencer, SeveralPointsReachedInOneUpdate) {
  Sequencer s(opts(0.5));
  s.set_plan({{1, 0}, {1.2, 0}, {5, 0}}, 0.0, Pose2D(0, 0, 0));
  auto ev = s.update(1.0, Pose2D(1.1, 0, 0));
  EXPECT_EQ(s.reached(), 2u);
  EXPECT_EQ(s.active()->index(), 2u);
}

TEST(Sequencer, TimeoutAbortsAndRequestsReplanFromCurrentPose) {
  Sequencer s(opts(0.5, 10.0));
  s.set_plan({{1, 0}, {20, 0}, {30, 0}}, 0.0, Pose2D(0, 0, 0));
  s.update(2.0, Pose2D(0.8, 0, 0));  // point 0 reached at t = 2: point 1 starts
  ASSERT_EQ(s.active()->index(), 1u);
  auto ev = s.update(11.9, Pose2D(5, 1, 0.3));
  EXPECT_TRUE(ev.empty());
  ev = s.update(12.1, Pose2D(6, 1.5, 0.2));  // 10.1 s on point 1
  ASSERT_TRUE(has(ev, T::kTaskFailed));
  ASSERT_TRUE(has(ev, T::kPlanAborted));
  ASSERT_TRUE(has(ev, T::kReplanRequested));
  for (const auto& e : ev)
    if (e.type == T::kReplanRequested) {
      EXPECT_DOUBLE_EQ(e.pose.x, 6.0);  // from the current pose
      EXPECT_DOUBLE_EQ(e.pose.y, 1.5);
      EXPECT_EQ(e.index, 1u);           // the failed path point
      EXPECT_DOUBLE_EQ(e.point.x, 20.0);
    }
  EXPECT_EQ(s.state(), SequencerState::kWaitingForPlan);
  EXPECT_EQ(s.active(), nullptr);
  EXPECT_EQ(s.failed(), 1u);
  EXPECT_EQ(s.replans(), 1u);
  // Nothing happens while the planner has replan_timeout (10 s) to answer;
  // then the request goes again, from the pose at that time.
  EXPECT_TRUE(s.update(22.0, Pose2D(6, 1.5, 0)).empty());
  ev = s.update(22.2, Pose2D(6.5, 1.0, 0));
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].type, T::kReplanRequested);
  EXPECT_DOUBLE_EQ(ev[0].pose.x, 6.5);
  EXPECT_DOUBLE_EQ(ev[0].pose.y, 1.0);
  EXPECT_EQ(ev[0].index, 1u);
  EXPECT_DOUBLE_EQ(ev[0].point.x, 20.0);
  EXPECT_EQ(s.replans(), 1u);  // one aborted plan, asked twice
  EXPECT_TRUE(s.update(32.0, Pose2D(6.5, 1.0, 0)).empty());
  ev = s.set_plan({{30, 0}}, 51.0, Pose2D(6, 1.5, 0));
  EXPECT_EQ(s.state(), SequencerState::kRunning);
  EXPECT_EQ(s.active()->index(), 0u);
  EXPECT_DOUBLE_EQ(s.active()->goal().x, 30.0);
}

TEST(Sequencer, GivesUpAfterMaxReplans) {
  SequencerOptions o = opts(0.5, 1.0);
  o.max_replans = 2;
  Sequencer s(o);
  double t = 0.0;
  for (int k = 0; k < 2; ++k) {
    s.set_plan({{10, 0}}, t, Pose2D(0, 0, 0));
    auto ev = s.update(t + 1.5, Pose2D(0, 0, 0));
    EXPECT_TRUE(has(ev, T::kReplanRequested));
    t += 2.0;
  }
  s.set_plan({{10, 0}}, t, Pose2D(0, 0, 0));
  auto ev = s.update(t + 1.5, Pose2D(0, 0, 0));
  EXPECT_TRUE(has(ev, T::kGaveUp));
  EXPECT_FALSE(has(ev, T::kReplanRequested));
  EXPECT_EQ(s.state(), SequencerState::kGaveUp);
  // A plan from outside (not an answer to a re-plan request) starts afresh:
  // its first failure asks for a re-plan again.
  s.set_plan({{10, 0}}, t + 2.0, Pose2D(0, 0, 0));
  ev = s.update(t + 3.5, Pose2D(0, 0, 0));
  EXPECT_TRUE(has(ev, T::kReplanRequested));
  EXPECT_FALSE(has(ev, T::kGaveUp));
}

TEST(Sequencer, SkipPolicyGoesToNextPoint) {
  SequencerOptions o = opts(0.5, 1.0);
  o.path_task.on_failure = OnFailure::kSkip;
  Sequencer s(o);
  s.set_plan({{10, 0}, {20, 0}}, 0.0, Pose2D(0, 0, 0));
  auto ev = s.update(1.5, Pose2D(0, 0, 0));
  EXPECT_TRUE(has(ev, T::kTaskFailed));
  EXPECT_FALSE(has(ev, T::kPlanAborted));
  EXPECT_EQ(s.active()->index(), 1u);
}

TEST(Sequencer, ManualModeSuspendsTheTimeout) {
  Sequencer s(opts(0.5, 10.0));
  s.set_plan({{10, 0}}, 0.0, Pose2D(0, 0, 0));
  s.set_mode(Mode::kManual, 5.0);
  EXPECT_TRUE(s.active()->suspended());
  EXPECT_TRUE(s.update(100.0, Pose2D(1, 0, 0)).empty());
  s.set_mode(Mode::kAuto, 100.0);
  EXPECT_TRUE(s.update(104.0, Pose2D(1, 0, 0)).empty());   // 9 s active
  EXPECT_TRUE(has(s.update(105.5, Pose2D(1, 0, 0)), T::kTaskFailed));
}

TEST(Sequencer, NewPlanReplacesRunningOne) {
  Sequencer s(opts());
  s.set_plan({{10, 0}, {20, 0}}, 0.0, Pose2D(0, 0, 0));
  s.set_plan({{0, 5}}, 1.0, Pose2D(0, 0, 0));
  EXPECT_EQ(s.plans(), 2u);
  EXPECT_DOUBLE_EQ(s.active()->goal().y, 5.0);
  s.set_plan({}, 2.0, Pose2D(0, 0, 0));
  EXPECT_EQ(s.state(), SequencerState::kIdle);
  EXPECT_EQ(s.active(), nullptr);
}

TEST(GoalCrisp, DistanceAndBearingInRuleBaseUnits) {
  // Robot at (1, 1) facing +y; goal at (0, 1): 1 m, 90 deg to the left.
  GoalCrisp g = goal_crisp(Pose2D(1, 1, M_PI / 2), {0, 1});
  EXPECT_NEAR(g.distance_cm, 100.0, 1e-9);
  EXPECT_NEAR(g.bearing_deg, 90.0, 1e-9);
  g = goal_crisp(Pose2D(0, 0, 0), {-3, 0});
  EXPECT_NEAR(g.bearing_deg, 180.0, 1e-9);  // behind: +180, never -180
  g = goal_crisp(Pose2D(0, 0, 0), {3, -3});
  EXPECT_NEAR(g.bearing_deg, -45.0, 1e-9);
  EXPECT_NEAR(g.distance_cm, 100.0 * std::sqrt(18.0), 1e-9);
}
