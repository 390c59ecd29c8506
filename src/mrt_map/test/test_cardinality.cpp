// Class cardinality (max_count): when as many anchors of a class are live
// (confirmed or coasting) as the class has objects, an observation that no
// live anchor takes is one of the lost (coasting) anchors coming back, not
// a new object; below the cardinality a new object gets a new symbol.
#include <gtest/gtest.h>

#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_map/tracker.h"

using namespace mrt::map;

namespace {
Observation obs(double x, double y, double t) {
  Observation o;
  o.class_index = 0;
  o.z = Vec2(x, y);
  o.R = 1e-4 * Mat2::Identity();
  o.stamp = t;
  o.robot = "r1";
  o.sensors = {"r1/cam"};
  return o;
}

ConceptualModel model(int max_count, double accel_noise = 0.5) {
  // drop_after 1 s: without the cardinality an anchor unseen for more than
  // 1 s is dropped and its object comes back under a new symbol.
  std::string card = max_count > 0 ? ", max_count: " + std::to_string(max_count) : "";
  return ConceptualModel::parse(
      "classes:\n  Opponent: {motion: constant_velocity, accel_noise: " + std::to_string(accel_noise) +
      ", init_speed_sigma: 2" + card + "}\n"
      "tracker: {gate: 9.21, confirm_hits: 3, coast_after: 0.3, drop_after: 1.0, max_sigma: 3,\n"
      "          maneuver_radius: 0, reid_gate: 0}\n",
      "m.yaml");
}

const Anchor* nearest(const Tracker& tr, double x, double y) {
  const Anchor* best = nullptr;
  for (const Anchor& a : tr.anchors())
    if (!best || (a.fused.x.head<2>() - Vec2(x, y)).norm() < (best->fused.x.head<2>() - Vec2(x, y)).norm()) best = &a;
  return best;
}
// Objects at (0, 0) and (x2, 0), both seen every 0.1 s from 0 to 1 s, then
// only the second until (not including) `until` s.
void see_both_then_lose_first(Tracker& tr, double x2, double until) {
  int k = 0;
  for (; k <= 10; ++k) tr.cycle(0.1 * k, {obs(0, 0, 0.1 * k), obs(x2, 0, 0.1 * k)}, {});
  for (; 0.1 * k < until - 1e-9; ++k) tr.cycle(0.1 * k, {obs(x2, 0, 0.1 * k)}, {});
}
}  // namespace

TEST(Cardinality, ParsesAndIsNotInherited) {
  const ConceptualModel m = ConceptualModel::parse(
      "classes:\n  Robot: {}\n  Opponent: {parent: Robot, max_count: 5}\n  Keeper: {parent: Opponent}\n", "m.yaml");
  EXPECT_EQ(m.at(m.find("Opponent")).max_count, 5);
  EXPECT_EQ(m.at(m.find("Robot")).max_count, 0);
  EXPECT_EQ(m.at(m.find("Keeper")).max_count, 0);  // counted within Opponent's 5, no limit of its own
  EXPECT_THROW(ConceptualModel::parse("classes:\n  A: {max_count: 2.5}\n", "m.yaml"), mrt::common::ParseError);
  EXPECT_THROW(ConceptualModel::parse("classes:\n  A: {max_count: -1}\n", "m.yaml"), mrt::common::ParseError);
}

// Object 1 moves along x at 1/3 m/s, seen from 0 to 1 s (x = t / 3); object
// 2 stands at (5, 5) and is seen all the time. Object 1 leaves every view
// for 3 s and comes back at t = 4 s at x = 4/3, 1 m further along its
// velocity. Unseen 3 s > drop_after 1 s: without a cardinality its anchor
// is dropped and the object comes back as id 3; with max_count 2 (anchors
// 1 coasting + 2 confirmed = 2: at the cardinality) anchor 1 is kept and
// takes the observation back. Its own filter was dropped after 1 s, so it
// restarts from the observation: x = 4/3 = 1.333333 exactly.
TEST(Cardinality, ReturningObjectKeepsItsIdAtCardinality) {
  for (int max_count : {0, 2}) {
    const ConceptualModel m = model(max_count);
    Tracker tr(m);
    int k = 0;
    for (; k <= 10; ++k) tr.cycle(0.1 * k, {obs(0.1 * k / 3.0, 0, 0.1 * k), obs(5, 5, 0.1 * k)}, {});
    for (; k < 40; ++k) tr.cycle(0.1 * k, {obs(5, 5, 0.1 * k)}, {});
    tr.cycle(4.0, {obs(4.0 / 3.0, 0, 4.0), obs(5, 5, 4.0)}, {});
    ASSERT_EQ(tr.anchors().size(), 2u) << max_count;
    const Anchor* back = nearest(tr, 4.0 / 3.0, 0);
    EXPECT_EQ(nearest(tr, 5, 5)->id, 2u);
    if (max_count == 0) {
      EXPECT_EQ(back->id, 3u);
    } else {
      EXPECT_EQ(back->id, 1u);
      EXPECT_NEAR(back->fused.x(0), 4.0 / 3.0, 1e-9);
      EXPECT_EQ(back->status, AnchorStatus::kConfirmed);  // coasting -> confirmed on its first sighting
    }
  }
}

// Below the cardinality a genuinely new object gets a new symbol: max_count
// 3, objects 1 and 2 tracked and seen, a third appears at (-5, -5): id 3.
// At the cardinality (max_count 2) with no lost anchor to claim, the same
// third detection is still created (id 3): the cardinality never discards
// an observation.
TEST(Cardinality, NewObjectBelowCardinality) {
  for (int max_count : {3, 2}) {
    const ConceptualModel m = model(max_count);
    Tracker tr(m);
    for (int k = 0; k < 5; ++k) tr.cycle(0.1 * k, {obs(0, 0, 0.1 * k), obs(5, 5, 0.1 * k)}, {});
    tr.cycle(0.5, {obs(0, 0, 0.5), obs(5, 5, 0.5), obs(-5, -5, 0.5)}, {});
    ASSERT_EQ(tr.anchors().size(), 3u) << max_count;
    EXPECT_EQ(nearest(tr, -5, -5)->id, 3u);
    EXPECT_EQ(nearest(tr, 0, 0)->id, 1u);
    EXPECT_EQ(nearest(tr, 5, 5)->id, 2u);
  }
}

// Two opponents cross in an X unseen: A from (-2, -1) at (1, 0.5) m/s, B
// from (-2, 1) at (1, -0.5) m/s, seen from 0 to 1 s, unseen from 1 to 3 s
// (they cross at t = 2 s, x = 0), seen again at t = 3 s: A at (1, 0.5), B at
// (1, -0.5). With max_count 2 both anchors are kept while lost (beyond
// drop_after 1 s) and not coalesced where their predictions meet at t = 2 s;
// at t = 3 s A's prediction is (1, 0.5) (exact data, position variance
// about q t^3 / 3 = 0.25 * 8 / 3 = 0.67 m^2), so the global assignment takes
// the straight pairs (d2 ~ 0) over the crossed ones (d2 ~ 1 / 0.67 each):
// A keeps id 1 at y = 0.5, B id 2 at y = -0.5. Without the cardinality both
// were dropped and come back new (3, 4). (Without the no-coalescence rule
// the two lost anchors are joined into one: 1 anchor, not 2.)
TEST(Cardinality, TwoOpponentsCrossingUnseenKeepTheirIds) {
  for (int max_count : {0, 2}) {
    const ConceptualModel m = model(max_count);
    Tracker tr(m);
    int k = 0;
    for (; k <= 10; ++k) {
      const double t = 0.1 * k;
      tr.cycle(t, {obs(-2 + t, -1 + 0.5 * t, t), obs(-2 + t, 1 - 0.5 * t, t)}, {});
    }
    for (; k < 30; ++k) tr.cycle(0.1 * k, {}, {});
    tr.cycle(3.0, {obs(1, 0.5, 3.0), obs(1, -0.5, 3.0)}, {});
    ASSERT_EQ(tr.anchors().size(), 2u) << max_count;
    if (max_count == 0) {
      EXPECT_EQ(nearest(tr, 1, 0.5)->id, 3u);
      EXPECT_EQ(nearest(tr, 1, -0.5)->id, 4u);
    } else {
      EXPECT_EQ(nearest(tr, 1, 0.5)->id, 1u);
      EXPECT_EQ(nearest(tr, 1, -0.5)->id, 2u);
    }
  }
}

// Outside every gate: object 1 stands at (0, 0), seen from 0 to 1 s, and
// comes back at t = 4 s at (3, 0) (it moved while unseen). accel_noise 0.05:
// the coasting position variance is about q t^3 / 3 = 0.0025 * 27 / 3 =
// 0.0225 m^2 plus the velocity's, so d2 ~ 9 / 0.025 = 360 >> gate 9.21: no
// association, no re-identification (reid_gate 0). Without a cardinality a
// new anchor (id 3); with max_count 2 the lost anchor 1 is claimed (the only
// candidate) and restarts from the observation: x = 3.
TEST(Cardinality, LostAnchorClaimedOutsideTheGate) {
  for (int max_count : {0, 2}) {
    const ConceptualModel m = model(max_count, 0.05);
    Tracker tr(m);
    int k = 0;
    for (; k <= 10; ++k) tr.cycle(0.1 * k, {obs(0, 0, 0.1 * k), obs(5, 5, 0.1 * k)}, {});
    for (; k < 40; ++k) tr.cycle(0.1 * k, {obs(5, 5, 0.1 * k)}, {});
    const Anchor* lost = nearest(tr, 0, 0);
    if (max_count == 2) {
      ASSERT_EQ(lost->id, 1u);
      EXPECT_EQ(lost->status, AnchorStatus::kCoasting);  // kept beyond drop_after: the class is at its cardinality
      EXPECT_LT(lost->fused.P(0, 0), 0.1);
    }
    tr.cycle(4.0, {obs(3, 0, 4.0), obs(5, 5, 4.0)}, {});
    ASSERT_EQ(tr.anchors().size(), 2u) << max_count;
    const Anchor* back = nearest(tr, 3, 0);
    EXPECT_EQ(back->id, max_count == 2 ? 1u : 3u);
    EXPECT_NEAR(back->fused.x(0), 3.0, 1e-9);
  }
}

// A lost anchor is not coalesced into a seen one: object 1 stands at (0, 0),
// seen from 0 to 1 s, then unseen; object 2 stands at (0.6, 0), seen all the
// time. With max_count 2 anchor 1 is kept while lost; its position variance
// grows (about q t^3 / 3 = 0.25 t^3 / 3 m^2 after t s unseen: 0.083 at 1 s),
// so by t ~ 2 s (0.36 / 0.67 = 0.5 < coalesce_gate 9.49) object 2's anchor
// lies well inside its gate: the old rule (only two *lost* anchors kept
// apart) joined them after coalesce_after 0.5 s into id 1, which then stood
// on object 2, and object 1 came back at t = 4 s as id 3. Now: ids 1 and 2
// stay, and object 1 comes back as id 1.
TEST(Cardinality, LostAnchorIsNotCoalescedIntoASeenOne) {
  const ConceptualModel m = model(2);
  Tracker tr(m);
  see_both_then_lose_first(tr, 0.6, 4.0);
  ASSERT_EQ(tr.anchors().size(), 2u);
  const Anchor* lost = nearest(tr, 0, 0);
  EXPECT_EQ(lost->id, 1u);
  EXPECT_EQ(lost->status, AnchorStatus::kCoasting);
  EXPECT_GT(lost->fused.P(0, 0), 0.36 / 9.49);  // object 2 is inside its gate
  EXPECT_EQ(nearest(tr, 0.6, 0)->id, 2u);
  tr.cycle(4.0, {obs(0, 0, 4.0), obs(0.6, 0, 4.0)}, {});
  ASSERT_EQ(tr.anchors().size(), 2u);
  EXPECT_EQ(nearest(tr, 0, 0)->id, 1u);
  EXPECT_EQ(nearest(tr, 0.6, 0)->id, 2u);
}

// A detection inside a tracked anchor's gate does not bring back a lost
// one: anchor 1 lost at (0, 0) since t = 1 s (position variance ~0.67 m^2 at
// t = 3 s), anchor 2 tracked at (1, 0) (variance ~1e-4). At t = 3 s object 2
// is detected twice, at (1, 0) and by a second camera at (1.02, 0) (d2 ~
// 0.0004 / 2e-4 = 2 from anchor 2, inside its gate; 1.04 / 0.67 = 1.6 from
// anchor 1). The assignment gives one detection to each anchor: before this
// rule anchor 1 took the second and jumped 1 m onto object 2. Now anchor 1
// stays lost at (0, 0), the second detection counts as anchor 2's duplicate
// (no new symbol), and no third anchor appears.
TEST(Cardinality, DetectionInsideATrackedGateDoesNotBringBackALostAnchor) {
  const ConceptualModel m = model(2);
  Tracker tr(m);
  see_both_then_lose_first(tr, 1.0, 3.0);
  Observation twin = obs(1.02, 0, 3.0);
  twin.sensors = {"r1/cam2"};
  tr.cycle(3.0, {obs(1, 0, 3.0), twin}, {});
  ASSERT_EQ(tr.anchors().size(), 2u);
  const Anchor& a1 = tr.anchors()[0];
  EXPECT_EQ(a1.id, 1u);
  EXPECT_EQ(a1.status, AnchorStatus::kCoasting);
  EXPECT_LT(a1.fused.x.head<2>().norm(), 0.05);
  EXPECT_EQ(nearest(tr, 1, 0)->id, 2u);
}
