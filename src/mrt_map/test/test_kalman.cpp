// Kalman predict/update, fusion rules, Merger and the assignment, against
// hand computations.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_map/assignment.h"
#include "mrt_map/kalman.h"
#include "mrt_map/merger.h"

using namespace mrt::map;

namespace {
ClassDef cv_class(double q) {
  ClassDef c;
  c.name = "Thing";
  c.motion = MotionModel::kConstantVelocity;
  c.accel_noise = q;
  return c;
}
Observation obs(double x, double y, double var, const std::string& sensor, int cls = 0) {
  Observation o;
  o.class_index = cls;
  o.z = Vec2(x, y);
  o.R = var * Mat2::Identity();
  o.sensors = {sensor};
  return o;
}
}  // namespace

TEST(Kalman, ConstantVelocityPredictAndUpdate) {
  // x = (0,0,1,0), P = I, q = 1, dt = 1. F P F' = [[2,0,1,0],[0,2,0,1],
  // [1,0,1,0],[0,1,0,1]]; Q = [1/3, 1/2; 1/2, 1] per axis ->
  // P- = [[7/3,0,1.5,0],[0,7/3,0,1.5],[1.5,0,2,0],[0,1.5,0,2]], x- = (1,0,1,0).
  Estimate e;
  e.x << 0, 0, 1, 0;
  e.P = Mat4::Identity();
  e = predict(e, cv_class(1.0), 1.0);
  EXPECT_NEAR(e.x(0), 1.0, 1e-12);
  EXPECT_NEAR(e.P(0, 0), 7.0 / 3.0, 1e-12);
  EXPECT_NEAR(e.P(0, 2), 1.5, 1e-12);
  EXPECT_NEAR(e.P(2, 2), 2.0, 1e-12);
  // z = (2, 0), R = 2/3 I: S = 3 I, y = (1, 0), d2 = 1/3; K = [7/9; 0; 1/2; 0]
  // on x: x+ = (1 + 7/9, 0, 1.5, 0); P+ = P- - K S K': P(0,0) = 7/3 - 49/27 =
  // 14/27, P(0,2) = 1.5 - 3.5/3 = 1/3, P(2,2) = 2 - 0.75 = 1.25.
  const Mat2 R = (2.0 / 3.0) * Mat2::Identity();
  EXPECT_NEAR(mahalanobis2(e, Vec2(2, 0), R), 1.0 / 3.0, 1e-12);
  update(e, Vec2(2, 0), R);
  EXPECT_NEAR(e.x(0), 1.0 + 7.0 / 9.0, 1e-12);
  EXPECT_NEAR(e.x(1), 0.0, 1e-12);
  EXPECT_NEAR(e.x(2), 1.5, 1e-12);
  EXPECT_NEAR(e.P(0, 0), 14.0 / 27.0, 1e-12);
  EXPECT_NEAR(e.P(0, 2), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(e.P(2, 2), 1.25, 1e-12);
  EXPECT_NEAR(e.P(1, 1), 14.0 / 27.0, 1e-12);
}

TEST(Kalman, CovarianceIntersectionOfTwoTeammates) {
  // a: (0,0), P = diag(1,4,1,1); b: (1,1), P = diag(4,1,1,1). Position
  // trace 1/(w + (1-w)/4) + 1/(w/4 + 1 - w) is symmetric in w <-> 1-w and
  // convex: w = 0.5, P = diag(1.6, 1.6); x = 1.6 * 0.5 * (0 + 1/4) = 0.2,
  // y = 1.6 * 0.5 * (0 + 1) = 0.8.
  Estimate a, b;
  a.P = Vec4(1, 4, 1, 1).asDiagonal();
  b.x << 1, 1, 0, 0;
  b.P = Vec4(4, 1, 1, 1).asDiagonal();
  double w = -1;
  const Estimate f = covariance_intersection(a, b, &w);
  EXPECT_NEAR(w, 0.5, 1e-6);
  EXPECT_NEAR(f.x(0), 0.2, 1e-6);
  EXPECT_NEAR(f.x(1), 0.8, 1e-6);
  EXPECT_NEAR(f.P(0, 0), 1.6, 1e-6);
  EXPECT_NEAR(f.P(1, 1), 1.6, 1e-6);
  // Independent fusion would claim diag(0.8, 0.8) (twice as confident).
  const Estimate g = fuse_estimates(a, b);
  EXPECT_NEAR(g.P(0, 0), 0.8, 1e-12);
  EXPECT_NEAR(g.x(0), 0.2, 1e-12);
  // No double counting: CI of an estimate with itself leaves it unchanged,
  // where independent fusion would halve the covariance.
  const Estimate s = covariance_intersection(a, a);
  EXPECT_NEAR(s.P(0, 0), 1.0, 1e-9);
  EXPECT_NEAR(s.P(1, 1), 4.0, 1e-9);
  EXPECT_NEAR(fuse_estimates(a, a).P(0, 0), 0.5, 1e-12);
}

TEST(Kalman, PrincipalAxes) {
  // [[3, 1], [1, 3]]: eigenvalues 4 (along (1,1), 45 deg) and 2.
  Mat2 C;
  C << 3, 1, 1, 3;
  const Ellipse e = principal_axes(C);
  EXPECT_NEAR(e.major, 4.0, 1e-12);
  EXPECT_NEAR(e.minor, 2.0, 1e-12);
  EXPECT_NEAR(e.angle, M_PI / 4, 1e-12);
}

TEST(Merger, JoinsTwoSensorsOfOneObjectOnly) {
  ConceptualModel m = ConceptualModel::parse("classes:\n  Ball: {}\n  Robot: {}\n", "t.yaml");
  const Merger merger(m);
  // z1 = (0,0), z2 = (0.1,0), R = 0.04 I each: d2 = 0.01/0.08 = 0.125 <= 9.21
  // -> one object at (0.05, 0) with R = 0.02 I.
  auto out = merger.merge({obs(0, 0, 0.04, "r/cam"), obs(0.1, 0, 0.04, "r/sonar")});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].z.x(), 0.05, 1e-12);
  EXPECT_NEAR(out[0].R(0, 0), 0.02, 1e-12);
  EXPECT_EQ(out[0].sensors.size(), 2u);
  // Same sensor: two objects. Incompatible classes: two objects.
  EXPECT_EQ(merger.merge({obs(0, 0, 0.04, "r/cam"), obs(0.1, 0, 0.04, "r/cam")}).size(), 2u);
  EXPECT_EQ(merger.merge({obs(0, 0, 0.04, "r/cam", 0), obs(0.1, 0, 0.04, "r/sonar", 1)}).size(), 2u);
  // Far apart: (1-0)^2 / 0.08 = 12.5 > 9.21.
  EXPECT_EQ(merger.merge({obs(0, 0, 0.04, "r/cam"), obs(1.0, 0, 0.04, "r/sonar")}).size(), 2u);
}

// map_node's dynamic_reconfigure: the Merger reads the tuned merge gate.
// z1 = (0, 0), z2 = (0.4, 0), R = 0.01 I each: d2 = 0.16 / 0.02 = 8 -> one
// object under 9.21, two under 4. Bad values are refused, nothing changed.
TEST(Merger, FollowsTheTunedMergeGate) {
  ConceptualModel m = ConceptualModel::parse("classes:\n  Ball: {}\n", "t.yaml");
  const Merger merger(m);
  const std::vector<Observation> two = {obs(0, 0, 0.01, "r/cam"), obs(0.4, 0, 0.01, "r/sonar")};
  EXPECT_EQ(merger.merge(two).size(), 1u);
  ModelTuning t = m.tuning();
  EXPECT_DOUBLE_EQ(t.merge_gate, 9.21);
  EXPECT_DOUBLE_EQ(t.team_gate, 13.82);
  t.merge_gate = 4.0;
  m.set_tuning(t);
  EXPECT_EQ(merger.merge(two).size(), 2u);
  t.merge_gate = 8.5;  // just above d2
  m.set_tuning(t);
  EXPECT_EQ(merger.merge(two).size(), 1u);
  ModelTuning bad = t;
  bad.gate = 0.0;
  EXPECT_THROW(m.set_tuning(bad), std::invalid_argument);
  bad = t;
  bad.team_extra_sigma = -0.1;
  EXPECT_THROW(m.set_tuning(bad), std::invalid_argument);
  EXPECT_DOUBLE_EQ(m.tracker().merge_gate, 8.5);
  EXPECT_DOUBLE_EQ(m.tracker().gate, 9.21);
}

TEST(Merger, LatencyCompensation) {
  ConceptualModel m = ConceptualModel::parse(
      "classes:\n  Ball: {motion: constant_velocity, accel_noise: 0}\nteam: {max_latency: 1.0, extra_sigma: 0}\n", "t.yaml");
  const Merger merger(m);
  RemoteTrack t;
  t.class_index = 0;
  t.estimate.x << 1, 0, 2, 0;
  t.estimate.stamp = 10.0;
  RemoteTrack late = t;
  // 0.5 s later at 2 m/s: x = 1 + 2 * 0.5 = 2; P(0,0) = 1 + 0.25 * 1 = 1.25.
  ASSERT_TRUE(merger.compensate(t, 10.5));
  EXPECT_NEAR(t.estimate.x(0), 2.0, 1e-12);
  EXPECT_NEAR(t.estimate.P(0, 0), 1.25, 1e-12);
  EXPECT_FALSE(merger.compensate(late, 11.6));  // 1.6 s > max_latency
  // With team.extra_sigma = 0.1: P(0,0) = 1.25 + 0.01.
  ConceptualModel m2 = ConceptualModel::parse(
      "classes:\n  Ball: {motion: constant_velocity, accel_noise: 0}\nteam: {extra_sigma: 0.1}\n", "t.yaml");
  ASSERT_TRUE(Merger(m2).compensate(late, 10.5));
  EXPECT_NEAR(late.estimate.P(0, 0), 1.26, 1e-12);
  EXPECT_NEAR(late.estimate.P(2, 2), 1.0, 1e-12);
}

TEST(Assignment, GlobalBeatsGreedy) {
  // Greedy takes (0,0) = 1 and leaves row 1 with 100 > gate; the global
  // optimum is (0,1) + (1,0) = 4 < 1 + miss (50).
  EXPECT_EQ(assign({{1, 2}, {2, 100}}, 50), (std::vector<int>{1, 0}));
  EXPECT_EQ(assign({{1, kInfeasible}}, 50), (std::vector<int>{0}));
  EXPECT_EQ(assign({{kInfeasible, 60}}, 50), (std::vector<int>{-1}));
  EXPECT_EQ(assign({}, 50), (std::vector<int>{}));
  // 3x3: the optimum of [[4,1,3],[2,0,5],[3,2,2]] is 1 + 2 + 2 = 5.
  EXPECT_EQ(hungarian({{4, 1, 3}, {2, 0, 5}, {3, 2, 2}}), (std::vector<int>{1, 0, 2}));
}
