// Each fuzzy set at and between its breakpoints (shapes of NOTES.md and
// ../shared/peer/brian/README.md), and barycenter areas worked by hand.
#include <gtest/gtest.h>

#include "mrt_brian/fuzzy_set.h"

using namespace mrt::brian;

TEST(FuzzySet, Triangle) {
  TriangleSet t("T", 0, 10, 30);
  EXPECT_DOUBLE_EQ(t.membership(-1), 0.0);
  EXPECT_DOUBLE_EQ(t.membership(0), 0.0);
  EXPECT_DOUBLE_EQ(t.membership(5), 0.5);
  EXPECT_DOUBLE_EQ(t.membership(10), 1.0);
  EXPECT_DOUBLE_EQ(t.membership(25), 0.25);
  EXPECT_DOUBLE_EQ(t.membership(30), 0.0);
  EXPECT_DOUBLE_EQ(t.membership(31), 0.0);
}

TEST(FuzzySet, OpenLeft) {
  OpenLeftSet s("L", 20, 30);
  EXPECT_DOUBLE_EQ(s.membership(-100), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(20), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(22.5), 0.75);
  EXPECT_DOUBLE_EQ(s.membership(30), 0.0);
  EXPECT_DOUBLE_EQ(s.membership(1e6), 0.0);
}

TEST(FuzzySet, OpenRight) {
  OpenRightSet s("FAR", 100, 120);  // (TOR (FAR 100 120)) of §10.4.1
  EXPECT_DOUBLE_EQ(s.membership(0), 0.0);
  EXPECT_DOUBLE_EQ(s.membership(100), 0.0);
  EXPECT_DOUBLE_EQ(s.membership(105), 0.25);
  EXPECT_DOUBLE_EQ(s.membership(120), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(1e6), 1.0);
}

TEST(FuzzySet, OpenRightWithReversedBreakpointsIsOneBeyondB) {
  // IsAac's (TOR (RIGHT 15 5)): the reference trace (cycle 11) gives 1 at 5.648.
  OpenRightSet s("RIGHT", 15, 5);
  EXPECT_DOUBLE_EQ(s.membership(5.648), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(40), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(-10), 0.0);
}

TEST(FuzzySet, Divided) {
  DividedSet s("N", 0, 10, 350, 360);  // peaks at 0/360 degrees
  EXPECT_DOUBLE_EQ(s.membership(0), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(5), 0.5);
  EXPECT_DOUBLE_EQ(s.membership(10), 0.0);
  EXPECT_DOUBLE_EQ(s.membership(180), 0.0);
  EXPECT_DOUBLE_EQ(s.membership(350), 0.0);
  EXPECT_DOUBLE_EQ(s.membership(357.5), 0.75);
  EXPECT_DOUBLE_EQ(s.membership(360), 1.0);
}

TEST(FuzzySet, Trapezium) {
  TrapeziumSet near("NEAR", 40, 60, 100, 120);
  EXPECT_DOUBLE_EQ(near.membership(40), 0.0);
  EXPECT_DOUBLE_EQ(near.membership(45), 0.25);
  EXPECT_DOUBLE_EQ(near.membership(60), 1.0);
  EXPECT_DOUBLE_EQ(near.membership(80), 1.0);
  EXPECT_DOUBLE_EQ(near.membership(100), 1.0);
  EXPECT_DOUBLE_EQ(near.membership(115), 0.25);
  EXPECT_DOUBLE_EQ(near.membership(120), 0.0);
  // §10.4.1: (TRA (NEAREST 0 0.1 40 60)) is 0 at 0, (TRA (NEAREST 0 0 40 60)) is not.
  EXPECT_DOUBLE_EQ(TrapeziumSet("A", 0, 0.1, 40, 60).membership(0), 0.0);
  EXPECT_DOUBLE_EQ(TrapeziumSet("B", 0, 0, 40, 60).membership(0), 1.0);
}

TEST(FuzzySet, Rectangle) {
  RectangleSet s("R", 2, 4);
  EXPECT_DOUBLE_EQ(s.membership(1.999), 0.0);
  EXPECT_DOUBLE_EQ(s.membership(2), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(3), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(4), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(4.001), 0.0);
}

TEST(FuzzySet, Singleton) {
  SingletonSet s("T", 1);
  EXPECT_DOUBLE_EQ(s.membership(1), 1.0);
  EXPECT_DOUBLE_EQ(s.membership(0.999), 0.0);
  EXPECT_DOUBLE_EQ(s.singleton(), 1.0);
}

TEST(FuzzySet, FactoryChecksArity) {
  EXPECT_THROW(make_fuzzy_set("TRI", "x", {1, 2}), std::invalid_argument);
  EXPECT_THROW(make_fuzzy_set("FOO", "x", {1}), std::invalid_argument);
  EXPECT_STREQ(make_fuzzy_set("DIV", "x", {0, 1, 2, 3})->type(), "DIV");
}

TEST(FuzzySet, ClippedAreaByHand) {
  // TRI 0 10 20 clipped at 0.5: 20*0.5 - (10*0.5)/2 = 7.5, centroid 10.
  const auto tri = TriangleSet("T", 0, 10, 20).polygons();
  AreaMoment am = clipped_area(tri[0], 0.5);
  EXPECT_NEAR(am.area, 7.5, 1e-12);
  EXPECT_NEAR(am.moment / am.area, 10.0, 1e-12);
  // Unclipped: area 10.
  EXPECT_NEAR(clipped_area(tri[0], 1.0).area, 10.0, 1e-12);
  // REC 2 4 at 0.25: 0.5, centroid 3.
  am = clipped_area(RectangleSet("R", 2, 4).polygons()[0], 0.25);
  EXPECT_NEAR(am.area, 0.5, 1e-12);
  EXPECT_NEAR(am.moment / am.area, 3.0, 1e-12);
  // TRA 0 10 20 40 at 1: area (10 + 40) / 2 = 25; moment by pieces:
  // ∫0..10 x(x/10) = 33.333, ∫10..20 x = 150, ∫20..40 x(40-x)/20 = 266.667 -> 450.
  am = clipped_area(TrapeziumSet("Z", 0, 10, 20, 40).polygons()[0], 1.0);
  EXPECT_NEAR(am.area, 25.0, 1e-9);
  EXPECT_NEAR(am.moment, 450.0, 1e-9);
}
