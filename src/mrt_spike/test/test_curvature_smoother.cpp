// CurvatureSmoother: Dubins and Reeds-Shepp curves through SPIKE's
// waypoints, against lengths worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "mrt_spike/curvature_smoother.h"
#include "mrt_spike/planner.h"
#include "mrt_spike/world_planner.h"

using namespace mrt::spike;

namespace {

// 10 x 10 m of free cells of 0.1 m, the origin at its centre.
const OccupancyGrid kOpen(100, 100);
const GridFrame kCentred{0.1, -5.0, -5.0};

SmoothingOptions options(SmoothingOptions::Model m, double r) {
  SmoothingOptions o;
  o.model = m;
  o.turning_radius = r;
  o.step = 0.02;
  return o;
}

bool all_cells_free(const OccupancyGrid& g, const GridFrame& f, const std::vector<Pose>& poses) {
  for (const Pose& p : poses)
    if (g.blocked(static_cast<int>(std::lround((p.x - f.origin_x) / f.resolution)),
                  static_cast<int>(std::lround((p.y - f.origin_y) / f.resolution))))
      return false;
  return true;
}

}  // namespace

TEST(CurvatureSmoother, DubinsUTurnIsAHalfCircle) {
  // (0, 0) heading 0 to (0, 2r) heading pi: a left half circle round
  // (0, r), length pi r, curvature 1/r all along.
  const double r = 1.0;
  const CurvatureSmoother s(kOpen, kCentred, options(SmoothingOptions::Model::dubins, r));
  const SmoothedPath p = s.smooth({{0, 0, 0}, {0, 2 * r, 0}}, 0.0, M_PI);
  EXPECT_TRUE(p.fully_smoothed);
  EXPECT_NEAR(p.length, M_PI * r, 1e-9);
  EXPECT_NEAR(polyline_length(p.poses), M_PI * r, 1e-3);  // chords of 0.02 m
  EXPECT_NEAR(p.max_curvature, 1.0 / r, 1e-3);
  for (const Pose& q : p.poses) EXPECT_NEAR(std::hypot(q.x, q.y - r), r, 1e-9);
  EXPECT_NEAR(p.poses.back().x, 0.0, 1e-12);
  EXPECT_NEAR(p.poses.back().y, 2 * r, 1e-12);
}

TEST(CurvatureSmoother, StraightPathStaysStraight) {
  // (0, 0) to (3, 4), heading along it: the segment itself, length 5.
  for (auto m : {SmoothingOptions::Model::dubins, SmoothingOptions::Model::reeds_shepp}) {
    const CurvatureSmoother s(kOpen, kCentred, options(m, 0.3));
    const SmoothedPath p = s.smooth({{0, 0, 0}, {3, 4, 0}}, std::atan2(4.0, 3.0));
    EXPECT_TRUE(p.fully_smoothed);
    EXPECT_NEAR(p.length, 5.0, 1e-9);
    EXPECT_LT(p.max_curvature, 1e-6);
    for (const Pose& q : p.poses) EXPECT_NEAR(4 * q.x - 3 * q.y, 0.0, 1e-9);  // on the line
    EXPECT_EQ(corner_count(p.poses), 0);
  }
}

TEST(CurvatureSmoother, CurvatureNeverExceedsTheBound) {
  // a zigzag of sharp corners (90 and 135 degrees), three radii
  const std::vector<Pose> zigzag{{-4, -4, 0}, {0, -4, 0}, {0, 0, 0}, {-3, 3, 0}, {3, 3, 0}};
  EXPECT_EQ(corner_count(zigzag), 3);
  EXPECT_TRUE(std::isinf(max_curvature({{0, 0, 0}, {1, 0, 0}, {1, 0, 1}})));  // turning on the spot
  for (auto m : {SmoothingOptions::Model::dubins, SmoothingOptions::Model::reeds_shepp})
    for (double r : {0.2, 0.5, 1.0}) {
      const SmoothedPath p = CurvatureSmoother(kOpen, kCentred, options(m, r)).smooth(zigzag, 0.0);
      EXPECT_TRUE(p.fully_smoothed);
      EXPECT_LE(p.max_curvature, 1.0 / r * 1.001) << r;  // chord vs arc of 0.02 m
      EXPECT_GT(p.max_curvature, 1.0 / r * 0.99) << r;   // it does turn at the bound
      EXPECT_GE(p.length, polyline_length(zigzag) - 1e-9);
    }
}

TEST(CurvatureSmoother, ReedsSheppNoLongerThanDubins) {
  // The goal 1 m straight behind: Reeds-Shepp backs up 1 m; Dubins loops.
  const double r = 0.5;
  const CurvatureSmoother d(kOpen, kCentred, options(SmoothingOptions::Model::dubins, r));
  const CurvatureSmoother rs(kOpen, kCentred, options(SmoothingOptions::Model::reeds_shepp, r));
  std::vector<Pose> out;
  double ld = 0, lrs = 0;
  ASSERT_TRUE(rs.curve({0, 0, 0}, {-1, 0, 0}, out, lrs));
  EXPECT_NEAR(lrs, 1.0, 1e-9);
  EXPECT_NEAR(max_curvature(out), 0.0, 1e-9);
  ASSERT_TRUE(d.curve({0, 0, 0}, {-1, 0, 0}, out, ld));
  EXPECT_GT(ld, 2 * M_PI * r);  // at least a full turn
  // and over a fan of queries
  for (int i = 0; i < 36; ++i) {
    const double a = i * M_PI / 18;
    const Pose from{0, 0, 0}, to{2 * std::cos(a), 2 * std::sin(a), 2 * a};
    ASSERT_TRUE(d.curve(from, to, out, ld));
    ASSERT_TRUE(rs.curve(from, to, out, lrs));
    EXPECT_LE(lrs, ld + 1e-9) << i;
    EXPECT_GE(lrs, 2.0 - 1e-9) << i;  // never shorter than the straight line
  }
}

TEST(CurvatureSmoother, AroundAnObstacleStaysInFreeCells) {
  // 4 x 3 m at 0.05 m, a 1 x 1 m block in the middle, inflated by 0.3 m;
  // SPIKE's any-angle path round it, smoothed with r = 0.3 m.
  OccupancyGrid raw(80, 60);
  for (int y = 20; y < 40; ++y)
    for (int x = 30; x < 50; ++x) raw.set_blocked(x, y, true);
  const OccupancyGrid grid = inflate(raw, 6.0);
  const GridFrame f{0.05, 0.0, 0.0};
  SpikePlanner planner(grid);
  const PlanResult r = planner.plan({5, 30}, {75, 30});
  ASSERT_TRUE(r.solved);
  ASSERT_GE(r.path.size(), 3u);  // it turns round the block
  for (auto m : {SmoothingOptions::Model::dubins, SmoothingOptions::Model::reeds_shepp}) {
    const CurvatureSmoother s(grid, f, options(m, 0.3));
    const SmoothedPath p = s.smooth(waypoint_poses(r.path, f), 0.0, 0.0);
    EXPECT_TRUE(all_cells_free(grid, f, p.poses));
    EXPECT_TRUE(s.poses_free(p.poses));
    EXPECT_TRUE(p.fully_smoothed);
    EXPECT_LE(p.max_curvature, 1.0 / 0.3 * 1.001);
    EXPECT_GE(p.length, r.length * f.resolution - 1e-9);  // never shorter than the any-angle path
    EXPECT_NEAR(p.poses.front().x, 0.25, 1e-12);
    EXPECT_NEAR(p.poses.back().x, 3.75, 1e-12);
    EXPECT_NEAR(p.poses.back().yaw, 0.0, 1e-12);
  }
}

TEST(CurvatureSmoother, KeepsTheStraightSegmentWhereNoCurveFits) {
  // An L-shaped corridor one cell (0.1 m) wide: no curve of r = 1 m fits
  // its corner, the straight segments are kept, the robot turns on the spot.
  OccupancyGrid grid(20, 20, true);
  for (int x = 2; x <= 15; ++x) grid.set_blocked(x, 2, false);
  for (int y = 2; y <= 15; ++y) grid.set_blocked(15, y, false);
  const GridFrame f{0.1, 0.0, 0.0};
  const CurvatureSmoother s(grid, f, options(SmoothingOptions::Model::dubins, 1.0));
  const SmoothedPath p = s.smooth({{0.2, 0.2, 0}, {1.5, 0.2, 0}, {1.5, 1.5, 0}}, 0.0, M_PI / 2);
  EXPECT_FALSE(p.fully_smoothed);
  EXPECT_GE(p.kept_segments, 1);
  EXPECT_TRUE(std::isinf(p.max_curvature));
  EXPECT_TRUE(all_cells_free(grid, f, p.poses));
  EXPECT_NEAR(p.length, 2.6, 1e-9);  // the two straight segments
}

TEST(CurvatureSmoother, ModelsByNameAndBadOptions) {
  EXPECT_EQ(smoothing_model("none"), SmoothingOptions::Model::none);
  EXPECT_EQ(smoothing_model("dubins"), SmoothingOptions::Model::dubins);
  EXPECT_EQ(smoothing_model("reeds_shepp"), SmoothingOptions::Model::reeds_shepp);
  EXPECT_THROW(smoothing_model("bezier"), std::invalid_argument);
  EXPECT_THROW(CurvatureSmoother(kOpen, kCentred, options(SmoothingOptions::Model::none, 0.3)), std::invalid_argument);
  EXPECT_THROW(CurvatureSmoother(kOpen, kCentred, options(SmoothingOptions::Model::dubins, 0.0)), std::invalid_argument);
  // one waypoint: itself, with the goal's heading
  const SmoothedPath p = CurvatureSmoother(kOpen, kCentred, options(SmoothingOptions::Model::dubins, 0.3))
                             .smooth({{1, 1, 0}, {1, 1, 0}}, 0.0, 0.5);
  ASSERT_EQ(p.poses.size(), 1u);
  EXPECT_DOUBLE_EQ(p.poses[0].yaw, 0.5);
  EXPECT_EQ(p.length, 0.0);
}

TEST(CurvatureSmoother, ReedsSheppCuspsKeepTheBound) {
  // 0.4 m sideways, same heading: Reeds-Shepp goes forward and back (cusps);
  // the cusps are sampled, so heading change over distance stays 1/r.
  const double r = 0.5;
  const CurvatureSmoother rs(kOpen, kCentred, options(SmoothingOptions::Model::reeds_shepp, r));
  std::vector<Pose> out;
  double l = 0;
  ASSERT_TRUE(rs.curve({0, 0, 0}, {0, 0.4, 0}, out, l));
  int reversals = 0;
  for (size_t i = 2; i < out.size(); ++i) {
    const double ax = out[i - 1].x - out[i - 2].x, ay = out[i - 1].y - out[i - 2].y;
    const double bx = out[i].x - out[i - 1].x, by = out[i].y - out[i - 1].y;
    if (ax * bx + ay * by < 0) ++reversals;
  }
  EXPECT_GE(reversals, 1);
  EXPECT_LE(max_curvature(out), 1.0 / r * 1.001);
  EXPECT_GT(l, 0.4);
}

TEST(CurvatureSmoother, MuseumQueriesKeepTheBoundAndTheFreeCells) {
  // FollowMe's museum at 0.05 m, 0.3 + 0.1 m of inflation, r = 0.15 m (long
  // nearly straight segments: OMPL 1.5's Dubins assertion is avoided)
  WorldPlanner planner(load_any_map(std::string(MRT_WORLDS_DIR) + "/museum.yaml", 0.05), WorldPlannerOptions{});
  const OccupancyGrid& grid = planner.inflated();
  const GridFrame& f = planner.map().frame;
  std::vector<Cell> free;
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x)
      if (grid.free(x, y)) free.push_back({x, y});
  for (auto m : {SmoothingOptions::Model::dubins, SmoothingOptions::Model::reeds_shepp}) {
    SmoothingOptions o = options(m, 0.15);
    o.step = 0.05;
    const CurvatureSmoother s(grid, f, o);
    std::mt19937 rng(1);
    std::uniform_int_distribution<size_t> pick(0, free.size() - 1);
    int fully = 0;
    for (int q = 0; q < 150; ++q) {
      const Cell a = free[pick(rng)], b = free[pick(rng)];
      const WorldPlan p = planner.plan(f.origin_x + f.resolution * a.x, f.origin_y + f.resolution * a.y,
                                       f.origin_x + f.resolution * b.x, f.origin_y + f.resolution * b.y);
      ASSERT_TRUE(p.solved) << q;
      const SmoothedPath sp = s.smooth(waypoint_poses(p.waypoints, f), std::numeric_limits<double>::quiet_NaN());
      EXPECT_TRUE(all_cells_free(grid, f, sp.poses)) << q;
      if (!sp.fully_smoothed) continue;
      ++fully;
      EXPECT_LE(sp.max_curvature, 1.0 / 0.15 * 1.005) << q;  // chords of 0.05 m on arcs of 0.15 m
    }
    EXPECT_GE(fully, 135);  // 90 %
  }
}
