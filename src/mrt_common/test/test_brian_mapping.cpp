// Mr. BRIAN's commands as a twist (brian_mapping.h; formerly mrt_airboard's).
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/brian_mapping.h"

using namespace mrt::common;

TEST(BrianMapping, PolarForOmniBases) {
  BrianMapping m(BrianMappingParams::for_base(BaseType::kOmni));
  // SpeedModule 50 cm/s towards SpeedAngle 90 deg (left), Rotation 30 deg/s.
  const Twist2D t = *m.to_twist({{"SpeedModule", 50.0}, {"SpeedAngle", 90.0}, {"Rotation", 30.0}, {"Other", 9.0}});
  EXPECT_NEAR(t.vx, 0.0, 1e-12);
  EXPECT_NEAR(t.vy, 0.5, 1e-12);
  EXPECT_NEAR(t.omega, M_PI / 6.0, 1e-12);
  const Twist2D b = *m.to_twist({{"SpeedModule", 20.0}, {"SpeedAngle", 180.0}});
  EXPECT_NEAR(b.vx, -0.2, 1e-12);
  EXPECT_NEAR(b.omega, 0.0, 1e-12);
}

TEST(BrianMapping, UnicycleForDifferentialBases) {
  BrianMapping m(BrianMappingParams::for_base(BaseType::kDifferential));
  const Twist2D t = *m.to_twist({{"Speed", 120.0}, {"Jog", -90.0}, {"SpeedAngle", 45.0}});
  EXPECT_NEAR(t.vx, 1.2, 1e-12);
  EXPECT_NEAR(t.vy, 0.0, 1e-12);
  EXPECT_NEAR(t.omega, -M_PI / 2.0, 1e-12);
  // Absent commands count as 0.
  const Twist2D z = *m.to_twist({{"Jog", 0.0}});
  EXPECT_EQ(z.vx, 0.0);
  // A non-finite mapped command invalidates the array (the node drops and
  // counts it); a non-finite unknown one is ignored, and so is SpeedAngle,
  // which the unicycle mode does not map.
  EXPECT_FALSE(m.to_twist({{"Speed", NAN}, {"Jog", 10.0}}).has_value());
  EXPECT_FALSE(m.to_twist({{"Speed", 10.0}, {"Jog", -INFINITY}}).has_value());
  const auto ok = m.to_twist({{"Speed", 10.0}, {"Other", NAN}, {"SpeedAngle", NAN}});
  ASSERT_TRUE(ok.has_value());
  EXPECT_NEAR(ok->vx, 0.1, 1e-15);
}

TEST(BrianMapping, NonFiniteAngleInvalidatesPolarArrays) {
  BrianMapping m(BrianMappingParams::for_base(BaseType::kOmni));
  EXPECT_FALSE(m.to_twist({{"SpeedModule", 20.0}, {"SpeedAngle", NAN}}).has_value());
}

TEST(BrianMapping, ParsesAndValidates) {
  EXPECT_EQ(BrianMappingParams::parse_mode("polar"), BrianMappingParams::Mode::kPolar);
  EXPECT_THROW(BrianMappingParams::parse_mode("cartesian"), std::invalid_argument);
  BrianMappingParams p;
  p.speed_name = "";
  EXPECT_THROW(BrianMapping{p}, std::invalid_argument);
}
