// Task files: parsing and errors with line and column.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_scare/task_config.h"

using namespace mrt::scare;
using mrt::common::ParseError;

namespace {
void expect_error(const std::string& yaml, int line, int col, const std::string& part) {
  try {
    parse_sequencer_options(yaml, "t.yaml");
    FAIL() << "no error for\n" << yaml;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "t.yaml");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), col) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(TaskConfig, ParsesReachPathPoint) {
  const auto o = parse_sequencer_options(
      "tasks:\n"
      "  ReachPathPoint:\n"
      "    success:\n"
      "      - within: 0.6\n"
      "    failure:\n"
      "      - timeout: 20\n"
      "        per_metre: 2.5\n"
      "    on_failure: abort_and_replan\n"
      "max_replans: 3\n"
      "replan_timeout: 4.5\n"
      "suspend_in_manual: false\n",
      "t.yaml");
  EXPECT_EQ(o.path_task.name, "ReachPathPoint");
  ASSERT_EQ(o.path_task.success.size(), 1u);
  EXPECT_EQ(o.path_task.success[0]->describe(), "within 0.6 m");
  EXPECT_DOUBLE_EQ(o.path_task.timeout_limit(4.0), 30.0);
  EXPECT_EQ(o.max_replans, 3);
  EXPECT_DOUBLE_EQ(o.replan_timeout, 4.5);
  EXPECT_FALSE(o.suspend_in_manual);
  EXPECT_EQ(o.path_task.on_failure, OnFailure::kAbortAndReplan);
}

TEST(TaskConfig, ErrorsNameLineAndColumn) {
  expect_error("tasks:\n  ReachPathPoint:\n    success: [{within: 0.5}]\n    failur: []\n", 4, 5,
               "unknown key 'failur'");
  expect_error("tasks:\n  ReachPathPoint:\n    success: [{within: -1}]\n    failure: [{timeout: 5}]\n",
               3, 24, "'within' > 0");
  expect_error("tasks:\n  ReachPathPoint:\n    success: [{within: 0.5}]\n", 3, 5, "missing key 'failure'");
  expect_error("tasks:\n  ReachPathPoint:\n    success: [{within: 0.5}]\n    failure: [{timeout: 5}]\n"
               "    on_failure: retry\n", 5, 17, "unknown on_failure");
  expect_error("tasks: {ReachPathPoint: {success: [{within: 1}], failure: [{timeout: x}]}}\n", 1, 70,
               "expected a number");
  expect_error("tasks: [\n", 2, 1, "");
  EXPECT_THROW(load_sequencer_options("/nonexistent/tasks.yaml"), ParseError);
  EXPECT_THROW(load_sequencer_options("/tmp"), ParseError);
}

