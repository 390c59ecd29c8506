// Issue 11, "wrong answers": circular outputs declared in the configuration
// (singleton and barycenter), the zero-WANT behaviour in the manual
// profile's average, the 2009 engine's float comparison at the 0.49
// threshold, and the select-best composer of manual eq. 10.5. Every
// expected number is worked by hand in the comment above its assertion.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "mrt_brian/brian.h"
#include "mrt_brian/cando_filter.h"
#include "mrt_brian/composer.h"
#include "mrt_brian/defuzzyfier.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;
namespace fs = std::filesystem;

namespace {

// Distance between two angles on a circle of `period`.
double circ_dist(double a, double b, double period = 360.0) {
  const double d = std::fmod(std::fabs(a - b), period);
  return std::min(d, period - d);
}

std::map<std::string, double> as_map(const CommandList& l) {
  std::map<std::string, double> m;
  for (const auto& c : l) m[c.name] = c.value;
  return m;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

// DIV 0 10 350 360 at mu 1 is symmetric about 0/360: the circular
// barycenter is 0. The linear one gave (5*10/3 + 5*(360-10/3)) / 10 = 180,
// half a turn off.
TEST(CircularOutputs, BarycenterOfASetStraddlingZero) {
  Defuzzyfier d(parse_shapes("(HEAD (CIRCULAR 0 360) (DIV (NORTH 0 10 350 360)) (REC (EAST 80 100)))", "s_shape.txt"),
                parse_associations("(Heading HEAD)", "s_ftoc.txt"), DefuzzMethod::kBarycenter);
  ASSERT_TRUE(d.is_angle(0));
  CommandList out = d.defuzzify({{"Heading", "NORTH", 1.0}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_LT(circ_dist(out[0].value, 0.0), 1e-9);
  EXPECT_GE(out[0].value, 0.0);
  EXPECT_LT(out[0].value, 360.0);
  // With EAST (REC 80 100) at 0.5 too, k = pi/180:
  //  NORTH: 2 * integral_0^10 (1 - x/10) cos(kx) dx = 2 (1 - cos 10deg) / (10 k^2)
  //         = 2 * 0.0151922 / 0.0030462 = 9.97464 (along 0deg; the sines cancel);
  //  EAST:  0.5 * integral_80^100 e^{ikx} dx = 0.5 * (1/k) * 2 sin 10deg * e^{i 90deg}
  //         = 0.5 * 57.29578 * 0.347296 = 9.94931 (along 90deg);
  //  atan2(9.94931, 9.97464) = 44.927 deg.
  out = d.defuzzify({{"Heading", "NORTH", 1.0}, {"Heading", "EAST", 0.5}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].value, 44.927, 1e-3);
}

// Singleton on a declared [0, 360): 350 and 30 at equal weights -> 10; the
// same labels on an undeclared shape stay linear: (350 + 30) / 2 = 190.
TEST(CircularOutputs, SingletonOnlyWhenDeclared) {
  const std::string sets = "(SNG (A350 350)) (SNG (A30 30)) (SNG (A90 90)) (SNG (A270 270)))";
  Defuzzyfier d(parse_shapes("(ANG (CIRCULAR 0 360) " + sets + " (LIN " + sets, "s"),
                parse_associations("(Course ANG) (SpeedAngle LIN)", "f"));
  auto out = as_map(d.defuzzify({{"Course", "A350", 0.5}, {"Course", "A30", 0.5},
                                 {"SpeedAngle", "A350", 0.5}, {"SpeedAngle", "A30", 0.5}}));
  EXPECT_NEAR(out["Course"], 10.0, 1e-9);
  // The name no longer decides (manual profile): "SpeedAngle" on a linear shape.
  EXPECT_NEAR(out["SpeedAngle"], 190.0, 1e-9);
  // Opposite angles cancel out: no command.
  EXPECT_TRUE(d.defuzzify({{"Course", "A90", 0.5}, {"Course", "A270", 0.5}}).empty());
}

// A signed range stays signed: on [-180, 180), 170 and -150 (= 210) at equal
// weights have the circular mean 190 = -170; not declared circular, the
// plain mean is (170 - 150) / 2 = 10. Both results lie in the shape's range.
TEST(CircularOutputs, SignedRangeStaysSigned) {
  const std::string sets = "(SNG (L 170)) (SNG (R -150)))";
  Defuzzyfier d(parse_shapes("(TURN (CIRCULAR -180 180) " + sets + " (PLAIN " + sets, "s"),
                parse_associations("(Turn TURN) (Steer PLAIN)", "f"));
  auto out = as_map(d.defuzzify({{"Turn", "L", 1.0}, {"Turn", "R", 1.0}, {"Steer", "L", 1.0}, {"Steer", "R", 1.0}}));
  EXPECT_NEAR(out["Turn"], -170.0, 1e-9);
  EXPECT_NEAR(out["Steer"], 10.0, 1e-9);
}

// The legacy profile keeps the 2009 rule: a name containing "Angle" is an
// angle in degrees with k = 0.01745 rad/deg. 350 and 30 at equal weights:
// 350k = 6.107500 rad = -0.175685 rad (mod 2 pi, since 360k != 2 pi) and
// 30k = 0.523500 rad; equal weights: the mean angle is their midpoint
// 0.173908 rad, / k = 9.96604 (not 10: the 2009 constant's error).
TEST(CircularOutputs, LegacyKeepsTheNameRule) {
  Defuzzyfier d(parse_shapes("(LIN (SNG (A350 350)) (SNG (A30 30)))", "s"),
                parse_associations("(SpeedAngle LIN) (Heading LIN)", "f"), DefuzzMethod::kSingleton,
                Profile::kLegacy);
  auto out = as_map(d.defuzzify({{"SpeedAngle", "A350", 0.5}, {"SpeedAngle", "A30", 0.5},
                                 {"Heading", "A350", 0.5}, {"Heading", "A30", 0.5}}));
  EXPECT_NEAR(out["SpeedAngle"], 9.96604, 1e-5);
  EXPECT_NEAR(out["Heading"], 190.0, 1e-9);
}

TEST(CircularOutputs, BadDeclarationsAreParseErrors) {
  EXPECT_THROW(parse_shapes("(A (CIRCULAR 360 0) (SNG (X 1)))", "s"), mrt::common::ParseError);
  EXPECT_THROW(parse_shapes("(A (CIRCULAR 0) (SNG (X 1)))", "s"), mrt::common::ParseError);
  EXPECT_THROW(parse_shapes("(A (CIRCULAR 0 360) (CIRCULAR 0 360) (SNG (X 1)))", "s"), mrt::common::ParseError);
}

// The harvesting example (manual profile), auto, battery full, not grasping:
// GoToHome is active (CANDO Auto = 1) but its WANT is 0.
// TargetDistance 110: NEAR 0.5, FAR 0.5 -> GoToTarget proposes FAST 0.5 and
// SLOW 0.5 (WANT 1). HomeDistance 200: GoToHome proposes FAST 1 with weight 0.
// Before: FAST = mean(0.5, 0) = 0.25, SLOW 0.5 -> (75*0.25 + 25*0.5) / 0.75
// = 41.67. Now GoToHome contributes nothing: (75*0.5 + 25*0.5) / 1 = 50.
TEST(ZeroWant, ContributesNothingToTheAverageInTheManualProfile) {
  auto brian = Brian::from_path(MRT_BRIAN_EXAMPLES_DIR "/harvesting");
  const CrispDataList in = {{"Status", 1, 1},          {"TargetVisible", 1, 1}, {"TargetDistance", 110, 1},
                            {"TargetAngle", 0, 1},     {"Battery", 100, 1},     {"Grasping", 0, 1},
                            {"ObstacleDistance", 500, 1}, {"ObstacleAngle", 0, 1}, {"HomeDistance", 200, 1},
                            {"HomeAngle", 0, 1}};
  auto out = as_map(brian->run(in));
  EXPECT_NEAR(out["SpeedModule"], 50.0, 1e-9);
  // The composer alone: one label, weights {1, 0}: the mean of 0.5 and 0
  // without the skip, 0.5 with it.
  Composer c(WeightComposerKind::kMult, FloatComposerKind::kAverage, {1});
  const ProposalList p = {{0, 0, 0, 1, 0.5, 1}, {0, 0, 1, 1, 1.0, 1}};
  const std::vector<double> w = {1.0, 0.0};
  ComposedActions o;
  c.compose(p, &w, o);
  EXPECT_DOUBLE_EQ(o.get(0, 0), 0.25);
  c.set_skip_zero_weight(true);
  c.compose(p, &w, o);
  EXPECT_DOUBLE_EQ(o.get(0, 0), 0.5);
}

// 0.49 read from a file or a message is 0.49f in the 2009 engine, which
// compared float with float: 0.49f > 0.49f is false, the behaviour is
// dropped. In double, 0.49f = 0.490000009537 > 0.49, which kept it. The
// manual profile compares doubles: 0.49 > 0.49 is false too, and
// 0.490000009537 > 0.49 is true there (it is above the threshold).
TEST(LegacyThreshold, ExactlyPointFortyNineIsDroppedAsInFloat) {
  const double f049 = static_cast<double>(0.49f);
  ASSERT_GT(f049, 0.49);
  ThresholdFilter legacy(0.49, true, true);
  EXPECT_FALSE(legacy.active({f049, 1.0}));   // CANDO value exactly 0.49f
  EXPECT_FALSE(legacy.active({0.9, f049}));   // reliability exactly 0.49f
  EXPECT_TRUE(legacy.active({0.4900001, 0.9}));  // next floats above 0.49f: kept
  ThresholdFilter manual(0.49);
  EXPECT_FALSE(manual.active({0.49, 1.0}));
  EXPECT_TRUE(manual.active({f049, 1.0}));
}

// The whole legacy engine: Cruise's CANDO and WANT are the reliability-0.49
// datum's <1, 0.49>. The composite filter drops it (0.49f > 0.49f is false):
// no command. With reliability 0.5 it passes and Speed = FAST = 30.
TEST(LegacyThreshold, EngineDropsTheBehaviourAtExactlyPointFortyNine) {
  const fs::path d = fs::temp_directory_path() / ("brian_threshold_" + std::to_string(::getpid()));
  fs::create_directories(d);
  write(d / "shape_ctof.txt", "(DIST (TOR (FAR 0 100)))\n");
  write(d / "ctof.txt", "(Obstacle DIST)\n");
  write(d / "Predicate.ini", "Far = (D Obstacle FAR);\n");
  write(d / "Cando.ini", "Cruise = (P Far);\n");
  write(d / "want.txt", "Cruise = (P Far);\n");
  write(d / "behavior.txt", "(level 1 Cruise cruise.rul)\n");
  write(d / "cruise.rul", "(Far) => (Speed FAST);\n");
  write(d / "s_shape.txt", "(SPD (SNG (STOP 0)) (SNG (FAST 30)))\n");
  write(d / "s_ftoc.txt", "(Speed SPD)\n");
  BrianOptions o;
  o.profile = Profile::kLegacy;
  auto brian = Brian::from_path(d.string(), o);
  EXPECT_TRUE(brian->run({{"Obstacle", 200, 0.49}}).empty());
  auto out = as_map(brian->run({{"Obstacle", 200, 0.5}}));
  EXPECT_NEAR(out["Speed"], 30.0, 1e-9);
  // Manual profile: the reliability is not thresholded, the value 1 passes;
  // the rule's value is 1 * 0.49 and the command is FAST = 30.
  auto manual = Brian::from_path(d.string());
  EXPECT_NEAR(as_map(manual->run({{"Obstacle", 200, 0.49}}))["Speed"], 30.0, 1e-9);
  fs::remove_all(d);
}

// Eq. 10.5: the actions of the behaviour with the largest CANDO x WANT.
// Behaviour 0 (score 0.9 * 0.5 = 0.45) proposes FAST 0.8; behaviour 1
// (score 0.6 * 0.9 = 0.54) proposes SLOW 0.3 and STOP 0.6: only behaviour
// 1's actions are kept, as proposed (not weighted): SLOW 0.3, STOP 0.6.
TEST(SelectBest, KeepsTheBestBehavioursActions) {
  Composer c(WeightComposerKind::kMult, FloatComposerKind::kSelectBest, {3});
  const int kStop = 0, kSlow = 1, kFast = 2;
  const ProposalList p = {{0, kFast, 0, 1, 0.8, 1}, {0, kSlow, 1, 1, 0.3, 1}, {0, kStop, 1, 1, 0.6, 1}};
  const std::vector<double> weights = {0.5, 0.9}, scores = {0.45, 0.54};
  ComposedActions o;
  c.compose(p, &weights, o, &scores);
  EXPECT_FALSE(o.present(0, kFast));
  EXPECT_DOUBLE_EQ(o.get(0, kSlow), 0.3);
  EXPECT_DOUBLE_EQ(o.get(0, kStop), 0.6);
  EXPECT_EQ(parse_float_composer("best"), FloatComposerKind::kSelectBest);
  // Through the facade on the harvesting example with Auto off: only
  // ManualMove is active (CANDO = WANT = 1); RemoteSpeed 80 -> FAST 75,
  // RemoteAngle 90 -> WEST 90, the same as the average here.
  BrianOptions opt;
  opt.float_composer = FloatComposerKind::kSelectBest;
  auto brian = Brian::from_path(MRT_BRIAN_EXAMPLES_DIR "/harvesting", opt);
  auto out = as_map(brian->run({{"Status", 0, 1}, {"RemoteSpeed", 80, 1}, {"RemoteAngle", 90, 1}}));
  EXPECT_NEAR(out["SpeedModule"], 75.0, 1e-9);
  EXPECT_NEAR(out["SpeedAngle"], 90.0, 1e-9);
}
