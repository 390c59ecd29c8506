// Tasks as YAML state machines with fuzzy conditions: success, failure,
// timeout, the exception handlers, ReachPathPoint's definition, errors.
#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"
#include "mrt_scare/task_machine.h"

using namespace mrt::scare;
using Outcome = TaskRun::Outcome;

namespace {

// A kick: approach the ball (success when near, failure when it is lost,
// 5 s timeout -> retry once), then shoot (success when the ball moved off,
// failure -> hand back to the coordinator, 2 s timeout -> re-plan).
const char* kYaml = R"Y(
fuzzy:
  shapes: "(UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))"
  data: "(Near UNIT) (Lost UNIT) (Kicked UNIT)"
threshold: 0.5
tasks:
  Kick:
    states:
      approach:
        success: (D Near HIGH)
        failure: (D Lost HIGH)
        timeout: 5
        on_success: goto shoot
        on_failure: abort
        on_timeout: retry
        retries: 1
      shoot:
        success: (D Kicked HIGH)
        failure: (D Lost HIGH)
        timeout: 2
        on_failure: hand_back
        on_timeout: replan
)Y";

CrispMap data(double near, double lost, double kicked, double reliability = 1.0) {
  return {{"Near", {near, reliability}}, {"Lost", {lost, 1.0}}, {"Kicked", {kicked, 1.0}}};
}

std::string error_of(const std::string& yaml) {
  try {
    parse_task_library(yaml, "t.yaml");
  } catch (const mrt::common::ParseError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(TaskMachine, SuccessGoesThroughTheStates) {
  const TaskLibrary lib = parse_task_library(kYaml, "t.yaml");
  TaskRun run(lib, lib.tasks.at("Kick"));
  run.start(0.0, data(0, 0, 0));
  EXPECT_EQ(run.update(1.0, data(0.4, 0, 0)), Outcome::kRunning);  // 0.4 < 0.5
  // Near 0.6 with reliability 0.8: degree 0.48 < 0.5, not yet.
  EXPECT_EQ(run.update(1.5, data(0.6, 0, 0, 0.8)), Outcome::kRunning);
  EXPECT_EQ(run.update(2.0, data(0.6, 0, 0)), Outcome::kRunning);  // 0.6: goto shoot
  EXPECT_EQ(run.state(), "shoot");
  EXPECT_EQ(run.reason(), "success");
  EXPECT_EQ(run.update(2.5, data(1, 0, 0.5)), Outcome::kSucceeded);  // 0.5 >= 0.5: done
}

TEST(TaskMachine, SuccessIsCheckedBeforeFailure) {
  const TaskLibrary lib = parse_task_library(kYaml, "t.yaml");
  TaskRun run(lib, lib.tasks.at("Kick"));
  run.start(0.0, {});
  run.update(0.1, data(1, 1, 0));
  EXPECT_EQ(run.state(), "shoot");
}

TEST(TaskMachine, FailureHandlers) {
  const TaskLibrary lib = parse_task_library(kYaml, "t.yaml");
  TaskRun run(lib, lib.tasks.at("Kick"));
  run.start(0.0, {});
  EXPECT_EQ(run.update(1.0, data(0, 0.7, 0)), Outcome::kAborted);  // approach: abort
  EXPECT_EQ(run.reason(), "failure");
  run.start(0.0, {});
  run.update(1.0, data(1, 0, 0));
  EXPECT_EQ(run.update(1.5, data(0, 0.9, 0)), Outcome::kHandBack);  // shoot: hand back
}

TEST(TaskMachine, TimeoutRetriesThenAborts) {
  const TaskLibrary lib = parse_task_library(kYaml, "t.yaml");
  TaskRun run(lib, lib.tasks.at("Kick"));
  run.start(0.0, {});
  EXPECT_EQ(run.update(5.0, {}), Outcome::kRunning);  // exactly 5 s: not yet
  EXPECT_EQ(run.update(5.1, {}), Outcome::kRunning);  // timeout: retry 1 of 1, re-entered at 5.1
  EXPECT_EQ(run.retries_used(), 1);
  EXPECT_EQ(run.reason(), "timeout");
  EXPECT_EQ(run.update(10.0, {}), Outcome::kRunning);  // 4.9 s in the state
  EXPECT_EQ(run.update(10.2, {}), Outcome::kAborted);  // 5.1 s: retries exhausted
}

TEST(TaskMachine, TimeoutReplans) {
  const TaskLibrary lib = parse_task_library(kYaml, "t.yaml");
  TaskRun run(lib, lib.tasks.at("Kick"));
  run.start(0.0, {});
  run.update(1.0, data(1, 0, 0));  // shoot entered at 1.0
  EXPECT_EQ(run.update(3.0, data(1, 0, 0)), Outcome::kRunning);
  EXPECT_EQ(run.update(3.01, data(1, 0, 0)), Outcome::kReplan);
  EXPECT_EQ(run.update(4.0, data(1, 0, 1)), Outcome::kReplan);  // ended: stays
}

TEST(TaskMachine, ReachPathPointDefinition) {
  const TaskLibrary lib = load_task_library(MRT_SCARE_CONFIG_DIR "/tasks/reach_path_point.yaml");
  TaskRun run(lib, lib.tasks.at("ReachPathPoint"));
  // 10 m leg: limit 15 + 0.04 * 1000 cm = 55 s (manual §2.3.1, Roby's tasks.yaml: 15 s + 4 s/m).
  run.start(0.0, {{"GoalDistance", {1000.0, 1.0}}});
  EXPECT_DOUBLE_EQ(run.limit(), 55.0);
  EXPECT_EQ(run.update(10.0, {{"GoalDistance", {60.5, 1.0}}}), Outcome::kRunning);
  EXPECT_EQ(run.update(11.0, {{"GoalDistance", {60.0, 1.0}}}), Outcome::kSucceeded);  // within 60 cm
  run.start(0.0, {{"GoalDistance", {1000.0, 1.0}}});
  EXPECT_EQ(run.update(55.0, {{"GoalDistance", {300.0, 1.0}}}), Outcome::kRunning);
  EXPECT_EQ(run.update(55.1, {{"GoalDistance", {300.0, 1.0}}}), Outcome::kReplan);  // failure: re-plan
}

// Columns counted by hand: the value after "on_success: " is column 44 of
// line 7, the "(" of the success predicate column 20, the state map 10.
TEST(TaskMachine, Errors) {
  const std::string head = "fuzzy:\n  shapes: \"(UNIT (TOR (HIGH 0 1)))\"\n  data: \"(A UNIT)\"\ntasks:\n  T:\n    states:\n";
  EXPECT_EQ(error_of(head + "      s: {success: (D A HIGH), on_success: goto nowhere}\n"),
            "t.yaml:7:44: unknown state 'nowhere' in task 'T'");
  EXPECT_EQ(error_of(head + "      s: {success: (D A HIGH), on_success: explode}\n"),
            "t.yaml:7:44: expected done, abort, retry, replan, hand_back or 'goto <state>' for 'on_success'");
  EXPECT_EQ(error_of(head + "      s: {success: (D B HIGH)}\n"), "t.yaml:7:20: unknown datum 'B' (not in the data associations)");
  EXPECT_EQ(error_of(head + "      s: {on_success: done}\n"),
            "t.yaml:7:10: expected at least one of 'success', 'failure', 'timeout' in state 's'");
}
