// The modes of an ambiguous localization carried from frame to frame
// (TrackerOptions::ambiguous_global_period): on the MSL field, field-line
// points alone cannot tell a pose from its half-turn mirror
// (x, y, theta) -> (-x, -y, theta + pi); the tracker keeps both, moves
// them with odometry, searches globally only every 30 frames and commits
// at the first frame with a coloured goal or post in view.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/angle.h"
#include "mrt_murea/tracker.h"
#include "mrt_sim/sensors.h"

using namespace mrt::murea;
using mrt::common::angle_diff;
using mrt::common::deg_to_rad;
using mrt::common::kPi;

namespace {

// The simulator's noise-free percepts at a pose; lines_only keeps the
// field-line points (symmetric), else every class with its colour.
std::vector<Percept> percepts_at(const mrt::sim::World& w, const Pose2D& pose, bool lines_only) {
  std::vector<Percept> ps;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, pose, mrt::sim::SensorsConfig{})) {
    const auto cls = parse_feature_class(s.membership_class);
    if (cls && (!lines_only || *cls == FeatureClass::Line)) ps.push_back({*cls, s.color, s.distance, s.bearing, 1.0});
  }
  return ps;
}

mrt::sim::World field() {
  mrt::sim::World w = mrt::sim::load_world(MRT_MUREA_DATA "/msl_field.yaml");
  w.movers.clear();
  return w;
}

Pose2D mirror(const Pose2D& p) { return Pose2D(-p.x, -p.y, p.theta + kPi); }

// Within the plateau's reach: 0.1 m and 3 degrees (as test_tracker.cpp).
bool near(const Pose2D& a, const Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y) < 0.1 && std::abs(angle_diff(a.theta, b.theta)) < deg_to_rad(3);
}

// The two carried modes are the truth and its mirror, in either order.
void expect_modes(const Tracker& t, const Pose2D& truth) {
  ASSERT_EQ(t.modes().size(), 2u);
  const Pose2D &a = t.modes()[0].pose, &b = t.modes()[1].pose;
  EXPECT_TRUE((near(a, truth) && near(b, mirror(truth))) || (near(a, mirror(truth)) && near(b, truth)))
      << "modes (" << a.x << ", " << a.y << ", " << a.theta << ") and (" << b.x << ", " << b.y << ", " << b.theta
      << ")";
}

}  // namespace

// One global search, then 10 frames of 5 cm forward with exact odometry:
// each a windowed search per mode, both modes following the motion; the
// 12th frame sees the coloured goal and its posts and commits to the truth.
TEST(Modes, CarriedByOdometryAndCommittedByColour) {
  const mrt::sim::World w = field();
  const FeatureMap map(w);
  Tracker t(map, TrackerOptions{});
  Pose2D truth(-6.0, -1.0, 0.3);  // the west goal 3 to 3.6 m away
  TrackResult r = t.update(percepts_at(w, truth, true));
  EXPECT_EQ(r.mode, TrackMode::Global);
  EXPECT_TRUE(r.lost);
  EXPECT_EQ(r.modes, 2u);
  expect_modes(t, truth);
  const Pose2D step(0.05, 0.0, 0.0);
  for (int i = 0; i < 10; ++i) {
    SCOPED_TRACE(i);
    truth = truth * step;
    t.predict(step, {1e-6, 0, 0, 0, 1e-6, 0, 0, 0, 1e-8});
    r = t.update(percepts_at(w, truth, true));
    EXPECT_EQ(r.mode, TrackMode::Tracking);  // no global search
    EXPECT_TRUE(r.lost);
    EXPECT_TRUE(r.search.ambiguous);
    expect_modes(t, truth);
  }
  truth = truth * step;
  t.predict(step, {1e-6, 0, 0, 0, 1e-6, 0, 0, 0, 1e-8});
  r = t.update(percepts_at(w, truth, false));
  EXPECT_FALSE(r.lost);
  EXPECT_TRUE(t.tracking());
  EXPECT_TRUE(t.modes().empty());
  EXPECT_TRUE(near(r.pose, truth)) << r.pose.x << ", " << r.pose.y << ", " << r.pose.theta;
}

// Standing still on lines only for 61 frames: global searches at frames
// 0, 30 and 60 (every ambiguous_global_period = 30 frames), windowed ones
// in between; with the period 0 (the former behaviour) all 61 are global.
TEST(Modes, GlobalSearchesAtABoundedRate) {
  const mrt::sim::World w = field();
  const FeatureMap map(w);
  const std::vector<Percept> ps = percepts_at(w, Pose2D(2.0, 1.0, -0.7), true);
  for (const int period : {30, 0}) {
    TrackerOptions o;
    o.ambiguous_global_period = period;
    Tracker t(map, o);
    int globals = 0;
    for (int i = 0; i < 61; ++i) {
      const TrackResult r = t.update(ps);
      EXPECT_TRUE(r.lost);
      globals += r.mode == TrackMode::Global ? 1 : 0;
      if (period == 30) {
        EXPECT_EQ(r.mode == TrackMode::Global, i % 30 == 0) << i;
      }
    }
    EXPECT_EQ(globals, period == 30 ? 3 : 61);
    EXPECT_EQ(t.modes().size(), period == 30 ? 2u : 0u);
  }
}
