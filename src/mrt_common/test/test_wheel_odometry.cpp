// The wheel encoders' odometry (wheel_odometry.h): the AIRBoard driver's
// figures (formerly mrt_airboard's EncoderOdometry tests) and FollowMe's.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/base_kinematics.h"
#include "mrt_common/pose2d.h"
#include "mrt_common/wheel_odometry.h"

using namespace mrt::common;

namespace {
// Counts of each wheel after `t` seconds of constant wheel speeds.
std::vector<int64_t> counts(const std::vector<double>& w, double t, int cpr) {
  std::vector<int64_t> c;
  for (double v : w) c.push_back(static_cast<int64_t>(std::llround(v * t * cpr / (2.0 * M_PI))));
  return c;
}
}  // namespace

TEST(WheelOdometry, ConstantTwistGivesTheExactArc) {
  for (const char* name : {"ianus3", "triskar", "omni4"}) {
    const BaseGeometry g = base_preset(name).geometry;
    const int cpr = 1 << 20;  // fine counts: quantisation far below the tolerance
    const Twist2D t{0.4, g.type == BaseType::kOmni ? -0.2 : 0.0, 0.8};
    const auto w = inverse(g, t);
    WheelOdometry odo(g, cpr);
    for (int i = 0; i <= 500; ++i) odo.update(counts(w, i * 0.01, cpr), i * 0.01);
    const auto want = exp_twist(t.vx, t.vy, t.omega, 5.0);
    EXPECT_NEAR(odo.pose().x, want.x, 1e-4) << name;
    EXPECT_NEAR(odo.pose().y, want.y, 1e-4) << name;
    EXPECT_NEAR(odo.pose().theta, want.theta, 1e-5) << name;
    EXPECT_NEAR(odo.twist().vx, t.vx, 1e-3) << name;
    EXPECT_NEAR(odo.twist().vy, t.vy, 1e-3) << name;
    EXPECT_NEAR(odo.twist().omega, t.omega, 1e-3) << name;
  }
}

TEST(WheelOdometry, StraightLineAndReset) {
  WheelOdometry odo(base_preset("ianus3").geometry, 1000);
  odo.update({0, 0}, 0.0);
  // 1000 counts = one revolution = 2 pi 0.05 m.
  odo.update({1000, 1000}, 1.0);
  EXPECT_NEAR(odo.pose().x, 2 * M_PI * 0.05, 1e-12);
  EXPECT_NEAR(odo.pose().y, 0.0, 1e-12);
  // After a reset (board restarted) the counts start again from anything.
  odo.reset();
  odo.update({-77, 5}, 2.0);
  EXPECT_NEAR(odo.pose().x, 2 * M_PI * 0.05, 1e-12);
  EXPECT_EQ(odo.twist().vx, 0.0);
  EXPECT_THROW(odo.update({1, 2, 3}, 3.0), std::invalid_argument);
}

TEST(WheelOdometry, TwistIsMeasuredOverAWindow) {
  WheelOdometry odo(base_preset("ianus3").geometry, 8192, 0.01);
  const std::vector<double> w{5.0, 5.0};  // 0.25 m/s, ~6.5 counts per ms
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    std::vector<int64_t> c;
    for (double v : w) c.push_back(static_cast<int64_t>(std::floor(v * i * 1e-3 * 8192 / (2 * M_PI))));
    odo.update(c, i * 1e-3);
    if (i > 20) worst = std::max(worst, std::fabs(odo.twist().vx - 0.25));
  }
  // One count in a 10 ms window: 2 pi 0.05 / 8192 / 0.01 = 3.8 mm/s.
  EXPECT_LT(worst, 0.004);
  EXPECT_NEAR(odo.pose().x, 0.25, 1e-4);
}

// FollowMe's differential odometry by hand: IANUS3 (r 0.05 m, track 0.38 m)
// with 2000 ticks per revolution, one tick 2 pi 0.05 / 2000 = 1.5708e-4 m.
// The right wheel 2000 ticks, the left 0: dl = 0, dr = 0.314159 m, so
// ds = 0.157080 m and dtheta = 0.314159 / 0.38 = 0.826735 rad: the arc of
// radius 0.19 m about the left wheel ends at x = 0.19 sin(0.826735) =
// 0.139788 m, y = 0.19 (1 - cos(0.826735)) = 0.061317 m. The path length is
// |ds| + track / 2 |dtheta| = 0.157080 + 0.157080 = 0.314159 m.
TEST(WheelOdometry, DifferentialArcAndPathLengthByHand) {
  WheelOdometry odo(base_preset("ianus3").geometry, 2000);
  odo.update({0, 0});
  odo.update({0, 2000});
  EXPECT_NEAR(odo.pose().x, 0.139788, 1e-6);
  EXPECT_NEAR(odo.pose().y, 0.061317, 1e-6);
  EXPECT_NEAR(odo.pose().theta, 0.826735, 1e-6);
  EXPECT_NEAR(odo.travelled(), 0.314159, 1e-6);
  // Back again: the pose returns, the path length doubles; no time given,
  // no twist.
  odo.update({0, 0});
  EXPECT_NEAR(odo.pose().x, 0.0, 1e-12);
  EXPECT_NEAR(odo.pose().theta, 0.0, 1e-12);
  EXPECT_NEAR(odo.travelled(), 0.628319, 1e-6);
  EXPECT_EQ(odo.twist().vx, 0.0);
  // Bad geometry or counts are refused.
  BaseGeometry flat = base_preset("ianus3").geometry;
  flat.track = 0.0;
  EXPECT_THROW(WheelOdometry(flat, 2000), std::invalid_argument);
  EXPECT_THROW(WheelOdometry(base_preset("ianus3").geometry, 0), std::invalid_argument);
  BaseGeometry line = base_preset("triskar").geometry;
  line.wheel_angles = {0.0, 0.0, 0.0};
  EXPECT_THROW(WheelOdometry(line, 2000), std::invalid_argument);
}
