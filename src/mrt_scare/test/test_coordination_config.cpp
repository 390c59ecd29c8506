// The activity file, the fuzzy opportunities (Mr. BRIAN's predicate
// language) and its errors with file:line:column.
#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"
#include "mrt_scare/activity.h"

using namespace mrt::scare;
using mrt::common::ParseError;

namespace {

std::string error_of(const std::string& yaml) {
  try {
    parse_activities(yaml, "a.yaml");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kHead =
    "fuzzy:\n"
    "  shapes: |\n"
    "    (UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))\n"
    "  data: \"(A UNIT) (B UNIT)\"\n"
    "  predicates: |\n"
    "    Both = (AND (D A HIGH) (D B HIGH));\n";

}  // namespace

TEST(ActivityFile, RoboCupExample) {
  const ActivitySet s = load_activities(MRT_SCARE_CONFIG_DIR "/robocup_activities.yaml");
  ASSERT_EQ(s.activities.size(), 7u);
  EXPECT_EQ(s.activities[0].name, "Defense");
  EXPECT_FALSE(s.activities[0].schema);
  EXPECT_DOUBLE_EQ(s.activities[0].priority, 1.2);
  EXPECT_EQ(s.activities[0].roles[0].target.kind, Target::Kind::kFixed);
  EXPECT_TRUE(s.activities[3].schema);
  EXPECT_EQ(s.slot_name({3, 1}), "PassageToMate.receiver");
  EXPECT_EQ(s.find_slot("PassageToMate.receiver"), 4);  // Defense, Recover, BringBall, passer, receiver
  EXPECT_EQ(s.activities[6].roles[0].max, 5);
  ASSERT_EQ(s.robots.size(), 3u);
  EXPECT_DOUBLE_EQ(s.attitude(s.robots[1], {3, 0}), 0.9);   // role entry
  EXPECT_DOUBLE_EQ(s.attitude(s.robots[0], {4, 1}), 0.8);   // activity entry for every role
  EXPECT_DOUBLE_EQ(s.attitude(s.robots[0], {1, 0}), 0.5);   // default
  EXPECT_EQ(s.robot_or_default("robot9").max_speed, 1.0);
}

TEST(ActivityFile, OpportunityIsAFuzzyPredicate) {
  ActivitySet s = parse_activities(kHead +
                                       "activities:\n"
                                       "  - {name: J, opportunity: (AND (P Both) (NOT (D A LOW)))}\n"
                                       "  - {name: K, opportunity: 0.25}\n",
                                   "a.yaml");
  // A = 0.7 (reliability 1), B = 0.4 (reliability 0.5): HIGH(A) = 0.7,
  // HIGH(B) = <0.4, 0.5>, Both = <min 0.4, min 0.5>; NOT LOW(A) = 1 - 0.3 =
  // 0.7; J = <0.4, 0.5>, degree 0.4 * 0.5 = 0.2.
  s.model->evaluate({{"A", {0.7, 1.0}}, {"B", {0.4, 0.5}}});
  const auto o = s.opportunities();
  EXPECT_NEAR(o[0], 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(o[1], 0.25);
  // A missing datum reads <0, 1>: HIGH(B) = 0, J = 0.
  s.model->evaluate({{"A", {0.7, 1.0}}});
  EXPECT_EQ(s.opportunities()[0], 0.0);
}

TEST(ActivityFile, ErrorsNameLineAndColumn) {
  // Columns counted by hand: the datum's '(' is column 28 of line 8.
  EXPECT_EQ(error_of(kHead + "activities:\n  - {name: J, opportunity: (D C HIGH)}\n"),
            "a.yaml:8:28: unknown datum 'C' (not in the data associations)");
  // Unknown label inside the block scalar of the predicates: line 6, the
  // '(' after "    Y = " in column 9.
  EXPECT_EQ(error_of("fuzzy:\n  shapes: \"(UNIT (TOR (HIGH 0 1)))\"\n  data: \"(A UNIT)\"\n  predicates: |\n"
                     "    X = (D A HIGH);\n    Y = (D A LOWW);\n"
                     "activities:\n  - {name: J, opportunity: (P Y)}\n"),
            "a.yaml:6:9: unknown label 'LOWW' of datum 'A'");
  EXPECT_EQ(error_of(kHead + "activities:\n  - {name: J, opportunity: 0.1, max: 0}\n"),
            "a.yaml:8:38: expected an integer in [1, 32] for 'max'");
  EXPECT_EQ(error_of(kHead + "activities:\n  - {name: J, opportunity: 0.1, min: 2, max: 1}\n"),
            "a.yaml:8:46: expected 'max' >= 'min' (2)");
  EXPECT_EQ(error_of(kHead + "activities:\n  - {name: J, opportunity: 0.1, roles: [{name: a}]}\n"),
            "a.yaml:8:40: expected a schema with 2 or 3 roles");
  EXPECT_EQ(error_of(kHead + "activities:\n  - {name: J, opportunity: 0.1, colour: red}\n"),
            "a.yaml:8:33: unknown key 'colour' in 'activity' (expected one of: name, opportunity, priority, min, "
            "max, target)");
  EXPECT_EQ(error_of(kHead + "activities:\n  - {name: J, opportunity: 0.1}\nrobots:\n  - {id: r, attitude: {Q: 1}}\n"),
            "a.yaml:10:24: unknown activity or role 'Q' in 'attitude'");
  EXPECT_EQ(error_of(kHead + "activities:\n  - {name: J, opportunity: 0.1}\nrobots:\n  - {id: r, attitude: {J: 1.5}}\n"),
            "a.yaml:10:27: expected an attitude in [0, 1] for 'J'");
}
