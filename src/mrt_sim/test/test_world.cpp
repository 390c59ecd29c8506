#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mrt_common/angle.h"
#include "mrt_common/parse_error.h"
#include "mrt_sim/world.h"

using namespace mrt::sim;
using mrt::common::deg_to_rad;
using mrt::common::kPi;
using mrt::common::ParseError;

namespace {

struct BadFile {
  const char* file;
  int line, column;
  const char* message;  // a part of the message
};

std::ostream& operator<<(std::ostream& os, const BadFile& b) { return os << b.file; }

class WorldErrors : public ::testing::TestWithParam<BadFile> {};

const char* kMinimal = "name: t\nbounds: [-5, -5, 5, 5]\nrobots:\n  - {name: r, base: ianus3, pose: [1, 2, 90]}\n";

}  // namespace

TEST_P(WorldErrors, NameFileLineColumnAndWhatWasExpected) {
  const BadFile& b = GetParam();
  const std::string path = std::string(MRT_SIM_TEST_DATA) + "/" + b.file;
  try {
    load_world(path);
    FAIL() << "no error for " << b.file;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), b.line) << e.what();
    EXPECT_EQ(e.column(), b.column) << e.what();
    EXPECT_NE(e.message().find(b.message), std::string::npos) << e.what();
  }
}

// Lines and columns counted by hand in the files under test/data.
INSTANTIATE_TEST_SUITE_P(
    BadFiles, WorldErrors,
    ::testing::Values(
        BadFile{"bad_syntax.yaml", 5, 4, "YAML syntax error"},
        BadFile{"missing_key.yaml", 4, 5, "missing required key 'x' in 'posts'"},
        BadFile{"wrong_type.yaml", 7, 13, "expected a number for 'radius'"},
        BadFile{"unknown_key.yaml", 8, 25, "unknown key 'max_rnage' in 'sonar'"},
        BadFile{"unknown_base.yaml", 5, 11, "unknown base preset 'roomba'"},
        BadFile{"negative_radius.yaml", 4, 40, "expected 'radius' > 0, got -0.1"},
        BadFile{"short_waypoints.yaml", 6, 16, "expected at least 2 waypoints"},
        BadFile{"duplicate_robot.yaml", 5, 12, "duplicate robot name 'robot1'"},
        BadFile{"no_robots.yaml", 5, 9, "expected at least one robot"},
        BadFile{"bad_angles.yaml", 7, 21, "wheel_angles"}));

TEST(World, MissingFileIsAParseError) {
  EXPECT_THROW(load_world(std::string(MRT_SIM_TEST_DATA) + "/nope.yaml"), ParseError);
}

TEST(World, MessageReadsFileLineColumn) {
  try {
    parse_world("name: x\nbounds: [0, 0, 1, 1]\nrobots:\n  - {name: r, base: ianus3, pose: [0, 0, zero]}\n",
                "inline.yaml");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_STREQ(e.what(), "inline.yaml:4:42: expected a number for 'pose'");
  }
}

TEST(World, MinimalDefaultsAndDegrees) {
  const World w = parse_world(kMinimal, "min.yaml");
  EXPECT_EQ(w.name, "t");
  EXPECT_EQ(w.file, "min.yaml");
  EXPECT_EQ(w.seed, 1u);
  EXPECT_FALSE(w.ball.enabled);
  ASSERT_EQ(w.robots.size(), 1u);
  const RobotConfig& r = w.robots[0];
  EXPECT_EQ(r.base.name, "ianus3");
  EXPECT_NEAR(r.initial_pose.theta, kPi / 2, 1e-15);  // 90 deg in the file
  // No sensors section: every sensor off.
  EXPECT_EQ(r.sensors.rate_mice, 0.0);
  EXPECT_EQ(r.sensors.rate_sonar, 0.0);
  EXPECT_EQ(r.sensors.rate_vision, 0.0);
  EXPECT_TRUE(r.sensors.mice.empty());
}

TEST(World, SensorsOverridesAndArcs) {
  const World w = parse_world(R"(
name: full
seed: 99
bounds: [-5, -5, 5, 5]
field_lines:
  - [0, 0, 1, 0]
  - {center: [0, 0], radius: 2, segments: 4, from: 0, to: 180}
goals:
  - {name: g, color: blue, x: 4, y: 0, theta: 0}
ball: {x: 1, friction: 0.3}
movers:
  - {name: m, class: Robot, waypoints: [[0, 0], [1, 0]], loop: false}
robots:
  - name: r
    base: triskar
    base_overrides: {body_radius: 0.3, wheel_angles: [0, 120, 240]}
    pose: [0, 0, 0]
    sensors:
      mice: {counts_per_m: 1000, left: {x: 0.05, y: 0.1, theta: 45}, right: {counts_per_m: 1200}}
      sonar: {count: 4, fov: 30, max_range: 3}
      vision: {bearing_noise: 1}
      dgps: {datum: [45.0, 9.0]}
)",
                              "full.yaml");
  EXPECT_EQ(w.seed, 99u);
  // 1 straight line + 4 chords of the half circle (45 deg each).
  ASSERT_EQ(w.field_lines.size(), 5u);
  EXPECT_NEAR(w.field_lines[1].b.x, 2.0 * std::cos(kPi / 4), 1e-12);
  EXPECT_NEAR(w.field_lines[4].b.x, -2.0, 1e-12);
  EXPECT_TRUE(w.ball.enabled);
  EXPECT_EQ(w.ball.friction, 0.3);
  EXPECT_FALSE(w.movers[0].loop);
  EXPECT_EQ(w.movers[0].membership_class, "Robot");

  const RobotConfig& r = w.robots[0];
  EXPECT_EQ(r.base.body_radius, 0.3);
  EXPECT_NEAR(r.base.wheel_angles[1], deg_to_rad(120), 1e-15);
  const SensorsConfig& s = r.sensors;
  ASSERT_EQ(s.mice.size(), 2u);
  EXPECT_EQ(s.mice[0].id, "left");
  EXPECT_EQ(s.mice[0].counts_per_m, 1000.0);
  EXPECT_NEAR(s.mice[0].mount.theta, kPi / 4, 1e-15);
  EXPECT_EQ(s.mice[1].counts_per_m, 1200.0);
  EXPECT_EQ(s.mice[1].mount.y, -0.1);  // default right mouse
  EXPECT_EQ(s.rate_mice, 50.0);
  // Four sonars evenly around a 0.3 m body: the second at (0, 0.3) facing +y.
  ASSERT_EQ(s.sonars.size(), 4u);
  EXPECT_NEAR(s.sonars[1].mount.x, 0.0, 1e-12);
  EXPECT_NEAR(s.sonars[1].mount.y, 0.3, 1e-12);
  EXPECT_NEAR(s.sonars[1].mount.theta, kPi / 2, 1e-12);
  EXPECT_NEAR(s.sonars[0].fov, deg_to_rad(30), 1e-15);
  EXPECT_EQ(s.sonars[0].max_range, 3.0);
  EXPECT_NEAR(s.vision_bearing_noise, deg_to_rad(1.0), 1e-15);
  EXPECT_EQ(s.rate_dgps, 1.0);
  EXPECT_EQ(s.datum_latitude, 45.0);
}

TEST(World, SonarMountsAndTheirErrors) {
  const std::string head = "name: s\nbounds: [-5, -5, 5, 5]\nrobots:\n  - name: r\n    base: omni4\n"
                           "    pose: [0, 0, 0]\n    sensors:\n      sonar: ";
  const World w = parse_world(head + "{mounts: [{x: 0.2, y: 0, theta: 0}, {x: 0, y: 0.2, theta: 90}]}\n", "s.yaml");
  ASSERT_EQ(w.robots[0].sensors.sonars.size(), 2u);
  EXPECT_NEAR(w.robots[0].sensors.sonars[1].mount.theta, kPi / 2, 1e-15);
  EXPECT_NEAR(w.robots[0].sensors.sonars[0].fov, 0.4, 1e-15);  // default, rad
  try {  // both ways of placing sonars: the second key is reported
    parse_world(head + "{count: 4, mounts: []}\n", "s.yaml");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_STREQ(e.what(), "s.yaml:8:33: expected either 'count' or 'mounts' in 'sonar', not both");
  }
  EXPECT_THROW(parse_world(head + "{count: 4, fov: 180}\n", "s.yaml"), ParseError);
  EXPECT_THROW(parse_world(head + "{count: 4, min_range: 2, max_range: 1}\n", "s.yaml"), ParseError);
  EXPECT_THROW(parse_world(head + "{count: 100000}\n", "s.yaml"), ParseError);
}

TEST(World, GoalWallsAndPosts) {
  Goal g;
  g.pose = Pose2D(9.0, 0.0, 0.0);  // mouth at x = 9, 2 m wide, 0.5 m deep
  const auto walls = goal_walls(g);
  EXPECT_NEAR(walls[0].a.x, 9.5, 1e-12);  // back
  EXPECT_NEAR(walls[0].a.y, 1.0, 1e-12);
  EXPECT_NEAR(walls[0].b.y, -1.0, 1e-12);
  const auto posts = goal_posts(g);
  EXPECT_NEAR(posts[0].y, 1.0, 1e-12);  // left when looking into the goal (+x)
  EXPECT_NEAR(posts[1].y, -1.0, 1e-12);
  EXPECT_NEAR(distance_to_segment({9.25, 0.0}, walls[0]), 0.25, 1e-12);
}

TEST(World, ShippedWorldsLoad) {
  const World msl = load_world(std::string(MRT_WORLDS_DIR) + "/msl_field.yaml");
  ASSERT_EQ(msl.robots.size(), 1u);
  EXPECT_EQ(msl.robots[0].name, "robot1");
  EXPECT_EQ(msl.robots[0].base.name, "ianus3");
  EXPECT_EQ(msl.robots[0].sensors.sonars.size(), 8u);
  EXPECT_EQ(msl.robots[0].sensors.mice.size(), 2u);
  EXPECT_EQ(msl.robots[0].sensors.rate_dgps, 0.0);
  EXPECT_GT(msl.robots[0].sensors.rate_vision, 0.0);
  EXPECT_EQ(msl.goals.size(), 2u);
  EXPECT_EQ(msl.posts.size(), 4u);
  EXPECT_TRUE(msl.ball.enabled);
  ASSERT_EQ(msl.movers.size(), 1u);
  EXPECT_EQ(msl.movers[0].membership_class, "Robot");

  const World museum = load_world(std::string(MRT_WORLDS_DIR) + "/museum.yaml");
  EXPECT_EQ(museum.robots.size(), 1u);
  int people = 0;
  for (const Mover& m : museum.movers) people += m.membership_class == "Person";
  EXPECT_EQ(people, 3);  // FollowMe's guest and two other visitors
  int exhibits = 0;
  for (const Post& p : museum.posts) exhibits += p.membership_class == "Exhibit";
  EXPECT_GE(exhibits, 3);
}
