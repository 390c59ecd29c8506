// The extent of the world (model `world:`): observations, teammates'
// anchors and predictions outside it are dropped; and the quiet own filter
// (class quiet_accel_noise) with its restart at a manoeuvre.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_map/tracker.h"
#include "mrt_map/world_model.h"

using namespace mrt::map;

namespace {
Observation obs(int cls, double x, double y, double var, double t) {
  Observation o;
  o.class_index = cls;
  o.z = Vec2(x, y);
  o.R = var * Mat2::Identity();
  o.stamp = t;
  o.robot = "r1";
  o.sensors = {"r1/cam"};
  return o;
}

PerceptObject ball_at(double x, double y) {
  PerceptObject o;
  o.membership_class = "Ball";
  o.attributes["x"] = {x, "", 0.05, 1.0};
  o.attributes["y"] = {y, "", 0.05, 1.0};
  return o;
}
}  // namespace

TEST(ConceptualModel, WorldBounds) {
  const ConceptualModel m = ConceptualModel::parse(
      "classes: {A: {}}\nworld: {x_min: -10, x_max: 10, y_min: -7, y_max: 7}\n", "m.yaml");
  ASSERT_TRUE(m.world().set);
  EXPECT_TRUE(m.world().contains(10.0, -7.0));  // the border is inside
  EXPECT_FALSE(m.world().contains(10.01, 0.0));
  EXPECT_FALSE(m.world().contains(0.0, -7.01));
  // No `world:` = unbounded.
  EXPECT_TRUE(ConceptualModel::parse("classes: {A: {}}\n", "m.yaml").world().contains(1e6, -1e6));
  try {
    ConceptualModel::parse("classes: {A: {}}\nworld: {x_min: 1, x_max: 1, y_min: 0, y_max: 1}\n", "m.yaml");
    FAIL() << "x_max = x_min accepted";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("m.yaml:2:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("x_max"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ConceptualModel::parse("classes: {A: {}}\nworld: {x_min: 0, x_max: 1, y_min: 0}\n", "m.yaml"),
               mrt::common::ParseError);
  EXPECT_THROW(ConceptualModel::parse("classes: {A: {}}\nworld: {x_min: 0, x_max: 1, y_min: 0, y_max: 1, z: 2}\n",
                                      "m.yaml"),
               mrt::common::ParseError);
}

TEST(WorldModel, DropsObservationsAndTeammatesAnchorsOutsideTheWorld) {
  const ConceptualModel m = ConceptualModel::parse(
      "classes: {Ball: {motion: constant_velocity}}\nworld: {x_min: -10, x_max: 10, y_min: -7, y_max: 7}\n", "m.yaml");
  WorldModel w(m, {"r1", 0.5});
  RobotPose pose;
  pose.x = 8.0;  // facing +x: robot-frame (3, 0) is world (11, 0), outside; (1, 0) is (9, 0)
  w.set_robot_pose(pose, 0.0);
  EXPECT_EQ(w.add_percept({ball_at(3.0, 0.0), ball_at(1.0, 0.0)}, pose, 0.0, 0.0, "cam"), 1);
  EXPECT_EQ(w.counters().outside_world, 1u);
  EXPECT_EQ(w.counters().accepted, 1u);
  // A teammate's anchor at (0, 7.5) (outside) and one at (0, 6.5) (inside).
  RemoteTrack out, in;
  out.id = 1;
  in.id = 2;
  out.class_index = in.class_index = 0;
  out.estimate.x << 0.0, 7.5, 0.0, 0.0;
  in.estimate.x << 0.0, 6.5, 0.0, 0.0;
  out.estimate.P = in.estimate.P = 0.01 * Mat4::Identity();
  out.last_seen = in.last_seen = 0.0;
  w.add_teammate_model("r2", {out, in}, 0.0);
  w.update(0.0);
  EXPECT_EQ(w.counters().outside_world, 2u);
  ASSERT_EQ(w.tracker().anchors().size(), 2u);  // own (9, 0) and the teammate's (0, 6.5)
  EXPECT_NEAR(w.tracker().anchors()[0].fused.x(0), 9.0, 1e-9);
  EXPECT_NEAR(w.tracker().anchors()[1].fused.x(1), 6.5, 1e-9);
}

TEST(Tracker, DropsAnAnchorPredictedOutOfTheWorld) {
  // No process noise, near-exact observations (variance 1e-10) at x = 9.0,
  // 9.1, 9.2 at t = 0, 0.1, 0.2: the filter interpolates them, x = 9.2,
  // v = 1.0 m/s at 0.2 s; predicted x(t) = 9.2 + (t - 0.2): 9.9 at 0.9 s
  // (inside x_max = 10: kept, coasting), 10.1 at 1.1 s (outside: dropped).
  // Without `world:` it is still coasting at 1.1 s (drop_after 3 s).
  for (const bool bounded : {true, false}) {
    const ConceptualModel m = ConceptualModel::parse(
        std::string("classes: {Ball: {motion: constant_velocity, accel_noise: 0, init_speed_sigma: 10}}\n"
                    "tracker: {confirm_hits: 3, coast_after: 0.3, drop_after: 3.0, max_sigma: 100}\n") +
            (bounded ? "world: {x_min: -10, x_max: 10, y_min: -7, y_max: 7}\n" : ""),
        "m.yaml");
    Tracker tr(m);
    for (double t : {0.0, 0.1, 0.2}) tr.cycle(t, {obs(0, 9.0 + t, 0.0, 1e-10, t)}, {});
    ASSERT_EQ(tr.anchors().size(), 1u);
    EXPECT_NEAR(tr.anchors()[0].fused.x(2), 1.0, 1e-6);
    tr.cycle(0.9, {}, {});
    ASSERT_EQ(tr.anchors().size(), 1u);
    EXPECT_NEAR(tr.anchors()[0].fused.x(0), 9.9, 1e-6);
    EXPECT_EQ(tr.anchors()[0].status, AnchorStatus::kCoasting);
    tr.cycle(1.1, {}, {});
    EXPECT_EQ(tr.anchors().size(), bounded ? 0u : 1u);
  }
}

TEST(Tracker, QuietFilterBetweenManoeuvres) {
  // Main own filter: q = accel_noise^2 = 1; quiet filter: q = 1e-12 (~0).
  // t = 0: z = (0, 0), R = 0.01 I, init_speed_sigma 1: both filters start
  // with P = diag(0.01, 0.01, 1, 1), x = 0 (the quiet one a copy).
  // t = 1, z = (1, 0), R = 0.01 I. Quiet: P_pp = 0.01 + 1 = 1.01, P_pv = 1,
  // S = 1.02, d2 = 1 / 1.02 = 0.98 <= gate 9.21: updated, x = 1.01 / 1.02 =
  // 0.990196, vx = 1 / 1.02 = 0.980392. Main: P_pp = 1.01 + 1/3 = 1.343333,
  // P_pv = 1 + 1/2 = 1.5, S = 1.353333, x = 0.992611, vx = 1.108374. The
  // anchor's estimate (fused, sent to teammates) is the quiet one.
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n"
      "  Moving: {motion: constant_velocity, accel_noise: 1, init_speed_sigma: 1, quiet_accel_noise: 1e-6}\n"
      "  Ball: {parent: Moving}\n"
      "tracker: {gate: 9.21, confirm_hits: 1, coast_after: 0.3, drop_after: 3.0, max_sigma: 100,\n"
      "          maneuver_radius: 20}\n",
      "m.yaml");
  const int ball = m.find("Ball");
  EXPECT_DOUBLE_EQ(m.at(ball).quiet_accel_noise, 1e-6);  // inherited
  EXPECT_DOUBLE_EQ(m.at(ball).quiet_nis, 0.0);           // 0: tracker.gate
  Tracker tr(m);
  tr.cycle(0.0, {obs(ball, 0, 0, 0.01, 0.0)}, {});
  ASSERT_EQ(tr.anchors().size(), 1u);
  ASSERT_TRUE(tr.anchors()[0].has_quiet);
  EXPECT_NEAR(tr.anchors()[0].quiet.P(2, 2), 1.0, 1e-12);
  tr.cycle(1.0, {obs(ball, 1, 0, 0.01, 1.0)}, {});
  const Anchor& a = tr.anchors()[0];
  EXPECT_NEAR(a.quiet.x(0), 0.990196, 1e-6);
  EXPECT_NEAR(a.quiet.x(2), 0.980392, 1e-6);
  EXPECT_NEAR(a.local.x(0), 0.992611, 1e-6);
  EXPECT_NEAR(a.local.x(2), 1.108374, 1e-6);
  EXPECT_NEAR(a.fused.x(0), 0.990196, 1e-6);
  EXPECT_EQ(tr.local_tracks("r1").at(0).estimate.x(2), a.quiet.x(2));
  // t = 2: z = (10, 0), 8 m off both predictions (d2 in the hundreds, > 9.21):
  // a manoeuvre (within maneuver_radius 20): the main filter forgets its
  // velocity, and the quiet one restarts as a copy of the main one.
  tr.cycle(2.0, {obs(ball, 10, 0, 0.01, 2.0)}, {});
  const Anchor& b = tr.anchors()[0];
  EXPECT_EQ(b.id, 1u);
  EXPECT_EQ(b.quiet.x, b.local.x);
  EXPECT_EQ(b.quiet.P, b.local.P);
  EXPECT_GT(b.local.x(0), 9.0);
}
