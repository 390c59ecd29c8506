// The extent of the world (model `world:`): observations, teammates'
// anchors and predictions outside it are dropped.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_map/tracker.h"
#include "mrt_map/world_model.h"
#include "observations.h"

using namespace mrt::map;
using mrt::map::test::obs;

namespace {

PerceptObject ball_at(double x, double y) {
  PerceptObject o;
  o.membership_class = "Ball";
  o.set("x", x, 0.05, 1.0);
  o.set("y", y, 0.05, 1.0);
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
