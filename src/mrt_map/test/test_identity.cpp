// Identity: two objects side by side, each seen by the own camera, are two
// anchors for good (never coalesced, never swapped).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mrt_map/tracker.h"
#include "observations.h"

using namespace mrt::map;
using mrt::map::test::obs;

namespace {

// Opponents with a constant-velocity model; coalescence after 0.5 s within 9.49.
ConceptualModel opponents_model(const std::string& max_count = "") {
  return ConceptualModel::parse(
      "classes:\n"
      "  Opponent: {motion: constant_velocity, accel_noise: 1.5, init_speed_sigma: 2" + max_count + "}\n"
      "tracker: {gate: 9.21, confirm_hits: 3, coalesce_gate: 9.49, coalesce_after: 0.5}\n",
      "m.yaml");
}

}  // namespace

TEST(Tracker, TwoNearAnchorsSwapFree) {
  // Two opponents 0.2 m apart (y = 0 and y = 0.2) moving together at 1 m/s
  // along x, both seen every cycle (30 Hz, sigma 0.2 m, no noise) for 2 s.
  // Their states stay within the coalescence gate (position 0.2 m apart
  // with position variances ~0.02 each: d2 ~ 0.04 / 0.04 ~ 1 < 9.49, same
  // velocity) far longer than coalesce_after 0.5 s: before this rule they
  // were joined into id 1 after 0.5 s. Each anchor takes its own
  // observation every cycle (Hungarian on d2: 0 for its own, ~0.6 for the
  // other's), so both stay, with their ids on their sides.
  const ConceptualModel m = opponents_model();
  const int opp = m.find("Opponent");
  Tracker tr(m);
  for (int k = 0; k <= 60; ++k) {
    const double t = k / 30.0;
    tr.cycle(t, {obs(opp, t, 0.0, 0.04, t), obs(opp, t, 0.2, 0.04, t)}, {});
  }
  ASSERT_EQ(tr.anchors().size(), 2u);
  EXPECT_EQ(tr.coalesced_count(), 0u);
  const Anchor& a = tr.anchors()[0];
  const Anchor& b = tr.anchors()[1];
  EXPECT_EQ(a.id, 1u);
  EXPECT_EQ(b.id, 2u);
  EXPECT_EQ(a.status, AnchorStatus::kConfirmed);
  EXPECT_EQ(b.status, AnchorStatus::kConfirmed);
  EXPECT_NEAR(a.fused.x(1), 0.0, 0.02);
  EXPECT_NEAR(b.fused.x(1), 0.2, 0.02);
  EXPECT_NEAR(a.fused.x(0), 2.0, 0.05);
  // The pair is inside the coalescence gate (the rule, not distance, keeps them apart).
  const Vec4 y = a.fused.x - b.fused.x;
  const Mat4 S = a.fused.P + b.fused.P;
  EXPECT_LT(y.dot(S.ldlt().solve(y)), 9.49);
}

TEST(Tracker, TwoFramesOfOneSensorInOneCycleAreNotTwoObjects) {
  // A lagging node: two frames of the same camera (stamps 1/30 s apart) of
  // one opponent standing at (1, 0) reach one cycle, every 0.1 s, for 2 s.
  // The association gives the first frame's observation to the anchor; the
  // second one, for the same object, may open a second anchor. The two
  // were not seen apart in one frame, so coalescence (gate 9.49, after
  // 0.5 s) joins them: one anchor at (1, 0) at the end.
  const ConceptualModel m = opponents_model();
  const int opp = m.find("Opponent");
  Tracker tr(m);
  for (int k = 0; k <= 20; ++k) {
    const double t = 0.1 * k;
    tr.cycle(t + 1.0 / 30.0, {obs(opp, 1.0, 0.0, 0.04, t), obs(opp, 1.0, 0.0, 0.04, t + 1.0 / 30.0)}, {});
  }
  std::size_t alive = 0;
  for (const Anchor& a : tr.anchors())
    if (a.status != AnchorStatus::kDropped) {
      ++alive;
      EXPECT_NEAR(a.fused.x(0), 1.0, 0.05);
    }
  EXPECT_EQ(alive, 1u);
}

TEST(Tracker, TwoTracksOfOneTeammateAreTwoObjectsOfAClassWithACardinality) {
  // The same two opponents as in TwoNearAnchorsSwapFree (0.2 m apart, 1 m/s
  // along x, 2 s), seen by teammate r2 only: its tracks 7 and 8 (variance
  // 0.04, velocity variance 0.01) at 10 Hz. Each track keeps its anchor
  // (the link is sticky), and the anchors' states stay inside the
  // coalescence gate (d2 ~ 0.04 / 0.08 = 0.5). Without a cardinality they
  // are joined into id 1 after coalesce_after; with one (max_count 5) the
  // teammate seeing two objects there keeps ids 1 and 2 apart.
  for (const std::string card : {"", ", max_count: 5"}) {
    const ConceptualModel m = opponents_model(card);
    const int opp = m.find("Opponent");
    Tracker tr(m);
    for (int k = 0; k <= 20; ++k) {
      const double t = 0.1 * k;
      std::vector<RemoteTrack> tracks;
      for (const double y : {0.0, 0.2}) {
        RemoteTrack r;
        r.robot = "r2";
        r.id = y == 0.0 ? 7 : 8;
        r.class_index = opp;
        r.estimate.x << t, y, 1.0, 0.0;
        r.estimate.P = Vec4(0.04, 0.04, 0.01, 0.01).asDiagonal();
        r.estimate.stamp = t;
        r.last_seen = t;
        r.sensors = {"r2/cam"};
        tracks.push_back(r);
      }
      tr.cycle(t, {}, tracks);
    }
    std::vector<const Anchor*> alive;
    for (const Anchor& a : tr.anchors())
      if (a.status == AnchorStatus::kConfirmed) alive.push_back(&a);
    if (card.empty()) {
      ASSERT_EQ(alive.size(), 1u);
      EXPECT_EQ(alive[0]->id, 1u);
      EXPECT_EQ(tr.coalesced_count(), 1u);
    } else {
      ASSERT_EQ(alive.size(), 2u);
      EXPECT_EQ(alive[0]->id, 1u);
      EXPECT_EQ(alive[1]->id, 2u);
      EXPECT_NEAR(alive[0]->fused.x(1), 0.0, 1e-6);
      EXPECT_NEAR(alive[1]->fused.x(1), 0.2, 1e-6);
      EXPECT_EQ(tr.coalesced_count(), 0u);
    }
  }
}
