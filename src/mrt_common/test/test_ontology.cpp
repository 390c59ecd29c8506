// The ontology: the shipped file parses and has the classes the stack
// names; the hierarchy and its inherited requirements; the check that drops
// an unknown class, a missing position or a wrongly typed attribute; a
// malformed ontology named by file:line.
#include <gtest/gtest.h>

#include "mrt_common/ontology.h"
#include "mrt_common/parse_error.h"

using namespace mrt::common;

TEST(Ontology, StandardHasEveryNamedClass) {
  const Ontology& o = Ontology::standard();
  for (const char* c : {percept_class::kBall, percept_class::kCar, percept_class::kExhibit, percept_class::kGoal,
                        percept_class::kGoalPost, percept_class::kLandmark, percept_class::kLine,
                        percept_class::kObstacle, percept_class::kOpponent, percept_class::kPerson,
                        percept_class::kRobot, percept_class::kTeammate, percept_class::kTree, percept_class::kWall})
    EXPECT_NE(o.find_class(c), nullptr) << c;
  // The built-in copy is the file.
  EXPECT_EQ(Ontology::load(MRT_ONTOLOGY_FILE).classes().size(), o.classes().size());
  EXPECT_TRUE(o.is_a("Teammate", "Robot"));
  EXPECT_TRUE(o.is_a("Teammate", "MovingObject"));
  EXPECT_TRUE(o.is_a("Ball", "Object"));
  EXPECT_FALSE(o.is_a("Robot", "Teammate"));
  EXPECT_FALSE(o.is_a("Goal", "MovingObject"));
  EXPECT_FALSE(o.is_a("Nothing", "Object"));
  const AttributeSpec* b = o.find_attribute("bearing");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->unit, "rad");
  EXPECT_FALSE(b->symbol);
  EXPECT_TRUE(o.find_attribute("color")->symbol);
}

TEST(Ontology, CheckAndFilter) {
  const Ontology& o = Ontology::standard();
  PerceptObject ok("b", "Ball");
  ok.set_polar({2.0, 0.5});
  EXPECT_EQ(o.check(ok), PerceptFault::kNone);
  PerceptObject xy("p", "Person");
  xy.set_cartesian({1.0, 2.0});
  EXPECT_EQ(o.check(xy), PerceptFault::kNone);  // Cartesian only is a position too
  PerceptObject unknown("u", "Unicorn");
  unknown.set_polar({1.0, 0.0});
  std::string why;
  EXPECT_EQ(o.check(unknown, &why), PerceptFault::kUnknownClass);
  EXPECT_NE(why.find("unknown class 'Unicorn'"), std::string::npos) << why;
  PerceptObject nopos("n", "Landmark");
  nopos.set("distance", 3.0).set_symbol("color", "red");  // no bearing: no position
  EXPECT_EQ(o.check(nopos, &why), PerceptFault::kMissingAttribute);
  EXPECT_NE(why.find("lacks a position"), std::string::npos) << why;
  PerceptObject wrong("w", "Ball");
  wrong.set_polar({1.0, 0.0}).set("color", 3.0);  // a colour must be a symbol
  EXPECT_EQ(o.check(wrong, &why), PerceptFault::kWrongKind);
  PerceptObject extra("e", "Ball");
  extra.set_polar({1.0, 0.0}).set("spin", 2.0);  // undeclared attributes are tolerated
  EXPECT_EQ(o.check(extra), PerceptFault::kNone);

  std::vector<PerceptObject> v{ok, unknown, nopos, xy, wrong, extra};
  PerceptDrops d;
  o.filter(v, d);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].name, "b");
  EXPECT_EQ(v[1].name, "p");
  EXPECT_EQ(v[2].name, "e");
  EXPECT_EQ(d.unknown_class, 1u);
  EXPECT_EQ(d.missing_attribute, 1u);
  EXPECT_EQ(d.wrong_kind, 1u);
  EXPECT_EQ(d.total(), 3u);
}

TEST(Ontology, RequirementsAreInherited) {
  const Ontology o = Ontology::parse(
      "attributes:\n  x: {type: number, unit: m}\n  y: {type: number, unit: m}\n  team: {type: symbol}\n"
      "classes:\n  Thing: {required: [position]}\n  Player: {parent: Thing, required: [team]}\n",
      "mini.yaml");
  EXPECT_EQ(o.required("Player"), (std::vector<std::string>{"position", "team"}));
  PerceptObject p("p", "Player");
  p.set_cartesian({1, 2});
  EXPECT_EQ(o.check(p), PerceptFault::kMissingAttribute);
  p.set_symbol("team", "cyan");
  EXPECT_EQ(o.check(p), PerceptFault::kNone);
}

TEST(Ontology, MalformedFileNamesLine) {
  auto line_of = [](const std::string& text) {
    try {
      Ontology::parse(text, "bad.yaml");
    } catch (const ParseError& e) {
      EXPECT_EQ(e.file(), "bad.yaml");
      return e.line();
    }
    ADD_FAILURE() << "no error: " << text;
    return -1;
  };
  EXPECT_EQ(line_of("attributes:\n  x: {type: vector}\nclasses: {}\n"), 2);
  EXPECT_EQ(line_of("attributes: {}\nclasses:\n  A: {parent: B}\n"), 3);
  EXPECT_EQ(line_of("attributes: {}\nclasses:\n  A: {parent: B}\n  B: {parent: A}\n"), 3);
  EXPECT_EQ(line_of("attributes: {}\nclasses:\n  A: {required: [speed]}\n"), 3);
  EXPECT_EQ(line_of("attributes: {}\nclasses: {}\nthings: 1\n"), 3);
}
