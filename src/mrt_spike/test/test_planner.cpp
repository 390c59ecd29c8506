// Decomposition invariants and planners on hand-made maps. Expected lengths
// are worked by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "mrt_spike/jump_point_search.h"
#include "mrt_spike/line_of_sight.h"
#include "mrt_spike/movingai.h"
#include "mrt_spike/planner.h"
#include "mrt_spike/quadtree.h"
#include "mrt_spike/scenario_run.h"
#include "mrt_spike/subgoal_graph.h"

using namespace mrt::spike;

namespace {
const std::string kData = MRT_SPIKE_TEST_DATA;
const double kS2 = std::sqrt(2.0);

// 7x7, a wall in column 3 from row 0 to row 4.
OccupancyGrid wall_map() {
  OccupancyGrid g(7, 7);
  for (int y = 0; y <= 4; ++y) g.set_blocked(3, y, true);
  return g;
}

void check_invariants(const OccupancyGrid& g, const Quadtree& t) {
  std::vector<int> cover(static_cast<size_t>(g.width()) * g.height(), 0);
  for (size_t i = 0; i < t.leaves().size(); ++i) {
    const QuadLeaf& L = t.leaves()[i];
    for (int y = L.y; y < L.y + L.size; ++y)
      for (int x = L.x; x < L.x + L.size; ++x) {
        ASSERT_TRUE(g.free(x, y)) << "leaf " << i << " crosses an obstacle at " << x << "," << y;
        ++cover[g.index(x, y)];
        ASSERT_EQ(t.leaf_at(x, y), static_cast<int>(i));
      }
  }
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) {
      ASSERT_EQ(cover[g.index(x, y)], g.free(x, y) ? 1 : 0) << "cell " << x << "," << y;
      if (g.blocked(x, y)) {
        ASSERT_EQ(t.leaf_at(x, y), -1);
      }
    }
}
}  // namespace

TEST(Quadtree, EveryFreeCellCoveredOnceNoLeafCrossesAnObstacle) {
  const OccupancyGrid g = load_movingai_map(kData + "/random64.map");
  const Quadtree t(g);
  check_invariants(g, t);
  const OccupancyGrid p = load_movingai_map(kData + "/passage32.map");
  check_invariants(p, Quadtree(p));
  // not a power of two, with inflation
  OccupancyGrid odd(13, 9);
  odd.set_blocked(6, 4, true);
  check_invariants(inflate(odd, 1.5), Quadtree(inflate(odd, 1.5)));
}

TEST(Quadtree, LargeCellsInOpenSpaceFinestNearObstacles) {
  // 16x16 empty: one leaf of side 16 (below the 64 cap).
  OccupancyGrid open(16, 16);
  const Quadtree t(open);
  ASSERT_EQ(t.leaves().size(), 1u);
  EXPECT_EQ(t.leaves()[0].size, 16);
  // one blocked cell at (0,0): 3 leaves of 8, 3 of 4, 3 of 2, 3 of 1 = 12.
  open.set_blocked(0, 0, true);
  const Quadtree u(open);
  EXPECT_EQ(u.leaves().size(), 12u);
  EXPECT_EQ(u.leaves()[u.leaf_at(1, 0)].size, 1);
  EXPECT_EQ(u.leaves()[u.leaf_at(15, 15)].size, 8);
  // 128x128 empty with the 64 cap: 4 leaves
  EXPECT_EQ(Quadtree(OccupancyGrid(128, 128)).leaves().size(), 4u);
}

TEST(Quadtree, FastLineOfSightAgreesWithTheGridWalk) {
  // The leaf-jumping walk must answer exactly as the cell-by-cell one.
  OccupancyGrid g(96, 80);
  for (int k = 0; k < 60; ++k) stamp_disc(g, (k * 37) % 96, (k * 23) % 80, (k % 3) * 1.5, true);
  const Quadtree t(g);
  int agree = 0, visible = 0;
  unsigned long r = 16;
  auto next = [&r](int n) {
    r = r * 6364136223846793005UL + 1442695040888963407UL;
    return static_cast<int>((r >> 33) % static_cast<unsigned long>(n));
  };
  for (int k = 0; k < 4000; ++k) {
    const Cell a{next(96), next(80)}, b{next(96), next(80)};
    const bool slow = line_of_sight(g, a, b);
    ASSERT_EQ(t.line_of_sight(a, b), slow) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
    ++agree;
    visible += slow ? 1 : 0;
  }
  EXPECT_EQ(agree, 4000);
  EXPECT_GT(visible, 100);   // both answers occur
  EXPECT_LT(visible, 3900);
}

TEST(Planner, NarrowPassageOneCellWide) {
  // Wall in column 16 with a single free cell at row 20. Octile: (2,2) to
  // (15,20) is 13 diagonal + 5 straight, then 2 straight through the gap
  // (a diagonal into the gap would cut the wall's corner), then (17,20) to
  // (29,2) is 12 diagonal + 6 straight: 25*sqrt(2) + 13 = 48.3553.
  const OccupancyGrid g = load_movingai_map(kData + "/passage32.map");
  GridAstar astar(g);
  const PlanResult a = astar.plan({2, 2}, {29, 2});
  ASSERT_TRUE(a.solved);
  EXPECT_NEAR(a.length, 25 * kS2 + 13, 1e-9);
  EXPECT_TRUE(path_valid(g, a.path, {2, 2}, {29, 2}));
  for (int mode = 0; mode < 4; ++mode) {
    SpikeOptions opts;
    opts.graph = SpikeOptions::Graph::quadtree;
    opts.quadtree.centre_only = mode % 2 == 0;
    opts.refine = mode >= 2;  // without refinement the quadtree search alone finds the gap
    SpikePlanner spike(g, opts);
    const PlanResult s = spike.plan({2, 2}, {29, 2});
    ASSERT_TRUE(s.solved);
    EXPECT_TRUE(path_valid(g, s.path, {2, 2}, {29, 2}));
    EXPECT_FALSE(s.fallback);
    // Any path reaches column 16 inside the gap x in [15.5,16.5], y in
    // [19.5,20.5]: at least 2 * hypot(13.5, 17.5) = 44.21; at most octile.
    EXPECT_GE(s.length, 2 * std::hypot(13.5, 17.5));
    if (opts.refine) {
      EXPECT_LE(s.length, 25 * kS2 + 13 + 1e-9);
    }
  }
  // the subgoal graph: octile-optimal before string pulling, so at most octile after
  const PlanResult sg = SpikePlanner(g).plan({2, 2}, {29, 2});
  ASSERT_TRUE(sg.solved);
  EXPECT_TRUE(path_valid(g, sg.path, {2, 2}, {29, 2}));
  EXPECT_GE(sg.length, 2 * std::hypot(13.5, 17.5));
  EXPECT_LE(sg.length, 25 * kS2 + 13 + 1e-9);
}

TEST(Planner, OpenSpaceStraightLine) {
  const OccupancyGrid g(10, 10);
  // octile (0,0)->(9,5): 5 diagonals + 4 straight; any-angle: hypot(9,5).
  EXPECT_NEAR(GridAstar(g).plan({0, 0}, {9, 5}).length, 5 * kS2 + 4, 1e-9);
  SpikePlanner spike(g);
  const PlanResult s = spike.plan({0, 0}, {9, 5});
  ASSERT_TRUE(s.solved);
  EXPECT_NEAR(s.length, std::hypot(9.0, 5.0), 1e-9);
  ASSERT_EQ(s.path.size(), 2u);
  const PlanResult same = spike.plan({4, 4}, {4, 4});
  ASSERT_TRUE(same.solved);
  EXPECT_EQ(same.path.size(), 1u);
  EXPECT_DOUBLE_EQ(same.length, 0.0);
}

TEST(Planner, AroundTheEndOfAWall) {
  const OccupancyGrid g = wall_map();
  // Octile (1,1)->(5,1): down to (2,5) = 1 diag + 3 straight, (2,5)->(4,5)
  // = 2 (the diagonals past the wall's end would cut its corner), up to
  // (5,1) = 1 diag + 3: 8 + 2*sqrt(2) = 10.828.
  const PlanResult a = GridAstar(g).plan({1, 1}, {5, 1});
  ASSERT_TRUE(a.solved);
  EXPECT_NEAR(a.length, 8 + 2 * kS2, 1e-9);
  // Any-angle: (1,1)->(2,5)->(4,5)->(5,1) is valid (hand-checked: the first
  // segment crosses x=1.5 at y=3, in free column 2): 2*sqrt(17) + 2 = 10.246.
  // Lower bound around the wall's corners (2.5,4.5), (3.5,4.5):
  // 2 * hypot(1.5, 3.5) + 1 = 8.616.
  const PlanResult s = SpikePlanner(g).plan({1, 1}, {5, 1});
  ASSERT_TRUE(s.solved);
  EXPECT_TRUE(path_valid(g, s.path, {1, 1}, {5, 1}));
  EXPECT_LE(s.length, 2 * std::sqrt(17.0) + 2 + 1e-9);
  EXPECT_GE(s.length, 2 * std::hypot(1.5, 3.5) + 1);
}

TEST(Planner, BlockedOrUnreachableGivesReasonAndNearestPoint) {
  const OccupancyGrid g = wall_map();
  SpikePlanner spike(g);
  PlanResult r = spike.plan({3, 2}, {5, 1});  // start inside the wall
  EXPECT_FALSE(r.solved);
  EXPECT_EQ(r.reason, "start (3, 2) is inside an obstacle");
  EXPECT_EQ(r.nearest, (Cell{2, 2}));  // first free cell at distance 1 in scan order
  // Goal (0,0) enclosed: wall around it.
  OccupancyGrid e(5, 5);
  e.set_blocked(1, 0, true);
  e.set_blocked(1, 1, true);
  e.set_blocked(0, 1, true);
  r = SpikePlanner(e).plan({4, 4}, {0, 0});
  EXPECT_FALSE(r.solved);
  EXPECT_EQ(r.reason, "goal (0, 0) is not reachable from the start");
  // reachable cells nearest (0,0): (2,0) and (0,2) at distance 2; (2,0) first
  EXPECT_EQ(r.nearest, (Cell{2, 0}));
  r = GridAstar(e).plan({4, 4}, {7, 7});
  EXPECT_EQ(r.reason, "goal (7, 7) is outside the map");
  EXPECT_EQ(r.nearest, (Cell{4, 4}));
}

TEST(Planner, StringPullNeverLengthens) {
  const OccupancyGrid g(5, 5);
  const std::vector<Cell> zigzag{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
  const auto pulled = string_pull(g, zigzag);
  EXPECT_EQ(pulled, (std::vector<Cell>{{0, 0}, {4, 0}}));  // 4 < 4*sqrt(2)
}

class SpikeVertices : public ::testing::TestWithParam<bool> {};

TEST_P(SpikeVertices, MatchesOctileOnRandomMap) {
  // 64x64, 30 % random obstacles (seed 16): every query both planners solve,
  // SPIKE's path valid and at most 1.01 x the octile A* length.
  const OccupancyGrid g = load_movingai_map(kData + "/random64.map");
  SpikeOptions opts;
  opts.graph = SpikeOptions::Graph::quadtree;
  opts.quadtree.centre_only = GetParam();
  SpikePlanner spike(g, opts);
  GridAstar astar(g);
  int solved = 0, pairs = 0;
  for (int k = 0; k < 200; ++k) {
    const Cell s{(k * 37) % 64, (k * 11) % 64}, t{(k * 53 + 7) % 64, (k * 29 + 3) % 64};
    if (g.blocked(s.x, s.y) || g.blocked(t.x, t.y)) continue;
    ++pairs;
    const PlanResult a = astar.plan(s, t), b = spike.plan(s, t);
    ASSERT_EQ(a.solved, b.solved) << k;
    if (!a.solved) continue;
    ++solved;
    EXPECT_TRUE(path_valid(g, b.path, s, t)) << k;
    EXPECT_LE(b.length, 1.01 * a.length + 1e-9) << k;
  }
  EXPECT_GT(pairs, 50);
  EXPECT_GT(solved, 40);
}

INSTANTIATE_TEST_SUITE_P(CentreAndCorners, SpikeVertices, ::testing::Values(true, false));

TEST(SubgoalGraph, CornersOfAWallEnd) {
  // The wall of column 3, rows 0-4, has one end: its convex corners are the
  // free cells diagonal to (3,4) with both shared sides free, (2,5) and
  // (4,5) (the map border makes none: the cells beside are blocked too).
  // They see each other straight across (3,5): one edge each way.
  const OccupancyGrid g = wall_map();
  SubgoalGraph sg(g);
  EXPECT_EQ(sg.subgoals(), (std::vector<Cell>{{2, 5}, {4, 5}}));
  EXPECT_EQ(sg.edge_count(), 2u);
  double cost = 0.0;
  const std::vector<Cell> p = sg.plan({1, 1}, {5, 1}, &cost);
  EXPECT_NEAR(cost, 8 + 2 * kS2, 1e-9);  // as the A* in AroundTheEndOfAWall
  EXPECT_TRUE(path_valid(g, p, {1, 1}, {5, 1}));
  EXPECT_NEAR(path_length(p), 8 + 2 * kS2, 1e-9);  // waypoints are the octile runs' ends
  EXPECT_TRUE(sg.plan({3, 2}, {5, 1}).empty());    // start in the wall
}

TEST(SubgoalGraph, OctileCostEqualsAstarOnRandomMap) {
  // The subgoal graph search is exact: the same octile cost as the A* on
  // every pair of the 64x64 random map, and its waypoints form a valid path.
  const OccupancyGrid g = load_movingai_map(kData + "/random64.map");
  SubgoalGraph sg(g);
  GridAstar astar(g);
  int solved = 0;
  for (int k = 0; k < 400; ++k) {
    const Cell s{(k * 37) % 64, (k * 11) % 64}, t{(k * 53 + 7) % 64, (k * 29 + 3) % 64};
    if (g.blocked(s.x, s.y) || g.blocked(t.x, t.y)) continue;
    const PlanResult a = astar.plan(s, t);
    double cost = -1.0;
    const std::vector<Cell> p = sg.plan(s, t, &cost);
    ASSERT_EQ(a.solved, !p.empty()) << k;
    if (!a.solved) continue;
    ++solved;
    EXPECT_NEAR(cost, a.length, 1e-6) << k;
    EXPECT_NEAR(path_length(p), a.length, 1e-6) << k;
    EXPECT_TRUE(path_valid(g, p, s, t)) << k;
  }
  EXPECT_GT(solved, 100);
}

TEST(SubgoalGraph, LandmarksKeepTheCostAndCutExpansions) {
  // The differential heuristic is consistent: with 8 landmarks the cost is
  // still the A*'s on every pair of the random map, and the search expands
  // fewer vertices in total than with the octile heuristic alone (it is never
  // below octile, so never more on a pair up to ties).
  const OccupancyGrid g = load_movingai_map(kData + "/random64.map");
  SubgoalGraph plain(g), alt(g, 8);
  EXPECT_EQ(plain.landmark_count(), 0);
  EXPECT_EQ(alt.landmark_count(), 8);
  GridAstar astar(g);
  int solved = 0, exp_plain = 0, exp_alt = 0;
  for (int k = 0; k < 400; ++k) {
    const Cell s{(k * 37) % 64, (k * 11) % 64}, t{(k * 53 + 7) % 64, (k * 29 + 3) % 64};
    if (g.blocked(s.x, s.y) || g.blocked(t.x, t.y)) continue;
    const PlanResult a = astar.plan(s, t);
    double cost = -1.0;
    const std::vector<Cell> p = alt.plan(s, t, &cost, &exp_alt);
    plain.plan(s, t, nullptr, &exp_plain);
    ASSERT_EQ(a.solved, !p.empty()) << k;
    if (!a.solved) continue;
    ++solved;
    EXPECT_NEAR(cost, a.length, 1e-6) << k;
    EXPECT_TRUE(path_valid(g, p, s, t)) << k;
  }
  EXPECT_GT(solved, 100);
  EXPECT_LT(exp_alt, exp_plain);
}

TEST(JumpPointSearch, OctileCostEqualsAstar) {
  // Exact like the A* (same octile cost, valid path) on the random map and
  // through the one-cell passage (25*sqrt(2) + 13, see NarrowPassageOneCellWide).
  const OccupancyGrid g = load_movingai_map(kData + "/random64.map");
  JumpPointSearch jps(g);
  GridAstar astar(g);
  int solved = 0;
  for (int k = 0; k < 400; ++k) {
    const Cell s{(k * 37) % 64, (k * 11) % 64}, t{(k * 53 + 7) % 64, (k * 29 + 3) % 64};
    if (g.blocked(s.x, s.y) || g.blocked(t.x, t.y)) continue;
    const PlanResult a = astar.plan(s, t), j = jps.plan(s, t);
    ASSERT_EQ(a.solved, j.solved) << k;
    if (!a.solved) continue;
    ++solved;
    EXPECT_NEAR(j.length, a.length, 1e-6) << k;
    EXPECT_NEAR(path_length(j.path), a.length, 1e-6) << k;
    EXPECT_TRUE(path_valid(g, j.path, s, t)) << k;
  }
  EXPECT_GT(solved, 100);
  const OccupancyGrid p = load_movingai_map(kData + "/passage32.map");
  const PlanResult j = JumpPointSearch(p).plan({2, 2}, {29, 2});
  ASSERT_TRUE(j.solved);
  EXPECT_NEAR(j.length, 25 * kS2 + 13, 1e-9);
}

TEST(ScenarioRun, OutputFormat) {
  const OccupancyGrid g = load_movingai_map(kData + "/passage32.map");
  const auto scen = load_scenario(kData + "/passage32.map.scen");
  SpikePlanner spike(g);
  auto out = run_queries(g, scen, {1}, [&](const Cell& s, const Cell& t) { return spike.plan(s, t); });
  ASSERT_EQ(out.size(), 1u);
  out[0].time_us = 12.0;
  std::ostringstream ss;
  print_outcome(ss, out[0]);
  // (0,0)->(9,5) in line of sight: one segment of sqrt(106) = 10.295630
  EXPECT_EQ(ss.str(), "query 1 solved 1 length 10.295630 time_us 12.0\npath 1 0 0 9 5\n");
  EXPECT_THROW(run_queries(g, scen, {2}, [&](const Cell& s, const Cell& t) { return spike.plan(s, t); }),
               std::out_of_range);
  const RunStats st = summarize(out);
  EXPECT_DOUBLE_EQ(st.solved_pct, 100.0);
  EXPECT_NEAR(st.max_ratio, std::sqrt(106.0) / 11.07106781, 1e-9);
}
