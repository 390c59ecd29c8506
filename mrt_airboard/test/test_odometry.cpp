#include <gtest/gtest.h>

#include <cmath>

#include "mrt_airboard/odometry.h"
#include "mrt_common/pose2d.h"

using namespace mrt::airboard;
using mrt::common::exp_twist;

namespace {
// Counts of each wheel after `t` seconds of constant wheel speeds.
std::vector<int64_t> counts(const std::vector<double>& w, double t, int cpr) {
  std::vector<int64_t> c;
  for (double v : w) c.push_back(static_cast<int64_t>(std::llround(v * t * cpr / (2.0 * M_PI))));
  return c;
}
}  // namespace

TEST(EncoderOdometry, ConstantTwistGivesTheExactArc) {
  for (const char* name : {"ianus3", "triskar", "omni4"}) {
    BaseParams p = base_preset(name);
    p.counts_per_rev = 1 << 20;  // fine counts: quantisation far below the tolerance
    auto k = make_kinematics(p);
    const Twist2D t{0.4, k->holonomic() ? -0.2 : 0.0, 0.8};
    const auto w = k->inverse(t);
    EncoderOdometry odo(p);
    for (int i = 0; i <= 500; ++i) odo.update(counts(w, i * 0.01, p.counts_per_rev), i * 0.01);
    const auto want = exp_twist(t.vx, t.vy, t.omega, 5.0);
    EXPECT_NEAR(odo.pose().x, want.x, 1e-4) << name;
    EXPECT_NEAR(odo.pose().y, want.y, 1e-4) << name;
    EXPECT_NEAR(odo.pose().theta, want.theta, 1e-5) << name;
    EXPECT_NEAR(odo.twist().vx, t.vx, 1e-3) << name;
    EXPECT_NEAR(odo.twist().vy, t.vy, 1e-3) << name;
    EXPECT_NEAR(odo.twist().omega, t.omega, 1e-3) << name;
  }
}

TEST(EncoderOdometry, StraightLineAndReset) {
  BaseParams p = base_preset("ianus3");
  p.counts_per_rev = 1000;
  EncoderOdometry odo(p);
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

TEST(EncoderOdometry, TwistIsMeasuredOverAWindow) {
  BaseParams p = base_preset("ianus3");  // 8192 counts per revolution
  EncoderOdometry odo(p, 0.01);
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
