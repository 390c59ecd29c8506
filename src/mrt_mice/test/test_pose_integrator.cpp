// Eqs. 4.3-4.5 as corrected in NOTES.md.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_mice/pose_integrator.h"

using namespace mrt::mice;

TEST(PoseIntegrator, HandComputedStep) {
  // From (1, 2, 90 deg) a displacement (dx, dy) = (3, 4): length 5 in the
  // direction 90 deg + atan2(4, 3): X' = 1 - 4, Y' = 2 + 3.
  const Pose2D p = integrate_pose(Pose2D(1, 2, M_PI / 2), Pose2D(3, 4, 0.25));
  EXPECT_NEAR(p.x, -3.0, 1e-12);
  EXPECT_NEAR(p.y, 5.0, 1e-12);
  EXPECT_NEAR(p.theta, M_PI / 2 + 0.25, 1e-12);
}

TEST(PoseIntegrator, BackwardsUsesAtan2NotArctan) {
  // dx < 0: arctan(dy/dx) would send the robot forwards.
  const Pose2D p = integrate_pose(Pose2D(0, 0, 0), Pose2D(-1, 0, 0));
  EXPECT_NEAR(p.x, -1.0, 1e-12);
  EXPECT_NEAR(p.y, 0.0, 1e-12);
}

TEST(PoseIntegrator, EqualsSE2Composition) {
  const Pose2D a(0.3, -1.2, 2.9), d(0.07, -0.02, 0.4);
  const Pose2D p = integrate_pose(a, d), q = a * d;
  EXPECT_NEAR(p.x, q.x, 1e-12);
  EXPECT_NEAR(p.y, q.y, 1e-12);
  EXPECT_NEAR(p.theta, q.theta, 1e-12);  // wrapped past pi
}

TEST(PoseIntegrator, SquareClosesAndCountsDistance) {
  PoseIntegrator it;
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < 100; ++i) it.add(Pose2D(0.01, 0, 0));
    it.add(Pose2D(0, 0, M_PI / 2));
  }
  EXPECT_NEAR(it.pose().x, 0.0, 1e-9);
  EXPECT_NEAR(it.pose().y, 0.0, 1e-9);
  EXPECT_NEAR(std::remainder(it.pose().theta, 2 * M_PI), 0.0, 1e-9);
  EXPECT_NEAR(it.distance(), 4.0, 1e-9);
  EXPECT_NEAR(it.rotation(), 2 * M_PI, 1e-9);
  it.reset(Pose2D(1, 1, 0));
  EXPECT_EQ(it.distance(), 0.0);
  EXPECT_EQ(it.pose().x, 1.0);
}
