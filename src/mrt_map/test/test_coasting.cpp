// Coasting and re-identification: the integrated Ornstein-Uhlenbeck motion
// (velocity_tau), per-class tracker settings, re-identification of a
// coasting anchor (tracker.reid_gate).
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_map/kalman.h"
#include "mrt_map/tracker.h"
#include "observations.h"

using namespace mrt::map;
using mrt::map::test::obs;


TEST(Kalman, OrnsteinUhlenbeckTransitionAndNoise) {
  ClassDef c;
  c.motion = MotionModel::kConstantVelocity;
  c.accel_noise = 1.0;  // q = 1
  c.velocity_tau = 1.0;
  // tau = dt = 1: a = e^-1 = 0.367879, F_pv = tau (1 - a) = 0.632121.
  const Mat4 F = transition(c, 1.0);
  EXPECT_NEAR(F(0, 2), 0.632121, 1e-6);
  EXPECT_NEAR(F(1, 3), 0.632121, 1e-6);
  EXPECT_NEAR(F(2, 2), 0.367879, 1e-6);
  EXPECT_NEAR(F(0, 0), 1.0, 1e-12);
  // Q_pp = q tau^2 (dt - 2 tau (1-a) + tau/2 (1-a^2)) = 1 - 1.264241 + 0.432332 = 0.168091;
  // Q_pv = q tau^2 / 2 (1-a)^2 = 0.5 * 0.399576 = 0.199788; Q_vv = q tau / 2 (1-a^2) = 0.432332
  // (also the midpoint-rule integrals of g_p^2, g_p g_v, g_v^2 over [0, 1]).
  const Mat4 Q = process_noise(c, 1.0);
  EXPECT_NEAR(Q(0, 0), 0.168091, 1e-6);
  EXPECT_NEAR(Q(0, 2), 0.199788, 1e-6);
  EXPECT_NEAR(Q(2, 0), 0.199788, 1e-6);
  EXPECT_NEAR(Q(3, 3), 0.432332, 1e-6);
  EXPECT_NEAR(Q(0, 1), 0.0, 1e-12);
  // tau = 0: constant velocity, F_pv = dt = 0.5, Q_pp = q dt^3 / 3 = 0.041667.
  c.velocity_tau = 0.0;
  EXPECT_NEAR(transition(c, 0.5)(0, 2), 0.5, 1e-12);
  EXPECT_NEAR(process_noise(c, 0.5)(0, 0), 0.125 / 3.0, 1e-12);
  // A long tau tends to constant velocity: tau = 1e4, dt = 0.5 -> F_pv ~ 0.5,
  // Q_pp ~ 0.041667 (relative difference of order dt / tau).
  c.velocity_tau = 1e4;
  EXPECT_NEAR(transition(c, 0.5)(0, 2), 0.5, 1e-4);
  EXPECT_NEAR(process_noise(c, 0.5)(0, 0), 0.125 / 3.0, 1e-5);
}

TEST(ConceptualModel, PerClassTrackerSettings) {
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n"
      "  Robot: {velocity_tau: 2, drop_after: 5, max_sigma: 4}\n"
      "  Opponent: {parent: Robot}\n"
      "  Ball: {}\n"
      "tracker: {reid_gate: 20}\n",
      "m.yaml");
  const ClassDef& opp = m.at(m.find("Opponent"));
  EXPECT_DOUBLE_EQ(opp.velocity_tau, 2.0);  // inherited from Robot
  EXPECT_DOUBLE_EQ(opp.drop_after, 5.0);
  EXPECT_DOUBLE_EQ(opp.max_sigma, 4.0);
  const ClassDef& ball = m.at(m.find("Ball"));
  EXPECT_DOUBLE_EQ(ball.velocity_tau, 0.0);  // defaults: constant velocity, the tracker's settings
  EXPECT_DOUBLE_EQ(ball.drop_after, 0.0);
  EXPECT_DOUBLE_EQ(m.tracker().reid_gate, 20.0);
  EXPECT_DOUBLE_EQ(ConceptualModel::parse("classes: {A: {}}\n", "m.yaml").tracker().reid_gate, 0.0);
  EXPECT_THROW(ConceptualModel::parse("classes:\n  Robot: {velocity_tau: -1}\n", "m.yaml"), mrt::common::ParseError);
  EXPECT_THROW(ConceptualModel::parse("classes: {A: {}}\ntracker: {reid_gate: -1}\n", "m.yaml"),
               mrt::common::ParseError);
}

TEST(Tracker, PerClassDropAfter) {
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n"
      "  Robot: {motion: static, accel_noise: 0}\n"
      "  Opponent: {parent: Robot, drop_after: 3.0}\n"
      "tracker: {confirm_hits: 3, coast_after: 0.3, drop_after: 1.0, max_sigma: 100}\n",
      "m.yaml");
  Tracker tr(m);
  const int robot = m.find("Robot"), opp = m.find("Opponent");
  for (double t : {0.0, 0.1, 0.2}) tr.cycle(t, {obs(robot, 0, 0, 0.01, t), obs(opp, 10, 0, 0.01, t)}, {});
  ASSERT_EQ(tr.anchors().size(), 2u);
  // At 1.5 s both unseen for 1.3 s: the Robot beyond the tracker's 1.0 s
  // (dropped), the Opponent within its own 3.0 s (coasting).
  tr.cycle(1.5, {}, {});
  ASSERT_EQ(tr.anchors().size(), 1u);
  EXPECT_EQ(tr.anchors()[0].class_index, opp);
  EXPECT_EQ(tr.anchors()[0].status, AnchorStatus::kCoasting);
  tr.cycle(3.1, {}, {});  // unseen 2.9 s <= 3.0: still there
  EXPECT_EQ(tr.anchors().size(), 1u);
  tr.cycle(3.3, {}, {});  // unseen 3.1 s > 3.0: dropped
  EXPECT_TRUE(tr.anchors().empty());
}

TEST(Tracker, ReidentifiesCoastingAnchor) {
  // Static, q = 0: three sightings at (0, 0) with variance 0.01 give
  // P = 0.01 / 3 = 0.003333. Coasting at 0.6 s (unseen 0.4 > 0.3). At 0.7 s
  // a sighting at (0.5, 0): d2 = 0.25 / (0.003333 + 0.01) = 18.75, beyond
  // the gate 9.21 (and no manoeuvre radius): a new anchor, unless
  // reid_gate 25 >= 18.75 re-identifies the coasting one. Then the
  // manoeuvre update: P = 0.003333 + 0.01 = 0.013333, K = 0.013333 /
  // 0.023333 = 0.571429, x = 0.5 K = 0.285714.
  for (double reid : {0.0, 25.0}) {
    const ConceptualModel m = ConceptualModel::parse(
        "classes:\n  Post: {motion: static, accel_noise: 0}\n"
        "tracker: {gate: 9.21, confirm_hits: 3, coast_after: 0.3, drop_after: 2.0, max_sigma: 100,\n"
        "          maneuver_radius: 0, reid_gate: " + std::to_string(reid) + "}\n",
        "m.yaml");
    Tracker tr(m);
    for (double t : {0.0, 0.1, 0.2}) tr.cycle(t, {obs(0, 0, 0, 0.01, t)}, {});
    tr.cycle(0.6, {}, {});
    ASSERT_EQ(tr.anchors().size(), 1u);
    ASSERT_EQ(tr.anchors()[0].status, AnchorStatus::kCoasting);
    EXPECT_NEAR(tr.anchors()[0].fused.P(0, 0), 0.01 / 3.0, 1e-9);
    tr.cycle(0.7, {obs(0, 0.5, 0, 0.01, 0.7)}, {});
    if (reid == 0.0) {
      ASSERT_EQ(tr.anchors().size(), 2u);
      EXPECT_EQ(tr.anchors()[1].id, 2u);
      EXPECT_EQ(tr.anchors()[0].status, AnchorStatus::kCoasting);
    } else {
      ASSERT_EQ(tr.anchors().size(), 1u);
      EXPECT_EQ(tr.anchors()[0].id, 1u);
      EXPECT_EQ(tr.anchors()[0].status, AnchorStatus::kConfirmed);
      EXPECT_NEAR(tr.anchors()[0].fused.x(0), 0.285714, 1e-6);
    }
  }
}

// When the teammates' support ends and only a stale own filter is left,
// the anchor keeps the team estimate (predicted), not the own filter: the
// object was seen by the own camera at (0, 0) until t = 0.5 s, then moved
// and only teammate r2 saw it, at (0.4, 0) (variance 0.01, still; linked
// as a manoeuvre, within maneuver_radius 0.5 m), until t = 1.5 s. The fused
// estimate is then the covariance intersection of the stale own filter
// (1 s unseen: position variance about q t^3 / 3 = 0.33) and r2's: close
// to (0.4, 0). At t = 1.6 s nobody sees it: before this rule the anchor
// fell back to its own filter, 0.4 m back near (0, 0) with a position
// variance of 0.51 (measured; wide enough to take a false detection metres
// away); now it stays at (0.4, 0).
TEST(Tracker, TeamEstimateOutlivesAStaleOwnFilter) {
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n  Ball: {motion: constant_velocity, accel_noise: 1, init_speed_sigma: 0.1}\n"
      "tracker: {gate: 9.21, confirm_hits: 3, coast_after: 0.3, drop_after: 3.0, max_sigma: 3}\n"
      "team: {gate: 13.82}\n",
      "m.yaml");
  Tracker tr(m);
  for (int k = 0; k <= 5; ++k) tr.cycle(0.1 * k, {obs(0, 0.0, 0.0, 1e-4, 0.1 * k)}, {});
  for (int k = 6; k <= 15; ++k) {
    const double t = 0.1 * k;
    RemoteTrack r;
    r.robot = "r2";
    r.id = 4;
    r.class_index = 0;
    r.estimate.x << 0.4, 0.0, 0.0, 0.0;
    r.estimate.P = Vec4(0.01, 0.01, 0.01, 0.01).asDiagonal();
    r.estimate.stamp = t;
    r.last_seen = t;
    r.sensors = {"r2/cam"};
    tr.cycle(t, {}, {r});
  }
  ASSERT_EQ(tr.anchors().size(), 1u);
  EXPECT_NEAR(tr.anchors()[0].fused.x(0), 0.4, 0.05);
  EXPECT_GT(tr.anchors()[0].local.P(0, 0), 0.3);  // the own filter is stale
  tr.cycle(1.6, {}, {});
  ASSERT_EQ(tr.anchors().size(), 1u);
  const Anchor& a = tr.anchors()[0];
  EXPECT_NEAR(a.fused.x(0), 0.4, 0.05);
  EXPECT_LT(a.fused.P(0, 0), 0.1);
  EXPECT_EQ(a.status, AnchorStatus::kConfirmed);  // unseen 0.1 s < coast_after
}
