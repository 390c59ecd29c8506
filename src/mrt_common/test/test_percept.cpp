// The percept builder and the position readers: the same object read in
// polar and Cartesian form, numbers worked out by hand (a 3-4-5 triangle).
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/percept.h"

using namespace mrt::common;

// distance 5, bearing atan2(4, 3) = 0.927295 rad: x = 3, y = 4. With
// sigma_distance 0.1 and sigma_bearing 0.02 the propagated x/y deviation is
// hypot(0.1, 5 * 0.02) = hypot(0.1, 0.1) = 0.141421.
TEST(Percept, PolarBuilderWritesBothForms) {
  PerceptObject o("ball", percept_class::kBall);
  o.set_polar({5.0, std::atan2(4.0, 3.0), 0.1, 0.02, 0.8}).set_symbol("color", "orange");
  ASSERT_EQ(o.attributes.size(), 5u);
  EXPECT_NEAR(*o.number("x"), 3.0, 1e-12);
  EXPECT_NEAR(*o.number("y"), 4.0, 1e-12);
  EXPECT_NEAR(o.find("x")->variability, 0.1414213562, 1e-9);
  EXPECT_DOUBLE_EQ(o.find("distance")->reliability, 0.8);
  EXPECT_EQ(o.symbol("color"), "orange");
  EXPECT_FALSE(o.number("color"));  // a symbol has no number
  EXPECT_EQ(o.symbol("x"), "");
  // An explicit x/y deviation replaces the propagated one.
  o.set_polar({5.0, 0.0, 0.1, 0.02}, 0.05);
  EXPECT_DOUBLE_EQ(o.find("y")->variability, 0.05);
  EXPECT_EQ(o.attributes.size(), 5u);  // set replaces, does not append
  EXPECT_EQ(o.set_symbol("team", "").attributes.size(), 5u);  // an empty symbol sets nothing
}

// Only x = 3, y = 4 (sigma 0.2 and 0.1): polar() gives distance 5, bearing
// 0.927295, sigma_distance = max(0.2, 0.1) = 0.2, sigma_bearing 0.2 / 5 =
// 0.04. Only distance 5 / bearing pi/2: cartesian() gives (0, 5).
TEST(Percept, ReadersTakeEitherForm) {
  PerceptObject c("p", percept_class::kPerson);
  c.set_cartesian({3.0, 4.0, 0.2, 0.1, 0.9});
  const auto p = polar(c);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->distance, 5.0, 1e-12);
  EXPECT_NEAR(p->bearing, 0.9272952180, 1e-9);
  EXPECT_NEAR(p->sigma_distance, 0.2, 1e-12);
  EXPECT_NEAR(p->sigma_bearing, 0.04, 1e-12);
  EXPECT_DOUBLE_EQ(p->reliability, 0.9);
  PerceptObject q("q", percept_class::kLandmark);
  q.set("distance", 5.0, 0.1).set("bearing", M_PI / 2, 0.02);
  const auto xy = cartesian(q);
  ASSERT_TRUE(xy);
  EXPECT_NEAR(xy->x, 0.0, 1e-12);
  EXPECT_NEAR(xy->y, 5.0, 1e-12);
  EXPECT_NEAR(xy->sigma_x, std::hypot(0.1, 0.1), 1e-12);
  // Both forms present: each reader takes its own.
  q.set("x", 1.0).set("y", 2.0);
  EXPECT_DOUBLE_EQ(cartesian(q)->x, 1.0);
  EXPECT_DOUBLE_EQ(polar(q)->distance, 5.0);
  // Half a pair is no position; a symbol is no number.
  PerceptObject h("h", percept_class::kBall);
  h.set("x", 1.0).set_symbol("y", "left");
  EXPECT_FALSE(polar(h));
  EXPECT_FALSE(cartesian(h));
}
