// FeatureMap and DistanceGrid: classes, layers and distance values worked
// out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mrt_murea/feature_map.h"
#include "mrt_world/world_loader.h"

using namespace mrt::murea;
using mrt::world::Segment;

TEST(FeatureClass, NamesAsTheSimulatorsPercepts) {
  EXPECT_EQ(parse_feature_class("Line"), FeatureClass::Line);
  EXPECT_EQ(parse_feature_class("Goal"), FeatureClass::Goal);
  EXPECT_EQ(parse_feature_class("GoalPost"), FeatureClass::GoalPost);
  EXPECT_EQ(parse_feature_class("Landmark"), FeatureClass::Landmark);
  EXPECT_EQ(parse_feature_class("Wall"), FeatureClass::Wall);
  EXPECT_FALSE(parse_feature_class("Ball"));
  EXPECT_FALSE(parse_feature_class("line"));  // case matters, as in the simulator
  EXPECT_STREQ(to_string(FeatureClass::GoalPost), "GoalPost");
}

// One segment (0,0)-(1,0) on a grid over [-1, 2] x [-1, 1] with 0.1 m pixels.
TEST(DistanceGrid, PixelCentreDistancesByHand) {
  const DistanceGrid g({Segment{{0, 0}, {1, 0}}}, -1, -1, 2, 1, 0.1);
  EXPECT_EQ(g.width(), 30);
  EXPECT_EQ(g.height(), 20);
  // (0.52, 0.33) lies in the pixel centred at (0.55, 0.35): 0.35 above the segment.
  EXPECT_NEAR(g.at(0.52, 0.33), 0.35, 1e-6);
  EXPECT_NEAR(g.exact(0.52, 0.33), 0.33, 1e-12);
  // (1.33, 0.43) -> centre (1.35, 0.45), nearest point the end (1, 0):
  // hypot(0.35, 0.45) = 0.5700877.
  EXPECT_NEAR(g.at(1.33, 0.43), 0.5700877, 1e-6);
  // Outside the grid the distance is exact: (3, 4) to (1, 0) = sqrt(20).
  EXPECT_NEAR(g.at(3, 4), std::sqrt(20.0), 1e-12);
  EXPECT_NEAR(g.slack(), 0.1 * std::sqrt(2.0), 1e-12);
}

// The two properties the search's bound relies on, on random points.
TEST(DistanceGrid, WithinHalfSlackOfTheTruthAndLipschitzUpToSlack) {
  const DistanceGrid g({Segment{{0, 0}, {1, 0}}, Segment{{-0.5, -0.7}, {0.3, 0.9}}}, -1, -1, 2, 1, 0.07);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(-1.5, 2.5), uy(-1.5, 1.5), ud(-0.2, 0.2);
  for (int i = 0; i < 20000; ++i) {
    const double x = ux(rng), y = uy(rng), qx = x + ud(rng), qy = y + ud(rng);
    EXPECT_LE(std::abs(g.at(x, y) - g.exact(x, y)), g.slack() / 2 + 1e-6);
    EXPECT_LE(std::abs(g.at(x, y) - g.at(qx, qy)), std::hypot(qx - x, qy - y) + g.slack() + 1e-6);
  }
}

TEST(FeatureMap, MslFieldLayers) {
  const FeatureMap map(mrt::world::load_world(MRT_MUREA_DATA "/msl_field.yaml"));
  EXPECT_EQ(map.points(FeatureClass::Goal).size(), 2u);
  EXPECT_EQ(map.points(FeatureClass::GoalPost).size(), 4u);
  EXPECT_EQ(map.points(FeatureClass::Landmark).size(), 4u);
  // A named goal matches its own mouth centre only: the yellow one at (9, 0).
  const Layer yellow = map.layer(FeatureClass::Goal, "yellow");
  ASSERT_EQ(yellow.points.size(), 1u);
  EXPECT_NEAR(yellow.distance(6, 4), 5.0, 1e-12);  // 3-4-5 triangle
  // An unnamed goal matches both: (-6, 4) is 5 m from the blue one at (-9, 0).
  EXPECT_NEAR(map.layer(FeatureClass::Goal, "").distance(-6, 4), 5.0, 1e-12);
  // Goal posts carry the goal's colour: blue posts at (-9, +-1).
  EXPECT_NEAR(map.layer(FeatureClass::GoalPost, "blue").distance(-9, 3), 2.0, 1e-12);
  // A colour no feature has never matches.
  EXPECT_TRUE(std::isinf(map.layer(FeatureClass::Landmark, "purple").distance(0, 0)));
  // Lines: (4.51, 0.01) is in the pixel centred at (4.5125, 0.0125) (grid
  // from -12, -9 in 2.5 cm pixels); nearest line the penalty line x = 6.75,
  // 2.2375 away (the centre circle is 2.51, the halfway line 4.51).
  EXPECT_NEAR(map.layer(FeatureClass::Line, "").distance(4.51, 0.01), 2.2375, 1e-5);
  // Walls include the goal walls: (9.31, 0.01) -> pixel centre (9.3125,
  // 0.0125), 0.1875 from the yellow goal's back wall x = 9.5.
  EXPECT_NEAR(map.layer(FeatureClass::Wall, "").distance(9.31, 0.01), 0.1875, 1e-5);
}

// The nearest point and the direction the distance grows: the segment's
// normal beside it, the direction from the end point beyond its ends
// (3-4-5 triangles: (1.3, 0.4) is 0.5 from the end (1, 0)).
TEST(DistanceGrid, NearestPointAndNormal) {
  const DistanceGrid g({Segment{{0, 0}, {1, 0}}}, -1, -1, 2, 1, 0.1);
  double nx = 0, ny = 0;
  Point2D c = g.nearest(0.5, 0.2, &nx, &ny);
  EXPECT_DOUBLE_EQ(c.x, 0.5);
  EXPECT_DOUBLE_EQ(c.y, 0.0);
  EXPECT_DOUBLE_EQ(std::abs(ny), 1.0);
  EXPECT_DOUBLE_EQ(nx, 0.0);
  c = g.nearest(1.3, 0.4, &nx, &ny);
  EXPECT_DOUBLE_EQ(c.x, 1.0);
  EXPECT_DOUBLE_EQ(c.y, 0.0);
  EXPECT_NEAR(nx, 0.6, 1e-12);
  EXPECT_NEAR(ny, 0.8, 1e-12);
  c = g.nearest(-0.3, -0.4, &nx, &ny);
  EXPECT_DOUBLE_EQ(c.x, 0.0);
  EXPECT_NEAR(nx, -0.6, 1e-12);
  EXPECT_NEAR(ny, -0.8, 1e-12);
}
