#include <gtest/gtest.h>

#include "mrt_common/angle.h"

using namespace mrt::common;

TEST(Angle, NormalizeWrapsIntoHalfOpenInterval) {
  EXPECT_NEAR(normalize_angle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(normalize_angle(-3 * kPi / 2), kPi / 2, 1e-12);
  EXPECT_NEAR(normalize_angle(7.0), 7.0 - 2 * kPi, 1e-12);
  EXPECT_DOUBLE_EQ(normalize_angle(kPi), kPi);    // +pi stays
  EXPECT_DOUBLE_EQ(normalize_angle(-kPi), kPi);   // -pi maps to +pi
  EXPECT_DOUBLE_EQ(normalize_angle(0.25), 0.25);
}

TEST(Angle, DiffTakesTheShortWay) {
  // 350 deg - 10 deg = -20 deg, not 340 deg.
  EXPECT_NEAR(angle_diff(deg_to_rad(350), deg_to_rad(10)), deg_to_rad(-20), 1e-12);
  EXPECT_NEAR(rad_to_deg(deg_to_rad(123.0)), 123.0, 1e-12);
}

TEST(Angle, CircularMeanAcrossWrapAround) {
  // Mean of 350 and 10 degrees is 0, where the arithmetic mean would say 180.
  EXPECT_NEAR(circular_mean({deg_to_rad(350), deg_to_rad(10)}), 0.0, 1e-12);
  // Weighted: 0 deg with weight 1 and 90 deg with weight 1 -> 45 deg.
  EXPECT_NEAR(circular_mean({0.0, kPi / 2}, {1.0, 1.0}), kPi / 4, 1e-12);
  // 0 deg weight 3, 90 deg weight 1 -> atan2(1, 3).
  EXPECT_NEAR(circular_mean({0.0, kPi / 2}, {3.0, 1.0}), std::atan2(1.0, 3.0), 1e-12);
}

TEST(Angle, CircularMeanRejectsUndefinedInput) {
  EXPECT_THROW(circular_mean({0.0, kPi}), std::invalid_argument);
  EXPECT_THROW(circular_mean({}), std::invalid_argument);
  EXPECT_THROW(circular_mean({0.0}, {1.0, 2.0}), std::invalid_argument);
}
