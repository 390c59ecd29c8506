// The ball's team settings (class keys `maneuver`, `keep_teammate_link`,
// `fusion`): a kick taken into the velocity, a teammate's track kept
// through its kick, the fusion rule per class. Values worked out by hand.
#include <gtest/gtest.h>

#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_map/kalman.h"
#include "mrt_map/tracker.h"

using namespace mrt::map;

namespace {

// Team fusion by covariance intersection; Ball overrides it, Robot keeps it.
std::string model(const std::string& ball_keys) {
  return "classes:\n"
         "  Ball: {motion: constant_velocity, accel_noise: 3.0, fusion: independent" + ball_keys + "}\n"
         "  Ball2: {parent: Ball}\n"
         "  Robot: {motion: constant_velocity, accel_noise: 1.5}\n"
         "team: {fusion: covariance_intersection}\n";
}

RemoteTrack track(const std::string& robot, std::uint32_t id, int cls, double x, double var, double t) {
  RemoteTrack r;
  r.robot = robot;
  r.id = id;
  r.class_index = cls;
  r.estimate.x << x, 0, 0, 0;
  r.estimate.P = Vec4(var, var, 1, 1).asDiagonal();
  r.estimate.stamp = r.last_seen = t;
  r.sensors = {robot + "/cam"};
  return r;
}

}  // namespace

TEST(BallTeam, ModelKeysParsedInheritedAndChecked) {
  const ConceptualModel m = ConceptualModel::parse(model(", maneuver: impulse, keep_teammate_link: 2"), "m.yaml");
  for (const char* name : {"Ball", "Ball2"}) {  // Ball2 inherits them
    const ClassDef& c = m.at(m.find(name));
    EXPECT_EQ(c.fusion, ClassDef::Fusion::kIndependent) << name;
    EXPECT_TRUE(c.impulse_maneuver) << name;
    EXPECT_DOUBLE_EQ(c.keep_link, 2.0) << name;
  }
  const ClassDef& robot = m.at(m.find("Robot"));
  EXPECT_EQ(robot.fusion, ClassDef::Fusion::kTeam);
  EXPECT_FALSE(robot.impulse_maneuver);
  EXPECT_DOUBLE_EQ(robot.keep_link, 0.0);
  auto error = [](const std::string& keys) {
    try {
      ConceptualModel::parse(model(keys), "m.yaml");
    } catch (const mrt::common::ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error(", maneuver: jump").find("m.yaml:2:"), std::string::npos);
  EXPECT_NE(error(", maneuver: jump").find("'reset' or 'impulse'"), std::string::npos);
  EXPECT_NE(error(", keep_teammate_link: -1").find("m.yaml:2:"), std::string::npos);
  EXPECT_NE(error(", fusion: average").find("m.yaml:2:"), std::string::npos);
}

TEST(BallTeam, ImpulseManeuverTakesTheKickIntoTheVelocity) {
  // Predicted x = (0, 0), v = (1, 0), P = 0.01 I; the observation (0.3, 0),
  // R = 0.01 I, comes dt = 0.1 s after the last one; s = 2 m/s.
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n  Ball: {motion: constant_velocity, init_speed_sigma: 2, maneuver: impulse}\n"
      "  Cart: {motion: constant_velocity, init_speed_sigma: 2}\n", "m.yaml");
  Estimate e;
  e.x << 0, 0, 1, 0;
  e.P = 0.01 * Mat4::Identity();
  const Mat2 R = 0.01 * Mat2::Identity();
  // Impulse: P_pp = 0.01 + 0.1^2 * 4 = 0.05, P_pv = 0.1 * 4 = 0.4, P_vv =
  // 4.01. S = 0.06: x = 0.3 * 0.05 / 0.06 = 0.25, vx = 1 + 0.3 * 0.4 / 0.06
  // = 3; P_pp = 0.05 - 0.05^2 / 0.06 = 1/120, P_vv = 4.01 - 0.4^2 / 0.06.
  Estimate kick = e;
  maneuver(kick, m.at(m.find("Ball")), 0.1, R);
  EXPECT_NEAR(kick.P(0, 2), 0.4, 1e-12);
  update(kick, Vec2(0.3, 0.0), R);
  EXPECT_NEAR(kick.x(0), 0.25, 1e-12);
  EXPECT_NEAR(kick.x(2), 3.0, 1e-12);
  EXPECT_NEAR(kick.P(0, 0), 1.0 / 120.0, 1e-12);
  EXPECT_NEAR(kick.P(2, 2), 4.01 - 0.16 / 0.06, 1e-12);
  // Reset (the default): P_pp = 0.02, uncorrelated, P_vv = 4: x = 0.3 *
  // 0.02 / 0.03 = 0.2, the velocity unchanged (1) until the next update.
  Estimate reset = e;
  maneuver(reset, m.at(m.find("Cart")), 0.1, R);
  update(reset, Vec2(0.3, 0.0), R);
  EXPECT_NEAR(reset.x(0), 0.2, 1e-12);
  EXPECT_NEAR(reset.x(2), 1.0, 1e-12);
  EXPECT_NEAR(reset.P(2, 2), 4.0, 1e-12);
}

TEST(BallTeam, TeammatesTrackKeptThroughItsKick) {
  // r2 (track 7) and r3 (track 9) report the ball at x = 0 (P = 0.01 I):
  // one anchor. 0.1 s later r2 has seen a kick (x = 1), r3 not yet (x = 0).
  // 1 m is far outside the gate (d2 ~ 1 / 0.02 = 50) and the 0.5 m
  // manoeuvre radius. Kept link (2 m): one anchor, the information fusion
  // of the two, x = 0.5, P_pp = 0.005. Without: r2's track is a new anchor.
  for (const bool keep : {true, false}) {
    const ConceptualModel m = ConceptualModel::parse(model(keep ? ", keep_teammate_link: 2.0" : ""), "m.yaml");
    Tracker tr(m);
    tr.cycle(0.0, {}, {track("r2", 7, 0, 0.0, 0.01, 0.0), track("r3", 9, 0, 0.0, 0.01, 0.0)});
    ASSERT_EQ(tr.anchors().size(), 1u);
    tr.cycle(0.1, {}, {track("r2", 7, 0, 1.0, 0.01, 0.1), track("r3", 9, 0, 0.0, 0.01, 0.1)});
    if (keep) {
      ASSERT_EQ(tr.anchors().size(), 1u);
      EXPECT_EQ(tr.anchors()[0].remote.size(), 2u);
      EXPECT_NEAR(tr.anchors()[0].fused.x(0), 0.5, 1e-9);
      EXPECT_NEAR(tr.anchors()[0].fused.P(0, 0), 0.005, 1e-9);
    } else {
      ASSERT_EQ(tr.anchors().size(), 2u);
      EXPECT_EQ(tr.anchors()[0].id, 1u);
      EXPECT_NEAR(tr.anchors()[0].fused.x(0), 0.0, 1e-9);  // r3's alone
      EXPECT_EQ(tr.anchors()[1].id, 2u);
      EXPECT_NEAR(tr.anchors()[1].fused.x(0), 1.0, 1e-9);  // r2's
    }
  }
}

TEST(BallTeam, FusionRulePerClass) {
  // Two teammates' tracks of one object: r2 at x = 0 (P_pp = 0.04), r3 at
  // x = 0.1 (0.01). Ball (independent): P = (25 + 100)^-1 = 0.008, x =
  // 0.008 * 100 * 0.1 = 0.08. Robot (the team's covariance intersection):
  // trace(P(w)) = 2 / (25 w + 100 (1 - w)) is least at w = 0: r3's alone.
  const ConceptualModel m = ConceptualModel::parse(model(""), "m.yaml");
  for (const char* name : {"Ball", "Robot"}) {
    const int cls = m.find(name);
    Tracker tr(m);
    tr.cycle(0.0, {}, {track("r2", 7, cls, 0.0, 0.04, 0.0), track("r3", 9, cls, 0.1, 0.01, 0.0)});
    ASSERT_EQ(tr.anchors().size(), 1u) << name;
    const Anchor& a = tr.anchors()[0];
    const bool ball = std::string(name) == "Ball";
    EXPECT_NEAR(a.fused.x(0), ball ? 0.08 : 0.1, 1e-9) << name;
    EXPECT_NEAR(a.fused.P(0, 0), ball ? 0.008 : 0.01, 1e-9) << name;
  }
}
