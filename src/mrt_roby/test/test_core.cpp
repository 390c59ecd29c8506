// Roby's core: its shipped task file, road maps, sonar sectors, crisp data
// and the DGPS localizer.
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/parse_error.h"
#include "mrt_roby/crisp_builder.h"
#include "mrt_roby/dgps_localizer.h"
#include "mrt_roby/route_planner.h"
#include "mrt_roby/sonar_sectors.h"
#include "mrt_scare/task_config.h"

using namespace mrt::roby;
using mrt::common::ParseError;
using mrt::scare::GoalCrisp;
using mrt::scare::Mode;
using mrt::scare::load_sequencer_options;

TEST(TaskConfig, ShippedFileLoads) {
  const auto o = load_sequencer_options(MRT_ROBY_CONFIG "/tasks.yaml");
  EXPECT_TRUE(o.machines);  // ReachPathPoint is a task machine
  mrt::scare::Sequencer seq(o);
  seq.set_plan({{10.0, 0.0}}, 0.0, {0.0, 0.0, 0.0});
  EXPECT_GT(seq.active_timeout(), 0.0);
}

// The shipped machine file gives the single-state file's numbers: a
// 10 m leg from the origin, 15 + 4 * 10 = 55 s; 70 cm from the point not
// reached, 50 cm reached (within 0.6 m / ARRIVED [0, 60] cm).
TEST(TaskConfig, MachineFileMatchesTheShippedOne) {
  for (const char* file : {MRT_ROBY_CONFIG "/tasks.yaml", MRT_ROBY_TEST_DATA "/tasks_single_state.yaml"}) {
    mrt::scare::Sequencer seq(load_sequencer_options(file));
    seq.set_plan({{10.0, 0.0}}, 0.0, {0.0, 0.0, 0.0});
    EXPECT_DOUBLE_EQ(seq.active_timeout(), 55.0) << file;
    EXPECT_EQ(seq.update(1.0, {9.3, 0.0, 0.0}).size(), 0u) << file;
    EXPECT_EQ(seq.update(2.0, {9.5, 0.0, 0.0}).size(), 2u) << file;  // succeeded, route completed
    EXPECT_EQ(seq.state(), mrt::scare::SequencerState::kDone) << file;
  }
  EXPECT_FALSE(load_sequencer_options(MRT_ROBY_TEST_DATA "/tasks_single_state.yaml").machines);
}

TEST(RoadMap, ParsesAndPlans) {
  RoadMap m = parse_road_map(
      "frame: world\nclearance: 0.5\nbuildings:\n  - {name: A, box: [2, 1, 4, 3]}\n"
      "route: [[5, 0], [5, 5]]\n",
      "m.yaml");
  ASSERT_EQ(m.buildings.size(), 1u);
  RoutePlanner p(m);
  auto r = p.plan({0, 0});
  ASSERT_EQ(r.size(), 2u);
  // A leg through the building is refused.
  RoutePlanner bad(parse_road_map("buildings: [{name: A, box: [2, -1, 4, 1]}]\nroute: [[5, 0]]\n", "m"));
  EXPECT_THROW(bad.plan({0, 0}), std::invalid_argument);
  EXPECT_EQ(bad.map().frame, "map");  // no `frame`: REP-105's map
  EXPECT_EQ(m.frame, "world");        // as given
  // Re-planning after point 0 failed: from the current pose through the rest.
  r = p.replan({4.5, 0.2}, {5.0, 0.1});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_DOUBLE_EQ(r[0].y, 5.0);
  EXPECT_TRUE(p.unreachable()[0]);
  try {
    parse_road_map("route: [[1, 2, 3]]\n", "m.yaml");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_EQ(e.column(), 9);
  }
}

TEST(RoadMap, ReplanGoesRoundABuildingFromTheCurrentPose) {
  // Building A = [2, 4] x [-1, 1], clearance 0.5. Route (0, 3) -> (6, 3) ->
  // (6, -3). The robot gives up on (6, 3) standing at (0, 0): the straight
  // leg to (6, -3) grazes A's corner (2, -1). The shortest way keeping 0.5
  // m goes round the corner's arc of radius 0.5: at least the straight
  // distance hypot(6, 3) = 6.708, at most the polyline over the corner
  // pushed out by 0.505, (0, 0) -> (1.495, -1.505) -> (6, -3):
  // 2.1213 + 4.7466 = 6.868, plus SPIKE's grid margin (0.1414 m around the
  // corner: under 0.3 m more).
  RoutePlanner p(parse_road_map("clearance: 0.5\nbuildings: [{name: A, box: [2, -1, 4, 1]}]\n"
                                "route: [[0, 3], [6, 3], [6, -3]]\n", "m"));
  const Building a{"A", 2, -1, 4, 1};
  p.plan({-1, 3});
  const auto r = p.replan({0, 0}, {6, 3});
  ASSERT_GE(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r.back().x, 6.0);
  EXPECT_DOUBLE_EQ(r.back().y, -3.0);
  double len = 0.0;
  Point2D prev{0, 0};
  for (const auto& q : r) {
    EXPECT_GE(segment_rect_distance(prev, q, a), 0.5 - 1e-9) << q.x << ", " << q.y;
    EXPECT_LT(q.y, -1.0);  // round the lower side
    len += std::hypot(q.x - prev.x, q.y - prev.y);
    prev = q;
  }
  EXPECT_GE(len, std::hypot(6.0, 3.0));
  EXPECT_LE(len, 6.868 + 0.3);
  // From (1.8, 0), inside A's clearance (0.2 m from it), the robot backs
  // out first, coming no closer, then keeps the clearance.
  const auto q = p.detour({1.8, 0.0}, {6, -3});
  ASSERT_FALSE(q.empty());
  EXPECT_GE(segment_rect_distance({1.8, 0.0}, q[0], a), 0.2 - 1e-9);
  for (size_t i = 0; i < q.size(); ++i)
    EXPECT_GE(segment_rect_distance(q[i], i + 1 < q.size() ? q[i + 1] : Point2D{6, -3}, a), 0.5 - 1e-9) << i;
  // A clear leg needs no detour; a goal within the clearance has no way.
  EXPECT_TRUE(p.detour({0, 3}, {6, 3}).empty());
  EXPECT_THROW(p.detour({0, 0}, {4.3, 0}), std::runtime_error);
}

TEST(RoadMap, SegmentRectangleDistance) {
  Building b{"b", 0, 0, 2, 2};
  EXPECT_DOUBLE_EQ(segment_rect_distance({-1, 3}, {3, 3}, b), 1.0);   // parallel above
  EXPECT_DOUBLE_EQ(segment_rect_distance({-1, -1}, {3, 3}, b), 0.0);  // crossing
  EXPECT_NEAR(segment_rect_distance({3, 3}, {4, 4}, b), std::sqrt(2.0), 1e-12);  // corner
}

TEST(SonarSectors, MinimumPerSector) {
  // 16 sonars every 22.5 deg: front = 0, +-22.5; front-left = 45, 67.5.
  SonarSectors s(even_mounts_deg(16), default_sectors(), 5.0);
  ASSERT_EQ(s.members()[0].size(), 3u);
  ASSERT_EQ(s.members()[1].size(), 2u);
  ASSERT_EQ(s.members()[3].size(), 2u);  // left: 90, 112.5
  // back, across 180: 157.5, 180, -157.5 (sonars 7, 8, 9)
  EXPECT_EQ(s.members()[5], (std::vector<std::size_t>{7, 8, 9}));
  auto d = s.distances();
  for (double v : d) EXPECT_DOUBLE_EQ(v, 5.0);
  EXPECT_TRUE(s.set_range(15, 1.2));  // -22.5 deg: front
  EXPECT_TRUE(s.set_range(2, 0.7));   // 45 deg: front-left
  EXPECT_FALSE(s.set_range(3, NAN));
  EXPECT_FALSE(s.set_range(99, 1.0));
  d = s.distances();
  EXPECT_DOUBLE_EQ(d[0], 1.2);
  EXPECT_DOUBLE_EQ(d[1], 0.7);
  EXPECT_DOUBLE_EQ(d[2], 5.0);
}

TEST(SonarSectors, InfinitiesAsRep117AndStaleSonarsBlock) {
  // 8 sonars every 45 deg: sonar 0 alone is front, sonar 1 front-left,
  // sonar 2 left, sonar 7 front-right, sonar 6 right. Readings go stale
  // after 0.5 s.
  SonarSectors s(even_mounts_deg(8), default_sectors(), 5.0, 0.5);
  for (std::size_t i = 0; i < 8; ++i) ASSERT_TRUE(s.set_range(i, 3.0, 10.0));
  EXPECT_TRUE(s.set_range(0, INFINITY, 10.0));    // nothing in range
  EXPECT_TRUE(s.set_range(1, -INFINITY, 10.0));   // too close to measure
  EXPECT_FALSE(s.set_range(2, NAN, 10.2));        // refused: 3.0 kept, from t = 10
  EXPECT_FALSE(s.set_range(7, -0.5, 10.2));
  auto d = s.distances(10.3);
  EXPECT_DOUBLE_EQ(d[0], 5.0);
  EXPECT_DOUBLE_EQ(d[1], 0.0);
  EXPECT_DOUBLE_EQ(d[3], 3.0);
  EXPECT_TRUE(s.stale(10.5).empty());
  // At t = 10.6 only sonar 2 (left) and 7 (front-right) were not refreshed.
  for (std::size_t i : {0, 1, 3, 4, 5, 6}) ASSERT_TRUE(s.set_range(i, 4.0, 10.4));
  EXPECT_EQ(s.stale(10.6), (std::vector<std::size_t>{2, 7}));
  d = s.distances(10.6);
  EXPECT_DOUBLE_EQ(d[0], 4.0);  // front
  EXPECT_DOUBLE_EQ(d[2], 0.0);  // front-right: sonar 7 is silent
  EXPECT_DOUBLE_EQ(d[3], 0.0);  // left: sonar 2 is silent
  EXPECT_DOUBLE_EQ(d[4], 4.0);  // right
  // A sonar never heard from is stale from the start.
  SonarSectors fresh(even_mounts_deg(8), default_sectors(), 5.0, 0.5);
  EXPECT_EQ(fresh.stale(0.0).size(), 8u);
  EXPECT_THROW(SonarSectors(even_mounts_deg(8), default_sectors(), 5.0, -1.0), std::invalid_argument);
}

// Each Range message's own geometry: its max_range caps the reading (a
// sonar of 3 m range claiming 4.5 m says only "nothing within 3 m"), and a
// sonar's beam axis moved by set_mount (the node takes it from tf) changes
// its sector. 8 sonars every 45 deg as above.
TEST(SonarSectors, RangeMessageGeometry) {
  SonarSectors s(even_mounts_deg(8), default_sectors(), 5.0);
  EXPECT_TRUE(s.set_range(0, 4.5, 0.0, 3.0));
  EXPECT_DOUBLE_EQ(s.distances()[0], 3.0);   // front: capped at the sensor's 3 m
  EXPECT_TRUE(s.set_range(0, INFINITY, 0.0, 3.0));
  EXPECT_DOUBLE_EQ(s.distances()[0], 3.0);   // nothing within its 3 m
  EXPECT_TRUE(s.set_range(1, 1.0));          // 45 deg: front-left
  EXPECT_DOUBLE_EQ(s.distances()[1], 1.0);
  // tf says sonar 1 actually looks at -90 deg: right, no longer front-left.
  EXPECT_TRUE(s.set_mount(1, -90.0));
  EXPECT_DOUBLE_EQ(s.distances()[1], 5.0);
  EXPECT_DOUBLE_EQ(s.distances()[4], 1.0);
  EXPECT_EQ(s.members()[4], (std::vector<std::size_t>{6, 1}));
  EXPECT_FALSE(s.set_mount(9, 0.0));
  EXPECT_FALSE(s.set_mount(1, NAN));
}

TEST(CrispBuilder, RuleBaseUnits) {
  CrispInputs in;
  in.goal = GoalCrisp{250.0, -30.0};
  in.mode = Mode::kManual;
  in.sector_names = {"ObstacleFront", "ObstacleFrontLeft", "ObstacleFrontRight", "ObstacleLeft",
                     "ObstacleRight"};
  in.sector_distances = {1.0, 0.8, 2.0, 3.0, 1.5};
  in.remote = RemoteCommand{0.3, -M_PI / 6};
  in.last_jog_deg = 12.0;
  const auto c = build_crisp(in);
  auto get = [&](const std::string& n) -> double {
    for (const auto& x : c)
      if (x.name == n) return x.value;
    ADD_FAILURE() << n;
    return NAN;
  };
  EXPECT_EQ(get("Status"), 0.0);
  EXPECT_EQ(get("HaveGoal"), 1.0);
  EXPECT_EQ(get("GoalDistance"), 250.0);
  EXPECT_EQ(get("GoalBearing"), -30.0);
  EXPECT_DOUBLE_EQ(get("ObstacleFrontLeft"), 80.0);
  EXPECT_DOUBLE_EQ(get("FreeSide"), 80.0 - 150.0);
  EXPECT_DOUBLE_EQ(get("RemoteSpeed"), 30.0);
  EXPECT_NEAR(get("RemoteTurn"), -30.0, 1e-12);
  EXPECT_EQ(get("LastJog"), 12.0);
}

TEST(DgpsLocalizer, CorrectsPositionAndHeading) {
  // Odometry believes the heading is 0.2 rad off; driving straight along x
  // with exact fixes pulls the heading back.
  DgpsLocalizer l(mrt::common::Pose2D(0, 0, 0.2));
  double x = 0.0;
  for (int k = 0; k < 30; ++k) {
    for (int i = 0; i < 50; ++i) l.predict(0.5, 0.0, 0.02);  // 0.5 m per second
    x += 0.5 * 1.0;
    l.correct(x, 0.0);
  }
  EXPECT_NEAR(l.pose().theta, 0.0, 0.02);
  EXPECT_NEAR(l.pose().x, x, 0.05);
  EXPECT_NEAR(l.pose().y, 0.0, 0.05);
  EXPECT_EQ(l.fixes(), 30);
}
