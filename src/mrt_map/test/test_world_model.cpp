// WorldModel: crisp data for Mr. BRIAN, coordination parameters, drops,
// and a ball lost by one robot and kept through its teammate.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_map/world_model.h"

using namespace mrt::map;

namespace {
const char* kModel =
    "classes:\n"
    "  Ball: {motion: constant_velocity, accel_noise: 1, attributes: {color: {symbols: {orange: 1, red: 0.8}}}}\n"
    "  Robot: {motion: constant_velocity}\n"
    "  Opponent: {parent: Robot, attributes: {color: {symbols: {cyan: 1}}}}\n"
    "tracker: {confirm_hits: 2, coast_after: 0.3, drop_after: 2.0, reliability_tau: 1.0}\n"
    "crisp:\n"
    "  - {name: BallDistance, class: Ball, quantity: distance, scale: 1000}\n"
    "  - {name: BallAngle, class: Ball, quantity: bearing, scale: 57.29577951308232}\n"
    "  - {name: OpponentNearest, class: Opponent, quantity: distance, scale: 1000, missing: 99999}\n"
    "  - {name: PassTargetX, parameter: PassTargetX, scale: 1000}\n";

PerceptObject at(const std::string& cls, const std::string& color, double x, double y) {
  PerceptObject o;
  o.membership_class = cls;
  o.attributes.push_back({"color", 0.0, color, 0.0, 1.0});
  o.set("x", x, 0.05, 1.0);
  o.set("y", y, 0.05, 1.0);
  return o;
}
}  // namespace

TEST(WorldModel, CrispDataAndParameters) {
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  WorldModel w(m, {"r1", 0.5});
  RobotPose pose;
  pose.theta = M_PI / 2;  // facing +y
  w.set_robot_pose(pose, 0.0);
  // Ball (red: degree 0.8) in the robot frame at (1, -1) = world (1, 1).
  for (double t : {0.0, 0.1}) {
    w.add_percept({at("Ball", "red", 1, -1)}, pose, t, t, "cam");
    w.update(t);
  }
  w.set_parameter("PassTargetX", 2.5, 0.8, 0.1);
  const auto c = w.crisp(0.1);
  ASSERT_EQ(c.size(), 4u);
  // Distance sqrt(2) m = 1414.21 mm; bearing atan2(1,1) - 90 deg = -45 deg;
  // reliability = degree 0.8 * exp(-0 / 1) = 0.8.
  EXPECT_NEAR(c[0].value, 1000 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(c[0].reliability, 0.8, 1e-12);
  EXPECT_NEAR(c[1].value, -45.0, 1e-6);
  EXPECT_EQ(c[2].name, "OpponentNearest");
  EXPECT_DOUBLE_EQ(c[2].value, 99999);  // no opponent: missing, reliability 0
  EXPECT_DOUBLE_EQ(c[2].reliability, 0.0);
  EXPECT_DOUBLE_EQ(c[3].value, 2500);
  EXPECT_DOUBLE_EQ(c[3].reliability, 0.8);
  // 0.5 s later without a sighting: reliability 0.8 * exp(-0.5) = 0.48522.
  w.update(0.6);
  EXPECT_NEAR(w.crisp(0.6)[0].reliability, 0.8 * std::exp(-0.5), 1e-9);
}

TEST(WorldModel, DropsAndCountsBadInput) {
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  WorldModel w(m, {"r1", 0.5});
  RobotPose pose;
  PerceptObject nan_obj = at("Ball", "orange", NAN, 0);
  EXPECT_EQ(w.add_percept({at("Car", "red", 1, 0), nan_obj, at("Ball", "orange", 1, 0)}, pose, 1.0, 1.0, "cam"), 1);
  EXPECT_EQ(w.add_percept({at("Ball", "orange", 1, 0), at("Ball", "orange", 2, 0)}, pose, 0.2, 1.0, "cam"), 0);
  EXPECT_EQ(w.counters().unknown_class, 1u);
  EXPECT_EQ(w.counters().non_finite, 1u);
  EXPECT_EQ(w.counters().stale, 2u);  // 0.8 s old > 0.5
  EXPECT_EQ(w.counters().accepted, 1u);
}

TEST(WorldModel, BallLostByOneRobotIsKeptByTheTeammate) {
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  WorldModel r1(m, {"r1", 0.5}), r2(m, {"r2", 0.5});
  RobotPose p1, p2;
  p2.x = 4;
  double t = 0;
  auto step = [&](bool r1_sees, bool r2_sees) {
    // Ball at rest at world (2, 1).
    if (r1_sees) r1.add_percept({at("Ball", "orange", 2, 1)}, p1, t, t, "cam");
    if (r2_sees) r2.add_percept({at("Ball", "orange", -2, 1)}, p2, t, t, "cam");
    r1.add_teammate_model("r2", r2.local_tracks(), t, &p2);
    r2.add_teammate_model("r1", r1.local_tracks(), t, &p1);
    r1.update(t);
    r2.update(t);
    t += 0.1;
  };
  for (int k = 0; k < 5; ++k) step(true, true);
  ASSERT_EQ(r1.tracker().anchors().size(), 1u);  // one anchor, not two
  const std::uint32_t id = r1.tracker().anchors()[0].id;
  EXPECT_EQ(r1.tracker().anchors()[0].sources.count("r2/cam"), 1u);
  for (int k = 0; k < 10; ++k) step(false, true);  // r1 loses it for 1 s
  ASSERT_EQ(r1.tracker().anchors().size(), 1u);
  const Anchor& a = r1.tracker().anchors()[0];
  EXPECT_EQ(a.id, id);
  EXPECT_EQ(a.status, AnchorStatus::kConfirmed);  // kept alive by r2
  EXPECT_NEAR(a.fused.x(0), 2.0, 0.05);
  EXPECT_NEAR(a.fused.x(1), 1.0, 0.05);
  // r1 reads r2's model of the previous cycle (last seen t - 0.2 after the
  // loop's final t += 0.1): reliability = 1 (orange) * exp(-0.2 / 1).
  EXPECT_NEAR(r1.crisp(t)[0].reliability, std::exp(-0.2), 1e-9);
}

// An orange object only r1 sees (a shirt behind the goal) and the ball that
// r1 and r2 both see, each seen by r1 in every frame: equally reliable, but
// `best_supported` takes the ball the teammate reports too.
TEST(WorldModel, BestSupportedPrefersWhatTeammatesReport) {
  const std::string model = std::string(kModel) +
                            "  - {name: MostReliableX, class: Ball, quantity: x, select: most_reliable}\n"
                            "  - {name: BestSupportedX, class: Ball, quantity: x, select: best_supported}\n";
  const ConceptualModel m = ConceptualModel::parse(model, "t.yaml");
  WorldModel r1(m, {"r1", 0.5}), r2(m, {"r2", 0.5});
  RobotPose p1, p2;
  p2.x = 4;
  double t = 0;
  for (int k = 0; k < 5; ++k, t += 0.1) {
    // The shirt first: its anchor gets the lower id, which wins a tie.
    r1.add_percept({at("Ball", "orange", -1, 3), at("Ball", "orange", 2, 1)}, p1, t, t, "cam");
    r2.add_percept({at("Ball", "orange", -2, 1)}, p2, t, t, "cam");  // world (2, 1)
    r1.add_teammate_model("r2", r2.local_tracks(), t, &p2);
    r1.update(t);
    r2.update(t);
  }
  const double now = t - 0.1;
  ASSERT_EQ(r1.tracker().anchors().size(), 2u);
  const Anchor& shirt = r1.tracker().anchors()[0];
  const Anchor& ball = r1.tracker().anchors()[1];
  ASSERT_NEAR(ball.fused.x(0), 2.0, 0.05);
  ASSERT_EQ(ball.remote.count("r2"), 1u);
  // Own sightings now (c = 0.5 each); r2's track last seen one cycle ago
  // (r1 reads r2's model before r2's update): 0.5 exp(-0.1).
  EXPECT_NEAR(r1.tracker().support(shirt, now), 0.5, 1e-12);
  EXPECT_NEAR(r1.tracker().support(ball, now), 1.0 - 0.5 * (1.0 - 0.5 * std::exp(-0.1)), 1e-9);  // 0.726209
  const auto c = r1.crisp(now);
  ASSERT_EQ(c.size(), 6u);
  EXPECT_NEAR(c[4].value, -1.0, 0.05);  // most_reliable: a tie (1.0 each), the lower id
  EXPECT_NEAR(c[5].value, 2.0, 0.05);   // best_supported: the ball
  EXPECT_DOUBLE_EQ(c[5].reliability, 1.0);  // the reported reliability is still degree * exp(-age / tau)
  // The teammate's report grows old: at 0.5 s without any sighting the
  // ball's support is 1 - (1 - 0.5 e^-0.5)(1 - 0.5 e^-0.6), the shirt's 0.5 e^-0.5.
  r1.update(now + 0.5);
  const double later = now + 0.5;
  EXPECT_NEAR(r1.tracker().support(r1.tracker().anchors()[0], later), 0.5 * std::exp(-0.5), 1e-9);
  EXPECT_NEAR(r1.tracker().support(r1.tracker().anchors()[1], later),
              1.0 - (1.0 - 0.5 * std::exp(-0.5)) * (1.0 - 0.5 * std::exp(-0.6)), 1e-9);
}
