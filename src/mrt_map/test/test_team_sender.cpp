// TeamSender: the heartbeat and the dead-reckoning trigger, against hand
// computation (constant velocity: the teammate predicts x0 + v dt).
#include <gtest/gtest.h>

#include <stdexcept>

#include "mrt_common/parse_error.h"
#include "mrt_map/team_sender.h"

using namespace mrt::map;

namespace {
ConceptualModel model(double threshold) {
  return ConceptualModel::parse("classes:\n  Ball: {motion: constant_velocity, accel_noise: 1}\n"
                                "team: {send_threshold: " + std::to_string(threshold) + "}\n",
                                "m.yaml");
}

RemoteTrack track(std::uint32_t id, double x, double vx, double stamp) {
  RemoteTrack t;
  t.id = id;
  t.class_index = 0;
  t.estimate.x << x, 0.0, vx, 0.0;
  t.estimate.P = 0.01 * Mat4::Identity();
  t.estimate.stamp = stamp;
  t.last_seen = stamp;
  return t;
}
}  // namespace

TEST(TeamSender, SendsOnTheHeartbeatAndWhenTheTeammatesPredictionIsOff) {
  const ConceptualModel m = model(0.05);
  EXPECT_DOUBLE_EQ(m.team().send_threshold, 0.05);
  TeamSender s(m, 0.1);
  EXPECT_TRUE(s.due(0.0, {track(1, 0.0, 1.0, 0.0)}));  // nothing sent yet
  s.sent(0.0, {track(1, 0.0, 1.0, 0.0)});
  // 1/30 s later the teammates predict x = 0.0333: the track there, or
  // 0.04 m off, is not worth a message; 0.06 m off is.
  const double t1 = 1.0 / 30.0;
  EXPECT_FALSE(s.due(t1, {track(1, t1, 1.0, t1)}));
  EXPECT_FALSE(s.due(t1, {track(1, t1 + 0.04, 1.0, t1)}));
  EXPECT_TRUE(s.due(t1, {track(1, t1 + 0.06, 1.0, t1)}));
  // Kicked at t = 0 to 2 m/s: at t1 it is 0.0333 m further than predicted
  // (not due), at 2 t1 0.0667 m (due).
  EXPECT_FALSE(s.due(t1, {track(1, 2.0 * t1, 2.0, t1)}));
  EXPECT_TRUE(s.due(2.0 * t1, {track(1, 4.0 * t1, 2.0, 2.0 * t1)}));
  // A track the teammates have not had.
  EXPECT_TRUE(s.due(t1, {track(1, t1, 1.0, t1), track(2, 3.0, 0.0, t1)}));
  s.sent(2.0 * t1, {track(1, 4.0 * t1, 2.0, 2.0 * t1)});
  EXPECT_EQ(s.periodic(), 1u);
  EXPECT_EQ(s.on_deviation(), 1u);
  // The heartbeat counts from the last send, whatever triggered it.
  EXPECT_FALSE(s.due(0.1, {track(1, 4.0 * t1 + 2.0 * (0.1 - 2.0 * t1), 2.0, 0.1)}));
  EXPECT_TRUE(s.due(2.0 * t1 + 0.1, {track(1, 4.0 * t1 + 0.2, 2.0, 2.0 * t1 + 0.1)}));
}

TEST(TeamSender, ThresholdZeroIsPeriodicOnly) {
  const ConceptualModel m = model(0.0);  // outlives the sender (held by reference)
  TeamSender s(m, 0.1);
  s.sent(0.0, {track(1, 0.0, 1.0, 0.0)});
  EXPECT_FALSE(s.due(0.05, {track(1, 5.0, 1.0, 0.05), track(2, 0.0, 0.0, 0.05)}));
  EXPECT_TRUE(s.due(0.1, {}));
  EXPECT_THROW(TeamSender(model(0.0), 0.0), std::invalid_argument);
  EXPECT_THROW(TeamSender(model(0.0), 0.1, 0.1), std::invalid_argument);
}

// Checked once per 30 Hz cycle whose timer fires a little early: 3 cycles
// are 0.0999 s. Without a tolerance the 10 Hz heartbeat slips to every 4th
// cycle (7.5 Hz); with half a cycle it keeps every 3rd.
TEST(TeamSender, HeartbeatToleratesTimerJitter) {
  const ConceptualModel m = model(0.0);
  for (const double tolerance : {0.0, 0.5 / 30.0}) {
    TeamSender s(m, 0.1, tolerance);
    int sends = 0;
    for (int k = 0; k < 300; ++k) {
      const double now = k * (0.0999 / 3.0);
      if (s.due(now, {})) s.sent(now, {}), ++sends;
    }
    EXPECT_EQ(sends, tolerance > 0.0 ? 100 : 75) << tolerance;
  }
  EXPECT_THROW(ConceptualModel::parse("team: {send_threshold: -0.1}\n", "m.yaml"), mrt::common::ParseError);
}
