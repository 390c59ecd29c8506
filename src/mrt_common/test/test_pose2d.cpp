#include <gtest/gtest.h>

#include "mrt_common/pose2d.h"

using namespace mrt::common;

TEST(Pose2D, ComposeByHand) {
  // Robot at (1, 2) facing +y; a point 1 m ahead of it is at (1, 3).
  const Pose2D a(1.0, 2.0, kPi / 2);
  const Pose2D b(1.0, 0.0, kPi / 2);
  const Pose2D c = a * b;
  EXPECT_NEAR(c.x, 1.0, 1e-12);
  EXPECT_NEAR(c.y, 3.0, 1e-12);
  EXPECT_NEAR(c.theta, kPi, 1e-12);
}

TEST(Pose2D, InverseComposesToIdentity) {
  const Pose2D a(0.3, -1.2, 2.5);
  const Pose2D i = a * a.inverse();
  EXPECT_NEAR(i.x, 0.0, 1e-12);
  EXPECT_NEAR(i.y, 0.0, 1e-12);
  EXPECT_NEAR(i.theta, 0.0, 1e-12);
  // Inverse of a pure translation is the opposite translation.
  const Pose2D t = Pose2D(2.0, 3.0, 0.0).inverse();
  EXPECT_NEAR(t.x, -2.0, 1e-12);
  EXPECT_NEAR(t.y, -3.0, 1e-12);
}

TEST(Pose2D, TransformPointBothWays) {
  const Pose2D a(1.0, 1.0, kPi / 2);
  const Point2D p = a.transform({2.0, 0.0});  // 2 m ahead, facing +y
  EXPECT_NEAR(p.x, 1.0, 1e-12);
  EXPECT_NEAR(p.y, 3.0, 1e-12);
  const Point2D q = a.inverse_transform(p);
  EXPECT_NEAR(q.x, 2.0, 1e-12);
  EXPECT_NEAR(q.y, 0.0, 1e-12);
}

TEST(Pose2D, ExpTwistQuarterCircle) {
  // v = 1 m/s, omega = pi/2 rad/s for 1 s: a quarter circle of radius 2/pi.
  const double r = 2.0 / kPi;
  const Pose2D p = exp_twist(1.0, 0.0, kPi / 2, 1.0);
  EXPECT_NEAR(p.x, r, 1e-12);
  EXPECT_NEAR(p.y, r, 1e-12);
  EXPECT_NEAR(p.theta, kPi / 2, 1e-12);
}

TEST(Pose2D, ExpTwistStraightAndSideways) {
  const Pose2D s = exp_twist(0.5, 0.0, 0.0, 2.0);
  EXPECT_NEAR(s.x, 1.0, 1e-15);
  EXPECT_NEAR(s.y, 0.0, 1e-15);
  const Pose2D l = exp_twist(0.0, 0.5, 0.0, 2.0);  // omni base moving left
  EXPECT_NEAR(l.x, 0.0, 1e-15);
  EXPECT_NEAR(l.y, 1.0, 1e-15);
  // Tiny rotation: the series branch agrees with the closed form written
  // without cancellation, (1 - cos w) / w = 2 sin^2(w/2) / w.
  const double w = 1e-7;
  const Pose2D t = exp_twist(1.0, 0.0, w, 1.0);
  EXPECT_NEAR(t.x, std::sin(w) / w, 1e-15);
  EXPECT_NEAR(t.y, 2.0 * std::sin(w / 2) * std::sin(w / 2) / w, 1e-18);
}
