// The world loader and the geometry helpers: the shipped MSL field counted
// by hand from the MSL rules the file encodes, doors and regions, and
// malformed files named by file:line:column.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_world/world_loader.h"

using namespace mrt::world;

namespace {

// The ParseError of parse_world(text), or a failure when it loads.
mrt::common::ParseError error_of(const std::string& text) {
  try {
    parse_world(text, "w.yaml");
  } catch (const mrt::common::ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return mrt::common::ParseError("", 0, 0, "");
}

const char* kRooms =
    "name: rooms\n"
    "bounds: [0, 0, 10, 5]\n"
    "walls: [[5, 0, 5, 2], [5, 3, 5, 5]]\n"
    "doors:\n"
    "  - {name: middle, wall: [5, 2, 5, 3]}\n"
    "regions:\n"
    "  - {name: west, polygon: [[0, 0], [5, 0], [5, 5], [0, 5]]}\n"
    "  - {name: east, polygon: [[5, 0], [10, 0], [10, 5], [5, 5]]}\n"
    "robots: [{name: r1, base: ianus3, pose: [1, 1, 0]}]\n"  // the simulator's, skipped
    "seed: 3\n";

}  // namespace

// msl_field.yaml: 4 touch/goal lines, the halfway line, the centre circle
// as a 24-gon, 3 + 3 penalty-area lines, 3 + 3 goal-area lines and four
// corner arcs of 4 chords: 4 + 1 + 24 + 6 + 6 + 16 = 57 segments.
TEST(WorldLoader, MslField) {
  const World w = load_world(MRT_WORLDS_DIR "/msl_field.yaml");
  EXPECT_EQ(w.name, "msl_field");
  EXPECT_EQ(w.field_lines.size(), 57u);
  EXPECT_EQ(w.walls.size(), 4u);
  EXPECT_EQ(w.goals.size(), 2u);
  EXPECT_EQ(w.posts_of("Landmark").size(), 4u);
  EXPECT_DOUBLE_EQ(w.min_x, -10.0);
  EXPECT_DOUBLE_EQ(w.max_y, 7.0);
  // The centre circle's first chord: (2, 0) to (2 cos 15deg, 2 sin 15deg).
  EXPECT_NEAR(w.field_lines[5].a.x, 2.0, 1e-12);
  EXPECT_NEAR(w.field_lines[5].b.y, 2.0 * std::sin(M_PI / 12), 1e-12);
  // Walls and the goals' 3 walls each.
  EXPECT_EQ(solid_segments(w).size(), 4u + 6u);
}

// yellow_goal: mouth centre (9, 0), into +x, 2 m wide, 0.5 m deep; blue_goal
// at (-9, 0) turned by 180 deg: its left post (looking in) is at y = -1.
TEST(WorldGeometry, GoalWallsAndPosts) {
  const World w = load_world(MRT_WORLDS_DIR "/msl_field.yaml");
  const auto walls = goal_walls(w.goals[0]);
  EXPECT_NEAR(walls[0].a.x, 9.5, 1e-12);
  EXPECT_NEAR(walls[0].a.y, 1.0, 1e-12);
  EXPECT_NEAR(walls[0].b.y, -1.0, 1e-12);
  const auto blue = goal_posts(w.goals[1]);
  EXPECT_NEAR(blue[0].x, -9.0, 1e-12);
  EXPECT_NEAR(blue[0].y, -1.0, 1e-12);
  EXPECT_NEAR(blue[1].y, 1.0, 1e-12);
  Point2D c;
  EXPECT_NEAR(distance_to_segment({3, 4}, {{0, 0}, {6, 0}}, &c), 4.0, 1e-12);
  EXPECT_NEAR(c.x, 3.0, 1e-12);
  EXPECT_NEAR(distance_to_segment({-3, 4}, {{0, 0}, {6, 0}}), 5.0, 1e-12);  // beyond the end: to (0, 0)
}

TEST(WorldLoader, DoorsRegionsAndSimulationKeys) {
  const World w = parse_world(kRooms, "rooms.yaml");
  ASSERT_EQ(w.doors.size(), 1u);
  EXPECT_DOUBLE_EQ(w.door("middle").span.b.y, 3.0);
  EXPECT_THROW(w.door("back"), std::out_of_range);
  ASSERT_EQ(w.regions.size(), 2u);
  ASSERT_NE(w.region_at({2, 2}), nullptr);
  EXPECT_EQ(w.region_at({2, 2})->name, "west");
  EXPECT_EQ(w.region_at({7.5, 4.9})->name, "east");
  EXPECT_EQ(w.region_at({11, 1}), nullptr);
  EXPECT_EQ(w.walls.size(), 2u);  // the door is open: not a wall
}

TEST(WorldGeometry, InsidePolygon) {
  // An L: the unit square's corner (1..2, 1..2) cut away from a 2 x 2 square.
  const std::vector<Point2D> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(inside(l, {0.5, 1.5}));
  EXPECT_TRUE(inside(l, {1.5, 0.5}));
  EXPECT_FALSE(inside(l, {1.5, 1.5}));
  EXPECT_FALSE(inside(l, {-0.1, 0.5}));
  EXPECT_FALSE(inside({}, {0, 0}));
}

TEST(WorldLoader, ErrorsNameFileLineColumn) {
  auto e = error_of("name: x\nbounds: [0, 0, 1, 1]\nwals: []\n");
  EXPECT_EQ(e.file(), "w.yaml");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 1);
  EXPECT_NE(e.message().find("unknown key 'wals'"), std::string::npos) << e.what();
  e = error_of("name: x\nbounds: [0, 0, 1, 1]\ndoors:\n  - {name: a, wall: [0, 0, 1, 0]}\n  - {name: a, wall: [0, 1, 1, 1]}\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_NE(e.message().find("duplicate door name 'a'"), std::string::npos) << e.what();
  e = error_of("name: x\nbounds: [0, 0, 1, 1]\nregions:\n  - {name: r, polygon: [[0, 0], [1, 1]]}\n");
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(e.message().find("at least 3 corners"), std::string::npos) << e.what();
  e = error_of("name: x\nbounds: [1, 0, 0, 1]\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.message().find("xmin < xmax"), std::string::npos) << e.what();
  e = error_of("name: x\nbounds: [0, 0, 1, 1]\ndoors:\n  - {name: d}\n");
  EXPECT_NE(e.message().find("missing required key 'wall'"), std::string::npos) << e.what();
  e = error_of("name: x\nbounds: [0, 0, 1, 1]\nposts:\n  - {name: p, class: Unicorn, x: 0, y: 0}\n");
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(e.message().find("expected a class of the ontology"), std::string::npos) << e.what();
  e = error_of("bounds: [0, 0, 1, 1]\n");
  EXPECT_NE(e.message().find("'name'"), std::string::npos) << e.what();
  e = error_of("");
  EXPECT_EQ(e.line(), 1);
  EXPECT_NE(e.message().find("empty document"), std::string::npos) << e.what();
  EXPECT_THROW(load_world(MRT_WORLD_TEST_DATA "/nowhere.yaml"), mrt::common::ParseError);
}

// Every shipped world loads.
TEST(WorldLoader, ShippedWorlds) {
  for (const char* f : {"msl_field", "msl_team", "museum", "roby_outdoor"})
    EXPECT_NO_THROW(load_world(std::string(MRT_WORLDS_DIR "/") + f + ".yaml")) << f;
}
