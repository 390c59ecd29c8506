// The Sequencer running YAML task machines: path points and jobs, success,
// failure from the world model, timeout, retry count, re-plan, hand-back,
// abort, Manual mode. Every time and distance below is worked by hand.
#include <gtest/gtest.h>

#include <stdexcept>

#include "mrt_common/parse_error.h"
#include "mrt_scare/sequencer.h"
#include "mrt_scare/task_config.h"

using namespace mrt::scare;
using T = SequencerEvent::Type;

namespace {

// Reach: success within 50 cm, failure when the world says Blocked -> hand
// back, 10 s timeout -> re-plan. Approach: 4 s timeout retried twice, then
// abort; BallLost -> abort. Shoot: 3 s timeout -> re-plan.
const char* kYaml = R"Y(
fuzzy:
  shapes: |
    (UNIT (TOR (HIGH 0 1)))
    (CM (REC (ARRIVED 0 50)))
  data: "(GoalDistance CM) (Blocked UNIT) (BallNear UNIT) (BallLost UNIT) (Kicked UNIT)"
tasks:
  Reach:
    states:
      go:
        success: (D GoalDistance ARRIVED)
        failure: (D Blocked HIGH)
        timeout: 10
        on_failure: hand_back
        on_timeout: replan
  Approach:
    states:
      approach:
        success: (D BallNear HIGH)
        failure: (D BallLost HIGH)
        timeout: 4
        on_timeout: retry
        retries: 2
  Shoot:
    states:
      shoot:
        success: (D Kicked HIGH)
        timeout: 3
        on_timeout: replan
jobs:
  BringBall: [Approach, Shoot]
  PassageToMate.passer: [Shoot]
path_task: Reach
max_replans: 1
replan_timeout: 0
)Y";

Sequencer make() { return Sequencer(parse_sequencer_options(kYaml, "m.yaml")); }

std::vector<T> types(const std::vector<SequencerEvent>& ev) {
  std::vector<T> t;
  for (const auto& e : ev) t.push_back(e.type);
  return t;
}

const Pose2D kOrigin{0.0, 0.0, 0.0};

std::string error_of(const std::string& yaml) {
  try {
    parse_sequencer_options(yaml, "m.yaml");
  } catch (const mrt::common::ParseError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(SequencerMachine, PathPointsSucceedInOrder) {
  Sequencer seq = make();
  // Point 0 at 100 cm: not arrived.
  EXPECT_EQ(types(seq.set_plan({{1, 0}, {3, 0}}, 0.0, kOrigin)), (std::vector<T>{T::kPlanAccepted, T::kTaskStarted}));
  // At (0.6, 0): 40 cm <= 50 -> point 0 reached, point 1 (240 cm) started.
  auto ev = seq.update(1.0, {0.6, 0.0, 0.0});
  EXPECT_EQ(types(ev), (std::vector<T>{T::kTaskSucceeded, T::kTaskStarted}));
  EXPECT_EQ(ev[0].task, "Reach");
  EXPECT_EQ(ev[0].reason, "success");
  EXPECT_EQ(seq.active_state(), "go");
  // At (2.5, 0): exactly 50 cm, inside ARRIVED [0, 50].
  EXPECT_EQ(types(seq.update(2.0, {2.5, 0.0, 0.0})), (std::vector<T>{T::kTaskSucceeded, T::kRouteCompleted}));
  EXPECT_EQ(seq.state(), SequencerState::kDone);
  EXPECT_EQ(seq.reached(), 2u);
}

TEST(SequencerMachine, TimeoutReplansThenGivesUp) {
  Sequencer seq = make();
  seq.set_plan({{10, 0}}, 0.0, kOrigin);
  EXPECT_DOUBLE_EQ(seq.active_timeout(), 10.0);
  EXPECT_TRUE(seq.update(10.0, kOrigin).empty());  // exactly 10 s: not yet
  auto ev = seq.update(10.5, kOrigin);
  EXPECT_EQ(types(ev), (std::vector<T>{T::kTaskFailed, T::kPlanAborted, T::kReplanRequested}));
  EXPECT_EQ(ev[0].reason, "timeout");
  EXPECT_DOUBLE_EQ(ev[0].elapsed, 10.5);
  EXPECT_EQ(seq.state(), SequencerState::kWaitingForPlan);
  EXPECT_EQ(seq.replans(), 1u);
  // The answer at 11 s fails again at 21.5 s: 2 consecutive aborts > max_replans 1.
  seq.set_plan({{10, 0}}, 11.0, kOrigin);
  EXPECT_TRUE(seq.update(21.0, kOrigin).empty());
  EXPECT_EQ(types(seq.update(21.5, kOrigin)), (std::vector<T>{T::kTaskFailed, T::kPlanAborted, T::kGaveUp}));
  EXPECT_EQ(seq.state(), SequencerState::kGaveUp);
}

TEST(SequencerMachine, WorldFailureHandsBack) {
  Sequencer seq = make();
  seq.set_plan({{10, 0}}, 0.0, kOrigin);
  seq.set_world({{"Blocked", {0.8, 0.5}}});  // 0.8 * 0.5 = 0.4 < 0.5: holds not
  EXPECT_TRUE(seq.update(1.0, kOrigin).empty());
  seq.set_world({{"Blocked", {0.8, 1.0}}});  // 0.8 >= 0.5
  auto ev = seq.update(2.0, kOrigin);
  EXPECT_EQ(types(ev), (std::vector<T>{T::kTaskFailed, T::kHandedBack}));
  EXPECT_EQ(ev[1].reason, "failure");
  EXPECT_EQ(seq.state(), SequencerState::kHandedBack);
  EXPECT_EQ(seq.replans(), 0u);
  EXPECT_EQ(seq.active(), nullptr);
}

TEST(SequencerMachine, JobRetriesCountedThenAborts) {
  Sequencer seq = make();
  EXPECT_EQ(types(seq.set_job("BringBall", 0.0, kOrigin)), (std::vector<T>{T::kJobAccepted, T::kTaskStarted}));
  EXPECT_EQ(seq.job(), "BringBall");
  EXPECT_TRUE(seq.update(4.0, kOrigin).empty());                                    // 4 s: not over 4
  EXPECT_EQ(types(seq.update(4.5, kOrigin)), (std::vector<T>{T::kTaskRetried}));   // retry 1, re-entered at 4.5
  EXPECT_TRUE(seq.update(8.5, kOrigin).empty());                                    // 4.0 s in the state
  EXPECT_EQ(types(seq.update(8.6, kOrigin)), (std::vector<T>{T::kTaskRetried}));   // retry 2, at 8.6
  auto ev = seq.update(12.7, kOrigin);                                              // 4.1 s: retries exhausted
  EXPECT_EQ(types(ev), (std::vector<T>{T::kTaskFailed, T::kJobAborted}));
  EXPECT_EQ(ev[0].task, "Approach");
  EXPECT_EQ(seq.state(), SequencerState::kAborted);
  EXPECT_EQ(seq.failed(), 1u);
}

TEST(SequencerMachine, JobTasksRunInOrder) {
  Sequencer seq = make();
  seq.set_world({{"BallNear", {1.0, 1.0}}});
  // Approach succeeds at once, Shoot starts in the same call.
  auto ev = seq.set_job("BringBall.carrier", 0.0, kOrigin);  // the activity's entry
  EXPECT_EQ(types(ev), (std::vector<T>{T::kJobAccepted, T::kTaskStarted, T::kTaskSucceeded, T::kTaskStarted}));
  EXPECT_EQ(ev[3].task, "Shoot");
  EXPECT_DOUBLE_EQ(seq.active_timeout(), 3.0);
  EXPECT_TRUE(seq.update(1.0, kOrigin).empty());
  seq.set_world({{"Kicked", {1.0, 1.0}}});
  EXPECT_EQ(types(seq.update(2.0, kOrigin)), (std::vector<T>{T::kTaskSucceeded, T::kJobDone}));
  EXPECT_EQ(seq.state(), SequencerState::kDone);
  EXPECT_EQ(seq.reached(), 2u);
}

TEST(SequencerMachine, JobReplanRestartsItsTasks) {
  Sequencer seq = make();
  seq.set_job("PassageToMate.passer", 0.0, kOrigin);
  // Shoot's 3 s expire: the job's schedule starts again at once (re-plan 1 of 1).
  EXPECT_EQ(types(seq.update(3.5, kOrigin)), (std::vector<T>{T::kTaskFailed, T::kPlanAborted, T::kTaskStarted}));
  EXPECT_EQ(seq.state(), SequencerState::kRunning);
  EXPECT_EQ(seq.replans(), 1u);
  EXPECT_TRUE(seq.update(6.5, kOrigin).empty());  // 3.0 s since 3.5
  EXPECT_EQ(types(seq.update(7.0, kOrigin)), (std::vector<T>{T::kTaskFailed, T::kPlanAborted, T::kGaveUp}));
}

TEST(SequencerMachine, UnknownAndEmptyJobs) {
  Sequencer seq = make();
  EXPECT_FALSE(seq.knows_job("Defense"));
  EXPECT_THROW(seq.set_job("Defense", 0.0, kOrigin), std::invalid_argument);
  seq.set_job("BringBall", 0.0, kOrigin);
  EXPECT_EQ(types(seq.set_job("", 1.0, kOrigin)), (std::vector<T>{T::kJobAccepted}));
  EXPECT_EQ(seq.state(), SequencerState::kIdle);
  EXPECT_EQ(seq.active(), nullptr);
}

TEST(SequencerMachine, ManualModeStopsTheMachineClock) {
  Sequencer seq = make();
  seq.set_plan({{10, 0}}, 0.0, kOrigin);
  seq.set_mode(Mode::kManual, 2.0);
  EXPECT_TRUE(seq.update(20.0, kOrigin).empty());  // 2 s of task time
  seq.set_mode(Mode::kAuto, 22.0);
  EXPECT_TRUE(seq.update(29.9, kOrigin).empty());  // 2 + 7.9 = 9.9 s
  EXPECT_EQ(types(seq.update(30.5, kOrigin)),      // 2 + 8.5 = 10.5 s > 10
            (std::vector<T>{T::kTaskFailed, T::kPlanAborted, T::kReplanRequested}));
}

// ReachPathPoint as a machine gives the single-state task's numbers: 10 m
// leg, limit 15 + 4 * 10 = 55 s either way; 60 cm reached.
TEST(SequencerMachine, ReachPathPointMachineMatchesTheOldTask) {
  Sequencer seq(load_sequencer_options(MRT_SCARE_CONFIG_DIR "/tasks/reach_path_point.yaml"));
  ASSERT_TRUE(seq.options().machines);
  seq.set_plan({{10, 0}, {20, 0}}, 0.0, kOrigin);
  EXPECT_DOUBLE_EQ(seq.active_timeout(), 55.0);
  EXPECT_DOUBLE_EQ(TaskSpec::reach_path_point(0.6, 15.0, 4.0).timeout_limit(10.0), 55.0);
  EXPECT_EQ(types(seq.update(5.0, {9.5, 0.0, 0.0})), (std::vector<T>{T::kTaskSucceeded, T::kTaskStarted}));
  // Second leg from (9.5, 0): 10.5 m, 15 + 42 = 57 s from 5 s.
  EXPECT_DOUBLE_EQ(seq.active_timeout(), 57.0);
  EXPECT_TRUE(seq.update(62.0, {12.0, 0.0, 0.0}).empty());
  EXPECT_EQ(types(seq.update(62.1, {12.0, 0.0, 0.0})),
            (std::vector<T>{T::kTaskFailed, T::kPlanAborted, T::kReplanRequested}));
}

// Columns counted by hand: line 2 is "tasks: {X: ...}", its map at column 8;
// line 5 "jobs: {J: [Y]}", Y at column 12; line 4 "max_replans: 1.5", the value at 14.
TEST(SequencerMachine, FileErrors) {
  const std::string head = "fuzzy: {shapes: \"(UNIT (TOR (HIGH 0 1)))\", data: \"(A UNIT)\"}\n"
                           "tasks: {X: {states: {s: {success: (D A HIGH)}}}}\n";
  EXPECT_EQ(error_of(head), "m.yaml:2:8: path task 'ReachPathPoint' is not defined under 'tasks'");
  EXPECT_EQ(error_of(head + "path_task: X\n\njobs: {J: [Y]}\n"), "m.yaml:5:12: unknown task 'Y' in job 'J'");
  EXPECT_EQ(error_of(head + "jobs: {J: [X]}\n"), "no error");  // jobs only: no path task needed
  EXPECT_EQ(error_of(head + "path_task: X\nmax_replans: 1.5\n"),
            "m.yaml:4:14: expected an integer 0..1000 for 'max_replans'");
}
