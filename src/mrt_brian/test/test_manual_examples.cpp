// The worked examples of manual chapter 10, as corrected by
// ../shared/manual/NOTES.md. Expected numbers are those of the manual/NOTES.
#include <gtest/gtest.h>

#include "mrt_brian/cando_filter.h"
#include "mrt_brian/composer.h"
#include "mrt_brian/defuzzyfier.h"
#include "mrt_brian/expression_compiler.h"
#include "mrt_brian/fuzzyfier.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_brian/preacher.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;

namespace {
const char* kDistance =
    "(Distance\n (TRA (NEAREST 0 0.1 40 60))\n (TRA (NEAR 40 60 100 120))\n (TOR (FAR 100 120))\n )\n";
const char* kAngle =
    "(Angle\n (TRA (NORTH_1 0 0 30 60))\n (TRA (NORTH_2 300 330 360 360))\n (TRA (SOUTH 120 150 210 240))\n"
    " (TRA (WEST 30 60 120 150))\n (TRA (EST 210 240 300 330))\n )\n";
const char* kSpeedModule =
    "(SPEEDMODULE\n(SNG (STEADY 0))\n(SNG (VERY_SLOW 10))\n(SNG (SLOW 25))\n(SNG (FAST 75))\n(SNG (VERY_FAST 100))\n)\n";

Fuzzyfier distance_fuzzyfier() {
  return Fuzzyfier(parse_shapes(std::string(kDistance) + kAngle, "shape_ctof.txt"),
                   parse_associations("(TargetDistance Distance)\n(TargetAngle Angle)\n", "ctof.txt"));
}

const Fuzzyfier::FuzzyDatum* find(const std::vector<Fuzzyfier::FuzzyDatum>& v, const std::string& label) {
  for (const auto& f : v)
    if (f.label == label) return &f;
  return nullptr;
}
}  // namespace

// §10.4.1, first example as corrected by NOTES.md: 45 -> NEAREST 0.75, NEAR 0.25.
TEST(ManualExamples, Fuzzification45) {
  const auto out = distance_fuzzyfier().fuzzify(CrispDataList{{"TargetDistance", 45, 1}});
  ASSERT_EQ(out.size(), 2u);  // FAR = <0, 1> is not stored
  ASSERT_NE(find(out, "NEAREST"), nullptr);
  EXPECT_DOUBLE_EQ(find(out, "NEAREST")->value.value, 0.75);
  EXPECT_DOUBLE_EQ(find(out, "NEAR")->value.value, 0.25);
  EXPECT_DOUBLE_EQ(find(out, "NEAR")->value.reliability, 1.0);
  EXPECT_EQ(find(out, "FAR"), nullptr);
}

// §10.4.1 second example: <TargetDistance, 80, 0.4> -> NEAR 1, and the zeros
// are stored because their reliability is not 1.
TEST(ManualExamples, Fuzzification80) {
  const auto out = distance_fuzzyfier().fuzzify(CrispDataList{{"TargetDistance", 80, 0.4}});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_DOUBLE_EQ(find(out, "NEAREST")->value.value, 0.0);
  EXPECT_DOUBLE_EQ(find(out, "NEAREST")->value.reliability, 0.4);
  EXPECT_DOUBLE_EQ(find(out, "NEAR")->value.value, 1.0);
  EXPECT_DOUBLE_EQ(find(out, "NEAR")->value.reliability, 0.4);
  EXPECT_DOUBLE_EQ(find(out, "FAR")->value.value, 0.0);
  EXPECT_DOUBLE_EQ(find(out, "FAR")->value.reliability, 0.4);
}

// §10.4.2: TargetNorth = <0.9, 1>, TargetNorthNearest = <0.9, 0.4>.
TEST(ManualExamples, TargetNorthPredicates) {
  const Fuzzyfier fz = distance_fuzzyfier();
  const auto defs = parse_definitions(
      "TargetNearest = (D TargetDistance NEAREST);\n"
      "TargetNorth = (OR (D TargetAngle NORTH_1)\n (D TargetAngle NORTH_2));\n"
      "TargetNorthNearest = (AND (P TargetNorth)\n (P TargetNearest));\n",
      "Predicate.ini");
  SymbolTable preds, behaviors;
  for (const auto& d : defs) preds.intern(d.name);
  Defuzzyfier none;
  ExpressionCompiler compiler(fz, preds, behaviors, none);
  ExpressionPool pool;
  DefinitionList list;
  for (const auto& d : defs) list.add(preds.find(d.name), compiler.compile(d.expr, pool));
  Preacher preacher(&pool, list);
  EvalState s;
  s.fuzzy.assign(static_cast<std::size_t>(fz.slot_count()), FuzzyValue{});
  s.predicates.assign(3, FuzzyValue{});
  s.fuzzy[static_cast<std::size_t>(fz.slot("TargetDistance", "NEAREST"))] = {1.0, 0.4};
  s.fuzzy[static_cast<std::size_t>(fz.slot("TargetAngle", "NORTH_1"))] = {0.9, 0.7};
  s.fuzzy[static_cast<std::size_t>(fz.slot("TargetAngle", "NORTH_2"))] = {0.0, 1.0};
  s.fuzzy[static_cast<std::size_t>(fz.slot("TargetAngle", "WEST"))] = {0.1, 0.7};
  preacher.evaluate(s);
  const FuzzyValue nearest = s.predicates[static_cast<std::size_t>(preds.find("TargetNearest"))];
  const FuzzyValue north = s.predicates[static_cast<std::size_t>(preds.find("TargetNorth"))];
  const FuzzyValue both = s.predicates[static_cast<std::size_t>(preds.find("TargetNorthNearest"))];
  EXPECT_DOUBLE_EQ(nearest.value, 1.0);
  EXPECT_DOUBLE_EQ(nearest.reliability, 0.4);
  EXPECT_DOUBLE_EQ(north.value, 0.9);
  EXPECT_DOUBLE_EQ(north.reliability, 1.0);
  EXPECT_DOUBLE_EQ(both.value, 0.9);
  EXPECT_DOUBLE_EQ(both.reliability, 0.4);
}

// §10.4.6: (100*0.8 + 75*0.6 + 25*0.9) / 2.3 = 64.13.
TEST(ManualExamples, SingletonDefuzzification) {
  Defuzzyfier d(parse_shapes(kSpeedModule, "s_shape.txt"), parse_associations("(SpeedModule SPEEDMODULE)", "s_ftoc.txt"));
  const CommandList out = d.defuzzify({{"SpeedModule", "VERY_FAST", 0.8}, {"SpeedModule", "FAST", 0.6},
                                       {"SpeedModule", "SLOW", 0.9}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].name, "SpeedModule");
  EXPECT_NEAR(out[0].value, 64.13, 0.005);
  EXPECT_NEAR(out[0].value, 147.5 / 2.3, 1e-9);
}

// §10.4.9 with the 0.57 typo read as 0.56: FAST 0.34773, SLOW 0.50128.
TEST(ManualExamples, Composition) {
  Composer c(WeightComposerKind::kMult, FloatComposerKind::kAverage, {5});
  const int kFast = 3, kSlow = 2, kGoToTarget = 0, kAvoidObstacle = 1;
  ProposalList p = {{0, kFast, kGoToTarget, 1, 0.56, 1},
                    {0, kFast, kGoToTarget, 1, 0.478, 1},
                    {0, kSlow, kGoToTarget, 1, 0.968, 1},
                    {0, kSlow, kAvoidObstacle, 2, 0.354, 1}};
  const std::vector<double> weights = {0.67, 1.0};
  ComposedActions out = c.make_output();
  c.compose(p, &weights, out);
  EXPECT_NEAR(out.get(0, kFast), 0.34773, 1e-5);
  EXPECT_NEAR(out.get(0, kSlow), 0.50128, 1e-5);
  EXPECT_FALSE(out.present(0, 0));
  // The first step alone (§10.4.9's intermediate list).
  c.weight_in_place(p, weights);
  EXPECT_NEAR(p[0].value, 0.3752, 1e-9);
  EXPECT_NEAR(p[1].value, 0.32026, 1e-9);
  EXPECT_NEAR(p[2].value, 0.64856, 1e-9);
  EXPECT_NEAR(p[3].value, 0.354, 1e-9);
}

TEST(ManualExamples, OtherComposers) {
  const std::vector<double> weights = {0.5};
  ProposalList p = {{0, 0, 0, 1, 0.2, 1}, {0, 0, 0, 1, 0.8, 1}};
  ComposedActions out;
  Composer(WeightComposerKind::kMax, FloatComposerKind::kMin, {1}).compose(p, &weights, out);
  EXPECT_DOUBLE_EQ(out.get(0, 0), 0.5);  // min(max(.2,.5), max(.8,.5))
  Composer(WeightComposerKind::kMin, FloatComposerKind::kMax, {1}).compose(p, &weights, out);
  EXPECT_DOUBLE_EQ(out.get(0, 0), 0.5);  // max(min(.2,.5), min(.8,.5))
  Composer(WeightComposerKind::kMult, FloatComposerKind::kMax, {1}).compose(p, &weights, out);
  EXPECT_DOUBLE_EQ(out.get(0, 0), 0.4);
}

// §10.3.6: GoToTarget 0.467, AvoidObstacle 0.679, threshold 0.5.
TEST(ManualExamples, ThresholdFilter) {
  ThresholdFilter f(0.5);
  EXPECT_FALSE(f.active({0.467, 1.0}));
  EXPECT_TRUE(f.active({0.679, 1.0}));
  ThresholdFilter def;  // default 0.49 (§10.4.4)
  EXPECT_DOUBLE_EQ(def.threshold(), 0.49);
  EXPECT_FALSE(def.active({0.49, 1.0}));
  EXPECT_TRUE(def.active({0.5, 0.2}));
  ThresholdFilter composite(0.49, true);  // the 2009 engine's filter
  EXPECT_FALSE(composite.active({0.9, 0.45}));
  EXPECT_TRUE(composite.active({0.9, 0.5}));
}

// Barycenter defuzzification by hand: TRI 0 10 20 at 0.5 (area 7.5,
// centroid 10) and TRI 20 30 40 at 1 (area 10, centroid 30):
// (7.5*10 + 10*30) / 17.5 = 21.428571.
TEST(ManualExamples, BarycenterDefuzzification) {
  Defuzzyfier d(parse_shapes("(OUT (TRI (LOW 0 10 20)) (TRI (HIGH 20 30 40)))", "s_shape.txt"),
                parse_associations("(Speed OUT)", "s_ftoc.txt"), DefuzzMethod::kBarycenter);
  const CommandList out = d.defuzzify({{"Speed", "LOW", 0.5}, {"Speed", "HIGH", 1.0}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].value, 375.0 / 17.5, 1e-9);
  EXPECT_THROW(Defuzzyfier(parse_shapes(kSpeedModule, "s"), parse_associations("(S SPEEDMODULE)", "f"),
                           DefuzzMethod::kBarycenter),
               mrt::common::ParseError);
}

// Outputs on a shape declared `(CIRCULAR lo hi)` use a circular mean: 350
// and 30 with equal weights -> 10 on [0, 360); a heading on a signed range
// [-180, 180) with -10 and 30 -> 10 as well, and -170 (= 190) and 150 ->
// their circular mean 170 (the plain mean would be -10).
TEST(ManualExamples, CircularMeanForAngles) {
  Defuzzyfier d(parse_shapes("(ANG (CIRCULAR 0 360) (SNG (A350 350)) (SNG (A30 30)) (SNG (A90 90)) (SNG (A270 270)))"
                             "(SIGNED (CIRCULAR -180 180) (SNG (M10 -10)) (SNG (P30 30)) (SNG (M170 -170)) (SNG (P150 150)))",
                             "s"),
                parse_associations("(SpeedAngle ANG) (Heading SIGNED)", "f"));
  const CommandList out = d.defuzzify({{"SpeedAngle", "A350", 0.5}, {"SpeedAngle", "A30", 0.5},
                                       {"Heading", "M10", 0.5}, {"Heading", "P30", 0.5}});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].value, 10.0, 1e-9);  // SpeedAngle: circular on [0, 360)
  EXPECT_NEAR(out[1].value, 10.0, 1e-9);  // Heading: circular on [-180, 180)
  const CommandList h = d.defuzzify({{"Heading", "M170", 0.5}, {"Heading", "P150", 0.5}});
  ASSERT_EQ(h.size(), 1u);
  EXPECT_NEAR(h[0].value, 170.0, 1e-9);
  // Opposite angles cancel out: no command.
  EXPECT_TRUE(d.defuzzify({{"SpeedAngle", "A90", 0.5}, {"SpeedAngle", "A270", 0.5}}).empty());
}
