// Conceptual model loading and the Classifier on hand-made percepts.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_map/classifier.h"
#include "mrt_map/conceptual_model.h"

using namespace mrt::map;

namespace {
ConceptualModel test_model() { return ConceptualModel::load(MRT_MAP_TEST_DATA "/classes.yaml"); }

PerceptObject object(const std::string& cls, const std::string& color, double diameter = NAN) {
  PerceptObject o;
  o.membership_class = cls;
  if (!color.empty()) o.attributes.push_back({"color", 0.0, color, 0.0, 1.0});
  if (!std::isnan(diameter)) o.set("diameter", diameter);
  return o;
}

void expect_error(const std::string& text, int line, int column, const std::string& msg) {
  try {
    ConceptualModel::parse(text, "m.yaml");
    FAIL() << "no error for:\n" << text;
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(e.file(), "m.yaml");
    EXPECT_EQ(e.line(), line) << e.what();
    if (column > 0) {
      EXPECT_EQ(e.column(), column) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find(msg), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(ConceptualModel, RobocupHierarchyAndInheritance) {
  const ConceptualModel m = ConceptualModel::load(MRT_MAP_CONFIG_DIR "/robocup.yaml");
  const int ball = m.find("Ball"), robot = m.find("Robot"), mate = m.find("Teammate"), goal = m.find("Goal");
  ASSERT_GE(ball, 0);
  ASSERT_GE(mate, 0);
  EXPECT_TRUE(m.is_a(mate, robot));
  EXPECT_TRUE(m.is_a(mate, m.find("Object")));
  EXPECT_FALSE(m.is_a(robot, mate));
  EXPECT_TRUE(m.compatible(robot, mate));
  EXPECT_FALSE(m.compatible(ball, robot));
  EXPECT_EQ(m.at(ball).motion, MotionModel::kConstantVelocity);  // from MovingObject
  EXPECT_DOUBLE_EQ(m.at(ball).accel_noise, 3.0);                  // own
  EXPECT_DOUBLE_EQ(m.at(mate).accel_noise, 1.5);                  // from Robot
  EXPECT_EQ(m.at(goal).motion, MotionModel::kStatic);
  EXPECT_TRUE(m.at(mate).refined_by_teammate_pose);
  ASSERT_EQ(m.crisp().size(), 5u);
  EXPECT_EQ(m.crisp()[0].name, "BallDistance");
  EXPECT_DOUBLE_EQ(m.crisp()[0].scale, 1000.0);
  EXPECT_EQ(m.crisp()[3].quantity, CrispEntry::Quantity::kParameter);
}

TEST(ConceptualModel, ErrorsNameFileLineColumn) {
  // "  Ball: {parent: Thing}": 'Thing' starts at column 18 of line 3.
  expect_error("classes:\n  Object: {}\n  Ball: {parent: Thing}\n", 3, 18, "unknown parent class 'Thing'");
  expect_error("classes:\n  A: {parent: B}\n  B: {parent: A}\n", 2, 0, "cycle");
  expect_error("classes:\n  Ball:\n    attributes:\n      size: {set: [TRI, 1, 2]}\n", 4, 0, "bad fuzzy set");
  expect_error("classes:\n  Ball: {motion: flying}\n", 2, 18, "expected 'static' or 'constant_velocity'");
  expect_error("classes:\n  Ball: {}\ncrisp:\n  - {name: X, class: Cat, quantity: x}\n", 4, 22, "unknown class 'Cat'");
  expect_error("classes:\n  Ball: {colour: red}\n", 2, 10, "unknown key 'colour'");
  expect_error("classes:\n  Ball: {}\ntracker: {coast_after: 2, drop_after: 1}\n", 3, 0, "drop_after");
  expect_error("classes:\n  Ball: {}\ntracker: {source_confidence: 1.5}\n", 3, 30, "in (0, 1] for 'source_confidence'");
  expect_error("classes:\n  Ball: {}\ncrisp:\n  - {name: X, class: Ball, quantity: x, select: best}\n", 4, 49,
               "expected 'nearest', 'most_reliable' or 'best_supported' for 'select', got 'best'");
  EXPECT_THROW(ConceptualModel::load("/nonexistent/model.yaml"), mrt::common::ParseError);
}

TEST(Classifier, MatchingDegreesOnHandMadePercepts) {
  const ConceptualModel m = test_model();
  const Classifier c(m);
  // Object, red, 0.19 m: Ball = min(color red 0.6, TRI(0.1,0.22,0.34) at
  // 0.19 = (0.19-0.1)/(0.22-0.1) = 0.75) = 0.6 >= 0.5; Robot has no matcher.
  auto r = c.classify(object("Object", "red", 0.19));
  ASSERT_TRUE(r);
  EXPECT_EQ(m.at(r->class_index).name, "Ball");
  EXPECT_NEAR(r->degree, 0.6, 1e-12);
  // Orange but 0.40 m: TRI = 0 -> stays an Object with degree 1.
  r = c.classify(object("Object", "orange", 0.40));
  ASSERT_TRUE(r);
  EXPECT_EQ(m.at(r->class_index).name, "Object");
  EXPECT_DOUBLE_EQ(r->degree, 1.0);
  // Robot, cyan: Teammate 0.3 (< 0.5), Opponent 1.0 -> Opponent 1.0.
  r = c.classify(object("Robot", "cyan"));
  ASSERT_TRUE(r);
  EXPECT_EQ(m.at(r->class_index).name, "Opponent");
  EXPECT_DOUBLE_EQ(r->degree, 1.0);
  // Robot, magenta: Teammate 1.0, Opponent 0.35 -> Teammate.
  r = c.classify(object("Robot", "magenta"));
  EXPECT_EQ(m.at(r->class_index).name, "Teammate");
  // Robot, violet: Teammate 0.8, Opponent 0.75, 0.05 apart < margin 0.1 ->
  // ambiguous: keeps Robot, to be refined later.
  r = c.classify(object("Robot", "violet"));
  EXPECT_EQ(m.at(r->class_index).name, "Robot");
  // Robot without colour: neither child can be checked -> Robot.
  r = c.classify(object("Robot", ""));
  EXPECT_EQ(m.at(r->class_index).name, "Robot");
  // Declared Ball but blue: color degree 0 < 0.5 -> rejected.
  Rejection why = Rejection::kNone;
  EXPECT_FALSE(c.classify(object("Ball", "blue"), &why));
  EXPECT_EQ(why, Rejection::kUnmatched);
  EXPECT_FALSE(c.classify(object("Car", "red"), &why));
  EXPECT_EQ(why, Rejection::kUnknownClass);
}

TEST(Classifier, PlacesPolarPerceptInTheWorld) {
  const ConceptualModel m = test_model();
  const Classifier c(m);
  PerceptObject o = object("Robot", "cyan");
  o.set("distance", 2.0, 0.2, 1.0);
  o.set("bearing", M_PI / 2, 0.05, 1.0);
  RobotPose pose;
  pose.x = 1;
  pose.y = 1;
  pose.theta = M_PI / 2;
  pose.cov = 1e-4 * Mat2::Identity();
  pose.theta_sigma = 0.1;
  // Robot frame: (0, 2); J = [0 -2; 1 0]; J diag(0.04, 0.0025) J' =
  // diag(0.01, 0.04). Rotated by 90 deg: diag(0.04, 0.01); world point
  // (1,1) + (-2, 0) = (-1, 1); heading term 0.1^2 * perp perp' with perp =
  // (0, -2): +0.04 on yy; pose +1e-4: R = diag(0.0401, 0.0501).
  const auto obs = c.observe(o, pose, 5.0, "r1", "cam");
  ASSERT_TRUE(obs);
  EXPECT_NEAR(obs->z.x(), -1.0, 1e-12);
  EXPECT_NEAR(obs->z.y(), 1.0, 1e-12);
  EXPECT_NEAR(obs->R(0, 0), 0.0401, 1e-12);
  EXPECT_NEAR(obs->R(1, 1), 0.0501, 1e-12);
  EXPECT_NEAR(obs->R(0, 1), 0.0, 1e-12);
  EXPECT_EQ(m.at(obs->class_index).name, "Opponent");
  EXPECT_EQ(obs->sensors.count("r1/cam"), 1u);
  Rejection why = Rejection::kNone;
  o.set("distance", NAN);
  EXPECT_FALSE(c.observe(o, pose, 5.0, "r1", "cam", &why));
  EXPECT_EQ(why, Rejection::kNonFinite);
  EXPECT_FALSE(c.observe(object("Robot", "cyan"), pose, 5.0, "r1", "cam", &why));
  EXPECT_EQ(why, Rejection::kNoPosition);
}
