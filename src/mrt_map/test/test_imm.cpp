// The interacting multiple model own filter (class `imm:`, imm.h): one IMM
// step against a hand computation, the model file's `imm:` block, and the
// Tracker's own filter as an IMM.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_map/imm.h"
#include "mrt_map/tracker.h"
#include "observations.h"

using namespace mrt::map;
using mrt::map::test::obs;


TEST(Imm, OneStepAgainstHandComputation) {
  // Markov matrix p = [[0.9, 0.1], [0.2, 0.8]] (quiet -> kicked 0.1, kicked
  // -> quiet 0.2), mu = (0.8, 0.2). Quiet: x = 0, P = I; kicked: x = (0, 0,
  // 1, 0) (vx = 1), P = I. Quiet noise q = 0, kicked q = accel_noise^2 = 1.
  // Mixing: c = p' mu = (0.72 + 0.04, 0.08 + 0.16) = (0.76, 0.24);
  //   mu_i|0 = (0.72, 0.04) / 0.76 = (18/19, 1/19), mu_i|1 = (0.08, 0.16) /
  //   0.24 = (1/3, 2/3); x0_0 = vx 1/19, x0_1 = vx 2/3; spread on vx:
  //   P0_0(vx) = 1 + (18/19)(1/19) = 1 + a, a = 18/361 = 0.0498615;
  //   P0_1(vx) = 1 + (1/3)(2/3) = 1 + b, b = 2/9.
  // Prediction dt = 1 (F = [I I; 0 I], Q = q [I/3 I/2; I/2 I]):
  //   quiet x = (1/19, 0, 1/19, 0), Pxx = 2 + a, Pxv = Pvv = 1 + a, Pyy = 2;
  //   kicked x = (2/3, 0, 2/3, 0), Pxx = 2 + b + 1/3 = 2.555556,
  //   Pxv = 1 + b + 1/2 = 1.722222, Pvv = 2 + b, Pyy = 7/3; mu <- (0.76, 0.24).
  // Update z = (1, 0), R = I: S_quiet = diag(3 + a, 3), y = (18/19, 0),
  //   d2 = (18/19)^2 / (3 + a) = 0.294278; S_kicked = diag(3.555556,
  //   3.333333), y = (1/3, 0), d2 = (1/9) / 3.555556 = 0.03125;
  //   L = exp(-d2/2) / (2 pi sqrt(det S)) = 0.0454169, 0.0455136;
  //   mu = (0.76 * 0.0454169, 0.24 * 0.0455136) / sum = (0.759612, 0.240388).
  //   Quiet: Kx = (2 + a) / (3 + a) = 0.672116, x = 1/19 + Kx 18/19 =
  //   0.689373, vx = 1/19 + (1 + a)/(3 + a) 18/19 = 0.378747. Kicked: x =
  //   2/3 + (2.555556 / 3.555556) / 3 = 0.90625, vx = 2/3 + (1.722222 /
  //   3.555556) / 3 = 0.828125.
  // Combined: x = 0.759612 * 0.689373 + 0.240388 * 0.90625 = 0.741508,
  //   vx = 0.759612 * 0.378747 + 0.240388 * 0.828125 = 0.486772.
  ClassDef c;
  c.motion = MotionModel::kConstantVelocity;
  c.accel_noise = 1.0;
  c.imm = {true, 0.0, 0.0, 0.1, 0.2};
  ImmState s;
  s.model[0].P = s.model[1].P = Mat4::Identity();
  s.model[0].x.setZero();
  s.model[1].x << 0.0, 0.0, 1.0, 0.0;
  s.model[0].stamp = s.model[1].stamp = 0.0;
  s.mu = {0.8, 0.2};
  imm_predict(s, c, 1.0);
  EXPECT_NEAR(s.mu[0], 0.76, 1e-12);
  EXPECT_NEAR(s.model[0].x(0), 1.0 / 19.0, 1e-12);
  EXPECT_NEAR(s.model[0].P(2, 2), 1.0 + 18.0 / 361.0, 1e-12);
  EXPECT_NEAR(s.model[0].P(0, 0), 2.0 + 18.0 / 361.0, 1e-12);
  EXPECT_NEAR(s.model[1].x(2), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.model[1].P(0, 0), 2.555556, 1e-6);
  EXPECT_NEAR(s.model[1].P(0, 2), 1.722222, 1e-6);
  EXPECT_NEAR(s.model[1].P(1, 1), 7.0 / 3.0, 1e-12);
  imm_predict(s, c, 1.0);  // no time elapsed: no second mixing
  EXPECT_NEAR(s.mu[0], 0.76, 1e-12);
  imm_update(s, Vec2(1.0, 0.0), Mat2::Identity());
  EXPECT_NEAR(s.mu[0], 0.759612, 1e-6);
  EXPECT_NEAR(s.mu[1], 0.240388, 1e-6);
  EXPECT_NEAR(s.model[0].x(0), 0.689373, 1e-6);
  EXPECT_NEAR(s.model[0].x(2), 0.378747, 1e-6);
  EXPECT_NEAR(s.model[1].x(0), 0.90625, 1e-9);
  EXPECT_NEAR(s.model[1].x(2), 0.828125, 1e-9);
  const Estimate e = imm_combine(s);
  EXPECT_NEAR(e.x(0), 0.741508, 1e-6);
  EXPECT_NEAR(e.x(2), 0.486772, 1e-6);
  EXPECT_NEAR(e.x(1), 0.0, 1e-12);
  // Combined covariance >= the mode-weighted one (the spread term).
  EXPECT_GT(e.P(0, 0), s.mu[0] * s.model[0].P(0, 0) + s.mu[1] * s.model[1].P(0, 0));
}

TEST(ConceptualModel, ImmBlock) {
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n"
      "  Moving: {motion: constant_velocity, accel_noise: 3}\n"
      "  Ball: {parent: Moving, imm: {quiet_accel_noise: 0.4, p_quiet_to_kicked: 0.05, p_kicked_to_quiet: 0.3}}\n"
      "  Beach: {parent: Ball}\n",
      "m.yaml");
  const ImmDef& d = m.at(m.find("Beach")).imm;  // inherited
  EXPECT_TRUE(d.on);
  EXPECT_DOUBLE_EQ(d.quiet_accel_noise, 0.4);
  EXPECT_DOUBLE_EQ(d.kicked_accel_noise, 0.0);  // 0: the class's accel_noise
  EXPECT_DOUBLE_EQ(d.p_quiet_to_kicked, 0.05);
  EXPECT_DOUBLE_EQ(d.p_kicked_to_quiet, 0.3);
  EXPECT_FALSE(m.at(m.find("Moving")).imm.on);
  auto error = [](const std::string& text) {
    try {
      ConceptualModel::parse(text, "m.yaml");
    } catch (const mrt::common::ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string big = error("classes:\n  Ball: {imm: {p_quiet_to_kicked: 1.5}}\n");
  EXPECT_NE(big.find("m.yaml:2:"), std::string::npos) << big;
  EXPECT_NE(big.find("p_quiet_to_kicked"), std::string::npos) << big;
  const std::string unknown = error("classes:\n  Ball: {imm: {quiet: 1}}\n");
  EXPECT_NE(unknown.find("m.yaml:2:"), std::string::npos) << unknown;
  const std::string still = error("classes:\n  Post: {motion: static, imm: {}}\n");
  EXPECT_NE(still.find("constant_velocity"), std::string::npos) << still;
}

TEST(Tracker, ImmOwnFilter) {
  // Quiet q = 0, kicked q = accel_noise^2 = 1, p = [[0.9, 0.1], [0.2, 0.8]]:
  // a new anchor starts at the stationary mu = (0.2, 0.1) / 0.3 = (2/3, 1/3).
  // t = 0: z = 0, R = 0.01 I, init_speed_sigma 1: both models x = 0,
  // P = diag(0.01, 0.01, 1, 1); mixing identical models changes nothing and
  // c = p' mu = (2/3, 1/3). t = 1, z = (1, 0): quiet Pxx = 1.01, Pxv = 1,
  // S = 1.02 I, d2 = 1/1.02, x = 1.01/1.02 = 0.990196, vx = 1/1.02 =
  // 0.980392; kicked Pxx = 1.343333, Pxv = 1.5, S = 1.353333 I,
  // d2 = 1/1.353333 = 0.738916, x = 0.992611, vx = 1.108374.
  // L ~ exp(-d2/2)/det(S)^(1/2): 0.600541, 0.510679; mu = (2/3 * 0.600541,
  // 1/3 * 0.510679) / sum = (0.701652, 0.298348); combined x = 0.990917,
  // vx = 1.018575: the anchor's own estimate and what the teammates get.
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n"
      "  Ball: {motion: constant_velocity, accel_noise: 1, init_speed_sigma: 1,\n"
      "         imm: {quiet_accel_noise: 0, p_quiet_to_kicked: 0.1, p_kicked_to_quiet: 0.2}}\n"
      "tracker: {gate: 9.21, confirm_hits: 1, coast_after: 0.3, drop_after: 3.0, max_sigma: 100,\n"
      "          maneuver_radius: 20}\n",
      "m.yaml");
  const int ball = m.find("Ball");
  Tracker tr(m);
  tr.cycle(0.0, {obs(ball, 0, 0, 0.01, 0.0)}, {});
  ASSERT_EQ(tr.anchors().size(), 1u);
  ASSERT_TRUE(tr.anchors()[0].has_imm);
  EXPECT_NEAR(tr.anchors()[0].imm.mu[0], 2.0 / 3.0, 1e-12);
  tr.cycle(1.0, {obs(ball, 1, 0, 0.01, 1.0)}, {});
  const Anchor& a = tr.anchors()[0];
  EXPECT_NEAR(a.imm.mu[0], 0.701652, 1e-6);
  EXPECT_NEAR(a.imm.model[0].x(0), 0.990196, 1e-6);
  EXPECT_NEAR(a.imm.model[1].x(2), 1.108374, 1e-6);
  EXPECT_NEAR(a.local.x(0), 0.990917, 1e-6);
  EXPECT_NEAR(a.local.x(2), 1.018575, 1e-6);
  EXPECT_NEAR(a.fused.x(0), 0.990917, 1e-6);
  EXPECT_EQ(tr.local_tracks("r1").at(0).estimate.x(2), a.local.x(2));
  // t = 2: z = (10, 0), 8 m off (d2 in the hundreds > 9.21): a manoeuvre
  // within maneuver_radius 20: same id, velocities forgotten, and the
  // kicked model (the wider prediction) gains probability.
  const double kicked_before = a.imm.mu[1];
  tr.cycle(2.0, {obs(ball, 10, 0, 0.01, 2.0)}, {});
  const Anchor& b = tr.anchors()[0];
  EXPECT_EQ(b.id, 1u);
  EXPECT_GT(b.local.x(0), 9.0);
  EXPECT_GT(b.imm.mu[1], kicked_before);
}
