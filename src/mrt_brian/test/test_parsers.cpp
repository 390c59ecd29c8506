// Parsers: grammar, comments, blanks, and errors naming file:line:column.
#include <gtest/gtest.h>

#include "mrt_brian/behavior_list_parser.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_brian/rule_parser.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;
using mrt::common::ParseError;

TEST(Parsers, ShapesAndAssociations) {
  const auto shapes = parse_shapes("# c\n(Distance\n (TRA (NEAREST 0 0.1 40 60))\n (TOR (FAR 100 120))\n )\n", "s");
  ASSERT_EQ(shapes.size(), 1u);
  EXPECT_EQ(shapes[0].sets.size(), 2u);
  EXPECT_EQ(shapes[0].sets[1].line, 4);
  const auto a = parse_associations("(x XS) (y XS)\n(ProposedSpeed SP)\n", "c");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[2].line, 2);
}

// Only predicate, CANDO, WANT and rule files have '#( ... ;' block comments:
// in shape and association files '#(' starts a line comment like any '#',
// and must not swallow the lines up to the next ';'.
TEST(Parsers, NoBlockCommentsInShapeAndAssociationFiles) {
  const auto shapes = parse_shapes(
      "#(old shape, commented out\n(A (TRI (L 0 1 2)))\n(B (SNG (M 5)));\n(C (REC (N 1 3)))\n", "s_shape.txt");
  ASSERT_EQ(shapes.size(), 3u);
  EXPECT_EQ(shapes[0].name, "A");
  EXPECT_EQ(shapes[0].line, 2);
  EXPECT_EQ(shapes[1].name, "B");
  EXPECT_EQ(shapes[2].name, "C");
  EXPECT_EQ(shapes[2].line, 4);
  const auto a = parse_associations("#(Speed OLD)\n(Speed SPD)\n(Angle ANG);\n(Turn TRN)\n", "s_ftoc.txt");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].name, "Speed");
  EXPECT_EQ(a[0].line, 2);
  EXPECT_EQ(a[2].name, "Turn");
  // Predicate files keep them: the block runs to the first ';'.
  const auto d = parse_definitions("#( X = (D x L);\nY = (D y L);\n", "Predicate.ini");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].name, "Y");
}

TEST(Parsers, ShapeErrorsNameTheLine) {
  try {
    parse_shapes("(S\n (TRI (A 1 2))\n)", "shape_ctof.txt");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "shape_ctof.txt");
    EXPECT_EQ(e.line(), 2);
  }
  try {
    parse_shapes("(S\n\n (FOO (A 1 2))\n)", "shape_ctof.txt");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 3);
  }
}

TEST(Parsers, DefinitionsWithCommentsAndNoBreakSpace) {
  const auto d = parse_definitions(
      "XHigh = (D x HIGH);   # trailing comment\n#( block\n comment ;\nBoth =\xC2\xA0(AND (P XHigh) (YHigh));\n", "P");
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[1].name, "Both");
  EXPECT_EQ(d[1].line, 4);
  EXPECT_EQ(d[1].expr.kind, ExprAst::kAnd);
  EXPECT_EQ(d[1].expr.args[1].kind, ExprAst::kPredicate);
  EXPECT_EQ(d[1].expr.args[1].name, "YHigh");
}

TEST(Parsers, DefinitionErrors) {
  EXPECT_THROW(parse_definitions("A = (D x HIGH)\nB = (P A);", "P"), ParseError);  // missing ';'
  try {
    parse_definitions("A = (D x HIGH);\nB = (NOT);\n", "Predicate.ini");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
  }
}

TEST(Parsers, Rules) {
  const auto r = parse_rules(
      "# c\n(OR (A)\n (B)) => (&DEL.Speed ANY)\n (Speed FAST);\n(&B1.Speed.FAST) => (Mark ON) (&DEL.Turn *LEFT);\n", "x.rul");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].line, 4);  // the line of ';'
  EXPECT_EQ(r[0].start_line, 2);
  EXPECT_TRUE(r[0].actions[0].del);
  EXPECT_EQ(r[0].actions[0].action, "Speed");
  EXPECT_EQ(r[1].precondition.kind, ExprAst::kProposal);
  EXPECT_EQ(r[1].precondition.name, "B1");
  EXPECT_EQ(r[1].precondition.action, "Speed");
  EXPECT_EQ(r[1].precondition.label, "FAST");
  EXPECT_EQ(r[1].actions[1].label, "*LEFT");
}

TEST(Parsers, RuleWithoutSemicolonReportsItsLine) {
  try {
    parse_rules("(A) => (Speed FAST);\n\n(B) => (Speed SLOW)\n(C) => (Speed SLOW);\n", "GoToTarget.rul");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "GoToTarget.rul");
    EXPECT_EQ(e.line(), 4);  // the next rule starts where ';' was expected
    EXPECT_NE(std::string(e.what()).find("expected ';' after rule"), std::string::npos);
  }
  // The manual's '= >' is not '=>'.
  EXPECT_THROW(parse_rules("(TargetNord) = > (SpeedAngle NORD);\n", "r"), ParseError);
}

TEST(Parsers, BehaviorList) {
  const auto b = parse_behavior_list("( level 1 Search\t../config/Search.rul )\n\n( level 2 Avoid a.rul )\n", "behaviour.txt");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].path, "../config/Search.rul");
  EXPECT_EQ(b[1].level, 2);
  EXPECT_EQ(b[1].line, 3);
  EXPECT_THROW(parse_behavior_list("(level x A a.rul)", "b"), ParseError);
  EXPECT_THROW(parse_behavior_list("(lvl 1 A a.rul)", "b"), ParseError);
}

TEST(Parsers, CrispInput) {
  const auto c = parse_crisp_input("# h\nx 25\ny 0 0.5\n---\n---\nx 1 # c\n", "in");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].size(), 2u);
  EXPECT_DOUBLE_EQ(c[0][1].reliability, 0.5);
  EXPECT_TRUE(c[1].empty());
  EXPECT_DOUBLE_EQ(c[2][0].value, 1.0);
  try {
    parse_crisp_input("x 1\ny abc\n", "input.txt");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
  }
  EXPECT_THROW(parse_crisp_input("x 1 1.5\n", "in"), ParseError);
  EXPECT_THROW(parse_crisp_input("x\n", "in"), ParseError);
}
