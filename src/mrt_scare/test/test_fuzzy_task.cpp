// The sequencer's tasks with predicate conditions (Mr. BRIAN's language)
// over the task's own crisp data and the world model's.
#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"
#include "mrt_scare/task_config.h"

using namespace mrt::scare;

namespace {

const char* kYaml = R"Y(
fuzzy:
  shapes: |
    (GOALDISTANCE (REC (ARRIVED 0 60)))
    (UNIT (TOR (HIGH 0 1)))
    (SECONDS (REC (LATE 20.5 1000000)))
  data: "(GoalDistance GOALDISTANCE) (Blocked UNIT) (TaskElapsed SECONDS)"
tasks:
  ReachPathPoint:
    success:
      - predicate: (D GoalDistance ARRIVED)
    failure:
      - predicate: (OR (D Blocked HIGH) (D TaskElapsed LATE))
)Y";

bool has(const std::vector<SequencerEvent>& ev, SequencerEvent::Type t) {
  for (const auto& e : ev)
    if (e.type == t) return true;
  return false;
}

}  // namespace

TEST(FuzzyTask, SuccessWithinSixtyCentimetres) {
  Sequencer s(parse_sequencer_options(kYaml, "t.yaml"));
  s.set_plan({{10.0, 0.0}}, 0.0, Pose2D(0, 0, 0));
  EXPECT_FALSE(has(s.update(1.0, Pose2D(9.39, 0, 0)), SequencerEvent::Type::kTaskSucceeded));  // 61 cm
  EXPECT_TRUE(has(s.update(2.0, Pose2D(9.41, 0, 0)), SequencerEvent::Type::kTaskSucceeded));   // 59 cm
  EXPECT_EQ(s.state(), SequencerState::kDone);
}

TEST(FuzzyTask, FailureFromTheWorldModelOrTime) {
  Sequencer s(parse_sequencer_options(kYaml, "t.yaml"));
  s.set_plan({{10.0, 0.0}}, 0.0, Pose2D(0, 0, 0));
  s.set_world({{"Blocked", {0.4, 1.0}}});  // 0.4 < 0.5: goes on
  EXPECT_FALSE(has(s.update(1.0, Pose2D(1, 0, 0)), SequencerEvent::Type::kTaskFailed));
  // OR takes the max of values and of reliabilities (manual §10.3.2, NOTES):
  // <0.8, 0.5> OR <0, 1> (TaskElapsed not LATE) = <0.8, 1>, degree 0.8.
  s.set_world({{"Blocked", {0.8, 0.5}}});
  EXPECT_TRUE(has(s.update(2.0, Pose2D(1, 0, 0)), SequencerEvent::Type::kTaskFailed));
  s.set_world({});
  s.set_plan({{10.0, 0.0}}, 2.0, Pose2D(1, 0, 0));  // a new plan after the re-plan request
  s.set_world({{"Blocked", {0.6, 1.0}}});  // 0.6: fails, the plan is aborted, re-plan
  const auto ev = s.update(3.0, Pose2D(1, 0, 0));
  EXPECT_TRUE(has(ev, SequencerEvent::Type::kTaskFailed));
  EXPECT_TRUE(has(ev, SequencerEvent::Type::kReplanRequested));
  // Time: 20.4 s goes on, 20.5 s fails.
  s.set_world({});
  s.set_plan({{10.0, 0.0}}, 10.0, Pose2D(0, 0, 0));
  EXPECT_FALSE(has(s.update(30.4, Pose2D(1, 0, 0)), SequencerEvent::Type::kTaskFailed));
  EXPECT_TRUE(has(s.update(30.5, Pose2D(1, 0, 0)), SequencerEvent::Type::kTaskFailed));
}

TEST(FuzzyTask, PredicateErrors) {
  try {
    parse_sequencer_options("tasks:\n  ReachPathPoint:\n    success:\n      - predicate: (D X NEAR)\n"
                            "    failure:\n      - timeout: 5\n",
                            "t.yaml");
    FAIL() << "no error";
  } catch (const mrt::common::ParseError& e) {
    // Column 20: the value after "      - predicate: ".
    EXPECT_STREQ(e.what(), "t.yaml:4:20: a 'predicate' condition needs a top-level 'fuzzy' section");
  }
}
