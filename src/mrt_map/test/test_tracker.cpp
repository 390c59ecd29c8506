// Tracker: gating and Kalman updates through the tracker, the life cycle,
// id stability through a crossing, fusion of a teammate's anchor.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_map/kalman.h"
#include "mrt_map/tracker.h"
#include "observations.h"

using namespace mrt::map;
using mrt::map::test::obs;

namespace {
const char* kModel =
    "classes:\n"
    "  Post: {motion: static, accel_noise: 0}\n"
    "  Robot: {motion: constant_velocity, accel_noise: 1.5}\n"
    "tracker: {gate: 9.21, confirm_hits: 3, tentative_timeout: 0.3, coast_after: 0.3, drop_after: 1.0,\n"
    "          max_sigma: 100}\n";

}  // namespace

TEST(Tracker, GatingAndKalmanUpdate) {
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  Tracker tr(m);
  // Static, q = 0. First: x = (0,0), P = 0.04. Second at (0.1, 0): S = 0.08,
  // K = 0.5 -> x = 0.05, P = 0.02. Third at (1, 0): d2 = 0.95^2 / (0.02 +
  // 0.04) = 15.04 > 9.21 -> gated out, a second anchor.
  tr.cycle(0.0, {obs(0, 0, 0, 0.04, 0.0)}, {});
  tr.cycle(1.0, {obs(0, 0.1, 0, 0.04, 1.0)}, {});
  ASSERT_EQ(tr.anchors().size(), 1u);
  EXPECT_NEAR(tr.anchors()[0].fused.x(0), 0.05, 1e-9);
  EXPECT_NEAR(tr.anchors()[0].fused.P(0, 0), 0.02, 1e-9);
  tr.cycle(1.1, {obs(0, 1.0, 0, 0.04, 1.1)}, {});
  ASSERT_EQ(tr.anchors().size(), 2u);
  EXPECT_EQ(tr.anchors()[0].id, 1u);
  EXPECT_EQ(tr.anchors()[1].id, 2u);
  EXPECT_NEAR(tr.anchors()[0].fused.x(0), 0.05, 1e-9);
  EXPECT_NEAR(tr.anchors()[1].fused.x(0), 1.0, 1e-9);
}

TEST(Tracker, LifeCycle) {
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  Tracker tr(m);
  auto status = [&] { return tr.anchors().at(0).status; };
  // Seen at 0, 0.1, 0.2: 3 hits -> confirmed at 0.2.
  tr.cycle(0.0, {obs(0, 1, 1, 0.01, 0.0)}, {});
  EXPECT_EQ(status(), AnchorStatus::kTentative);
  tr.cycle(0.1, {obs(0, 1, 1, 0.01, 0.1)}, {});
  EXPECT_EQ(status(), AnchorStatus::kTentative);
  tr.cycle(0.2, {obs(0, 1, 1, 0.01, 0.2)}, {});
  EXPECT_EQ(status(), AnchorStatus::kConfirmed);
  // Unseen 0.2 s (<= coast_after 0.3): confirmed; 0.4 s: coasting.
  tr.cycle(0.4, {}, {});
  EXPECT_EQ(status(), AnchorStatus::kConfirmed);
  tr.cycle(0.6, {}, {});
  EXPECT_EQ(status(), AnchorStatus::kCoasting);
  // Seen again: confirmed, same id.
  tr.cycle(0.7, {obs(0, 1, 1, 0.01, 0.7)}, {});
  EXPECT_EQ(status(), AnchorStatus::kConfirmed);
  EXPECT_EQ(tr.anchors().at(0).id, 1u);
  tr.cycle(1.5, {}, {});  // 0.8 s unseen: coasting, not yet dropped
  EXPECT_EQ(status(), AnchorStatus::kCoasting);
  tr.cycle(1.8, {}, {});  // 1.1 s > drop_after 1.0: dropped
  EXPECT_TRUE(tr.anchors().empty());
  EXPECT_EQ(tr.dropped_count(), 1u);
  // A tentative anchor seen once is dropped after tentative_timeout 0.3 s.
  tr.cycle(2.0, {obs(0, 5, 5, 0.01, 2.0)}, {});
  tr.cycle(2.2, {}, {});
  ASSERT_EQ(tr.anchors().size(), 1u);
  EXPECT_EQ(status(), AnchorStatus::kTentative);
  EXPECT_EQ(tr.anchors()[0].id, 2u);
  tr.cycle(2.4, {}, {});
  EXPECT_TRUE(tr.anchors().empty());
}

TEST(Tracker, IdStableThroughACrossing) {
  // A goes (-3,-3) -> (3,3), B goes (-3,3) -> (3,-3), both at sqrt(2) m/s,
  // through the same point (0,0) at t = 3; observed at 10 Hz, sigma 0.1 m.
  // A is seen first, so it is anchor 1: after the crossing anchor 1 must
  // be at A's end (3,3) moving (+1,+1), anchor 2 at (3,-3) moving (+1,-1).
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  Tracker tr(m);
  for (int k = 0; k <= 60; ++k) {
    const double t = 0.1 * k;
    // Deterministic zero-mean wobble, within the noise.
    const double e = 0.05 * std::sin(1.7 * k);
    tr.cycle(t, {obs(1, -3 + t + e, -3 + t - e, 0.01, t), obs(1, -3 + t - e, 3 - t + e, 0.01, t)}, {});
    ASSERT_EQ(tr.anchors().size(), 2u) << "at t = " << t;
  }
  const Anchor& a = tr.anchors()[0];
  const Anchor& b = tr.anchors()[1];
  EXPECT_EQ(a.id, 1u);
  EXPECT_NEAR(a.fused.x(0), 3.0, 0.1);
  EXPECT_NEAR(a.fused.x(1), 3.0, 0.1);
  EXPECT_NEAR(a.fused.x(3), 1.0, 0.2);
  EXPECT_EQ(b.id, 2u);
  EXPECT_NEAR(b.fused.x(1), -3.0, 0.1);
  EXPECT_NEAR(b.fused.x(3), -1.0, 0.2);
}

TEST(Tracker, FusesTeammateByCovarianceIntersection) {
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  Tracker tr(m);
  // Own: static post seen at (0,0), R = diag(1, 4) (a single observation:
  // local P = R, velocity variance 1e-6). Teammate: (1,1), P = diag(4, 1,
  // 1e-6, 1e-6). d2 = (1,1) diag(5,5)^-1 (1,1)' = 0.4 <= 13.82 -> linked.
  // CI as in test_kalman: w = 0.5, x = (0.2, 0.8), P = diag(1.6, 1.6).
  Observation o = obs(0, 0, 0, 1.0, 0.0);
  o.R(1, 1) = 4.0;
  RemoteTrack t;
  t.robot = "r2";
  t.id = 7;
  t.class_index = 0;
  t.estimate.x << 1, 1, 0, 0;
  t.estimate.P = Vec4(4, 1, 1e-6, 1e-6).asDiagonal();
  t.last_seen = 0.0;
  t.sensors = {"r2/cam"};
  tr.cycle(0.0, {o}, {t});
  ASSERT_EQ(tr.anchors().size(), 1u);
  const Anchor& a = tr.anchors()[0];
  EXPECT_NEAR(a.fused.x(0), 0.2, 1e-6);
  EXPECT_NEAR(a.fused.x(1), 0.8, 1e-6);
  EXPECT_NEAR(a.fused.P(0, 0), 1.6, 1e-6);
  EXPECT_NEAR(a.fused.P(1, 1), 1.6, 1e-6);
  EXPECT_EQ(a.sources.count("r2/cam"), 1u);
  EXPECT_EQ(a.remote_ids.at("r2"), 7u);
  // What goes to the teammates is the own estimate only (no double counting).
  const auto local = tr.local_tracks("r1");
  EXPECT_TRUE(local.empty());  // 1 own hit < confirm_hits 3
  tr.cycle(0.1, {o}, {t});
  tr.cycle(0.2, {o}, {t});
  const auto local3 = tr.local_tracks("r1");
  ASSERT_EQ(local3.size(), 1u);
  EXPECT_LT(std::fabs(local3[0].estimate.x(0)), 1e-9);  // own data only: x stays 0
  EXPECT_EQ(local3[0].sensors, (std::set<std::string>{"r1/cam"}));
}
