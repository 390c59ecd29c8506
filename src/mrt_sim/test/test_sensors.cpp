#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mrt_common/angle.h"
#include "mrt_sim/sensors.h"

using namespace mrt::sim;
using mrt::common::deg_to_rad;
using mrt::common::kPi;

namespace {

MouseConfig mouse(double x, double y, double theta_deg, double counts_per_m) {
  MouseConfig c;
  c.id = "m";
  c.mount = Pose2D(x, y, deg_to_rad(theta_deg));
  c.counts_per_m = counts_per_m;
  return c;
}

// Runs `steps` steps of twist `t` and returns the counts read at the end.
std::pair<int, int> drive(MouseModel& m, const Twist2D& t, double dt, int steps) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < steps; ++i) m.step(t, dt, rng);
  int dx = 0, dy = 0;
  m.read(dx, dy);
  return {dx, dy};
}

SonarConfig sonar(double theta_deg, double fov_deg) {
  SonarConfig s;
  s.mount = Pose2D(0.0, 0.0, deg_to_rad(theta_deg));
  s.fov = deg_to_rad(fov_deg);
  s.min_range = 0.1;
  s.max_range = 5.0;
  return s;
}

World wall_at_x2() {
  World w;
  w.walls.push_back({{2.0, -10.0}, {2.0, 10.0}});
  return w;
}

Post post(const std::string& name, double x, double y, double r) {
  Post p;
  p.name = name;
  p.membership_class = "Landmark";
  p.color = "yellow";
  p.center = {x, y};
  p.radius = r;
  return p;
}

const SeenObject* find(const std::vector<SeenObject>& v, const std::string& name) {
  auto it = std::find_if(v.begin(), v.end(), [&](const SeenObject& o) { return o.name == name; });
  return it == v.end() ? nullptr : &*it;
}

}  // namespace

TEST(Mouse, DisplacementOfRotationInPlace) {
  // Mouse at (0, 0.1) facing forward, omega = pi/2 for 1 s: its point moves
  // with body velocity (-omega * 0.1, 0) = (-0.15708, 0) m/s.
  const Point2D d = mouse_displacement(Pose2D(0.0, 0.1, 0.0), {0.0, 0.0, kPi / 2}, 1.0);
  EXPECT_NEAR(d.x, -0.1 * kPi / 2, 1e-15);
  EXPECT_NEAR(d.y, 0.0, 1e-15);
}

TEST(Mouse, CountsOfRotationInPlace) {
  // 1000 steps of 1 ms at pi/2 rad/s: dx = -0.1 * pi/2 m * 15748 counts/m
  // = -2473.69 counts: floor, -2474 whole counts read, +0.31 kept; dy = 0.
  MouseModel m(mouse(0.0, 0.1, 0.0, 15748.0));
  const auto c = drive(m, {0.0, 0.0, kPi / 2}, 0.001, 1000);
  EXPECT_EQ(c.first, -2474);
  EXPECT_EQ(c.second, 0);
}

TEST(Mouse, CountsOfStraightLineWithRotatedMouse) {
  // Mouse at (0, -0.1) turned +90 deg; the robot goes 0.5 m/s straight for
  // 2 s: 1 m along the body x axis, which is the mouse's -y axis:
  // dx = 0, dy = -1 m * 1000 counts/m = -1000.
  MouseModel m(mouse(0.0, -0.1, 90.0, 1000.0));
  const auto c = drive(m, {0.5, 0.0, 0.0}, 0.001, 2000);
  EXPECT_EQ(c.first, 0);
  EXPECT_EQ(c.second, -1000);
}

TEST(Mouse, CountsOfArc) {
  // v = 0.5, omega = 0.25, mouse at (0.1, 0.1) turned 30 deg, 4 s.
  // Body velocity of the point: (0.5 - 0.25 * 0.1, 0.25 * 0.1) = (0.475, 0.025).
  // In the mouse frame: x = cos30 * 0.475 + sin30 * 0.025 = 0.4238620668,
  //                     y = -sin30 * 0.475 + cos30 * 0.025 = -0.2158493649 m/s.
  // Times 4 s times 1000 counts/m: floor, 1695.448 -> 1695, -863.397 -> -864.
  MouseModel m(mouse(0.1, 0.1, 30.0, 1000.0));
  const auto c = drive(m, {0.5, 0.0, 0.25}, 0.001, 4000);
  EXPECT_EQ(c.first, 1695);
  EXPECT_EQ(c.second, -864);
}

TEST(Mouse, RemainderIsCarried) {
  // 0.3 m per step at 1 count/m: 0.3 counts per step. After 3 steps nothing
  // whole (0.9), the 4th step completes one count; 100 steps give 30 in all.
  MouseModel m(mouse(0.0, 0.0, 0.0, 1.0));
  std::mt19937_64 rng(1);
  int dx = 0, dy = 0, total = 0;
  for (int i = 0; i < 3; ++i) m.step({0.3, 0.0, 0.0}, 1.0, rng);
  m.read(dx, dy);
  EXPECT_EQ(dx, 0);
  m.step({0.3, 0.0, 0.0}, 1.0, rng);
  m.read(dx, dy);
  EXPECT_EQ(dx, 1);
  total = 1;
  for (int i = 4; i < 100; ++i) {
    m.step({0.3, 0.0, 0.0}, 1.0, rng);
    m.read(dx, dy);
    total += dx;
  }
  EXPECT_EQ(total, 30);
  EXPECT_EQ(dy, 0);
}

TEST(Mouse, EveryReportWithinOneCountWhenTheMotionReverses) {
  // 1 count/m, read after every step. -0.7: total -0.7, floor -1, report
  // -1 (off by 0.3). +1.4: total 0.7, floor 0, report +1 (off by 0.4).
  // -1.4: total -0.7, report -1 (off by 0.4). Truncation towards zero would
  // report 0, 0, 0: off by 1.4 counts on the last two, beyond the one count
  // the error detector of mrt_mice allows per axis and sample.
  MouseModel m(mouse(0.0, 0.0, 0.0, 1.0));
  std::mt19937_64 rng(1);
  int dx = 0, dy = 0;
  m.step({-0.7, 0.0, 0.0}, 1.0, rng);  // total -0.7
  m.read(dx, dy);
  EXPECT_EQ(dx, -1);
  m.step({1.4, 0.0, 0.0}, 1.0, rng);  // total 0.7: floor 0, report +1
  m.read(dx, dy);
  EXPECT_EQ(dx, 1);
  m.step({-1.4, 0.0, 0.0}, 1.0, rng);  // total -0.7: floor -1, report -1
  m.read(dx, dy);
  EXPECT_EQ(dx, -1);
  // Random back-and-forth: each report within one count of the true motion.
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  double total = -0.7;
  long read_total = -1;
  for (int i = 0; i < 10000; ++i) {
    const double v = u(rng);
    m.step({v, 0.0, 0.0}, 1.0, rng);
    total += v;
    m.read(dx, dy);
    read_total += dx;
    ASSERT_LT(std::fabs(dx - v), 1.0 + 1e-6) << "step " << i;
    ASSERT_EQ(read_total, static_cast<long>(std::floor(total + 1e-9))) << "step " << i;
  }
}

TEST(Mouse, FaultShortensLengthKeepsDirection) {
  // Mouse turned 30 deg, robot going straight 1 m: exact reading
  // (cos30, -sin30) * 1e6 counts = (866025.4, -500000). With a fault every
  // step losing up to half of it, the length is between 0.5 and 1 of 1e6 and
  // the direction is still -30 deg.
  MouseConfig c = mouse(0.0, 0.0, 30.0, 1e6);
  c.fault_rate = 1.0;
  c.fault_max_fraction = 0.5;
  MouseModel m(c);
  std::mt19937_64 rng(3);
  bool all_faults = true;
  for (int i = 0; i < 1000; ++i) all_faults = m.step({1.0, 0.0, 0.0}, 0.001, rng) && all_faults;
  EXPECT_TRUE(all_faults);
  int dx = 0, dy = 0;
  m.read(dx, dy);
  const double len = std::hypot(dx, dy);
  EXPECT_GT(len, 0.5e6);
  EXPECT_LT(len, 1e6);
  EXPECT_NEAR(std::atan2(dy, dx), deg_to_rad(-30.0), 1e-5);
  // Uniform losses average a quarter of the length: about 0.75e6 counts.
  EXPECT_NEAR(len, 0.75e6, 0.03e6);
}

TEST(Sonar, WallAtKnownAngleNarrowBeam) {
  // Wall x = 2, beam at 30 deg with no cone: 2 / cos 30 = 2.309401077.
  const World w = wall_at_x2();
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(30.0, 0.0)), 2.0 / std::cos(deg_to_rad(30.0)), 1e-12);
  const auto hit = ray_cast(w, {}, {0.0, 0.0}, deg_to_rad(30.0), 5.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(*hit, 2.309401076758503, 1e-12);
  // From a robot at (1, 0) facing +y with the sonar on its right side (-90
  // deg): the beam points along +x and meets the wall after 1 m.
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(1.0, 0.0, kPi / 2), sonar(-90.0, 0.0)), 1.0, 1e-12);
}

TEST(Sonar, ConeReturnsNearestEcho) {
  const World w = wall_at_x2();
  // Cone [-5, 45] deg contains the perpendicular (0 deg): 2.0 m.
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(20.0, 50.0)), 2.0, 1e-12);
  // Cone [20, 60] deg: the nearest echo is along its 20 deg edge, 2 / cos 20 = 2.128355545.
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(40.0, 40.0)), 2.128355544951824, 1e-12);
  // Pointing away from the wall: nothing within 5 m.
  EXPECT_EQ(sonar_range(w, {}, Pose2D(), sonar(180.0, 30.0)), 5.0);
}

TEST(Sonar, Post) {
  World w;
  w.posts.push_back(post("p", 3.0, 0.0, 0.2));
  // Straight at it: 3 - 0.2 = 2.8 m, with or without a cone around it.
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(0.0, 0.0)), 2.8, 1e-12);
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(10.0, 30.0)), 2.8, 1e-12);
  // Cone [20, 40] deg: the post's edge is at atan(0.2 / 3) = 3.8 deg, outside.
  EXPECT_EQ(sonar_range(w, {}, Pose2D(), sonar(30.0, 20.0)), 5.0);
  // Cone [3, 23] deg: centre outside, but the 3 deg edge ray passes
  // 3 sin3 = 0.157 m from the centre, inside the post. Distance along it:
  // 3 cos3 - sqrt(0.04 - (3 sin3)^2) = 2.995889 - 0.123889 = 2.871999 m.
  const double b = 3.0 * std::cos(deg_to_rad(3.0));
  const double h = std::sqrt(0.04 - std::pow(3.0 * std::sin(deg_to_rad(3.0)), 2));
  EXPECT_NEAR(b - h, 2.871999, 1e-6);
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(13.0, 20.0)), b - h, 1e-12);
}

TEST(Sonar, ConeDoesNotMissThinPostBetweenRays) {
  // A 2 cm rod at 3 m, 2 deg off the axis of a 24 deg cone. Seven rays 4 deg
  // apart (0, +-4, ...) would pass 3 sin 2 = 0.105 m from it and miss; the
  // nearest echo is 3 - 0.02 = 2.98 m.
  World w;
  w.posts.push_back(post("rod", 3.0 * std::cos(deg_to_rad(2.0)), 3.0 * std::sin(deg_to_rad(2.0)), 0.02));
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(0.0, 24.0)), 2.98, 1e-12);
  for (int k = -3; k <= 3; ++k) EXPECT_FALSE(ray_cast(w, {}, {0.0, 0.0}, deg_to_rad(4.0 * k), 5.0).has_value());
}

TEST(Sonar, ClampsAndSeesOtherRobots) {
  World w;
  // Nothing there: max_range.
  EXPECT_EQ(sonar_range(w, {}, Pose2D(), sonar(0.0, 20.0)), 5.0);
  // Another robot of radius 0.25 at (1, 0): echo at 0.75 m.
  EXPECT_NEAR(sonar_range(w, {{{1.0, 0.0}, 0.25}}, Pose2D(), sonar(0.0, 20.0)), 0.75, 1e-12);
  // A wall 5 cm away reads min_range (0.1 m).
  w.walls.push_back({{0.05, -1.0}, {0.05, 1.0}});
  EXPECT_EQ(sonar_range(w, {}, Pose2D(), sonar(0.0, 20.0)), 0.1);
}

TEST(Sonar, SeesBallAndMovers) {
  World w;
  w.ball.enabled = true;
  w.ball.position = {2.0, 0.0};
  w.ball.radius = 0.11;
  Mover m;
  m.position = {0.0, 1.5};
  m.radius = 0.3;
  w.movers.push_back(m);
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(0.0, 0.0)), 1.89, 1e-12);
  EXPECT_NEAR(sonar_range(w, {}, Pose2D(), sonar(90.0, 0.0)), 1.2, 1e-12);
}

TEST(Vision, BearingOfLandmarkByHand) {
  // Robot at (1, 1) facing +y; landmark at (2, 2): distance sqrt 2, world
  // direction 45 deg, bearing 45 - 90 = -45 deg.
  World w;
  w.posts.push_back(post("lm", 2.0, 2.0, 0.1));
  SensorsConfig cfg;
  const auto seen = vision_percepts(w, {}, Pose2D(1.0, 1.0, kPi / 2), cfg);
  const SeenObject* o = find(seen, "lm");
  ASSERT_NE(o, nullptr);
  EXPECT_NEAR(o->distance, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(o->bearing, -kPi / 4, 1e-12);
  EXPECT_EQ(o->membership_class, "Landmark");
  EXPECT_EQ(o->color, "yellow");
}

TEST(Vision, OcclusionByPostAndWall) {
  World w;
  w.posts.push_back(post("far", 4.0, 0.0, 0.1));
  w.posts.push_back(post("near", 2.0, 0.05, 0.2));  // the sight line passes 5 cm from its centre
  SensorsConfig cfg;
  auto seen = vision_percepts(w, {}, Pose2D(), cfg);
  EXPECT_EQ(find(seen, "far"), nullptr);
  EXPECT_NE(find(seen, "near"), nullptr);
  w.posts[1].center = {2.0, 0.25};  // 25 cm off the line: no longer in the way
  seen = vision_percepts(w, {}, Pose2D(), cfg);
  EXPECT_NE(find(seen, "far"), nullptr);
  // A wall between hides it again.
  w.walls.push_back({{3.0, -1.0}, {3.0, 1.0}});
  seen = vision_percepts(w, {}, Pose2D(), cfg);
  EXPECT_EQ(find(seen, "far"), nullptr);
}

TEST(Vision, RangeLimit) {
  World w;
  w.posts.push_back(post("in", 5.9, 0.0, 0.1));
  w.posts.push_back(post("out", 0.0, -6.1, 0.1));
  SensorsConfig cfg;
  cfg.vision_range = 6.0;
  const auto seen = vision_percepts(w, {}, Pose2D(), cfg);
  EXPECT_NE(find(seen, "in"), nullptr);
  EXPECT_EQ(find(seen, "out"), nullptr);
}

TEST(Vision, GoalsBallRobotsAndLinePoints) {
  World w;
  Goal g;
  g.name = "yellow_goal";
  g.color = "yellow";
  g.pose = Pose2D(3.0, 0.0, 0.0);  // mouth at x = 3, opening towards -x
  w.goals.push_back(g);
  w.ball.enabled = true;
  w.ball.position = {1.0, -1.0};
  w.field_lines.push_back({{-1.0, 1.0}, {1.0, 1.0}});  // 2 m: 8 points at 0.25 m
  SensorsConfig cfg;
  const auto seen = vision_percepts(w, {{"mate", {-2.0, 0.0}, 0.25, "cyan"}}, Pose2D(), cfg);
  const SeenObject* goal = find(seen, "yellow_goal");
  ASSERT_NE(goal, nullptr);
  EXPECT_EQ(goal->membership_class, "Goal");
  EXPECT_NEAR(goal->distance, 3.0, 1e-12);
  EXPECT_NEAR(goal->bearing, 0.0, 1e-12);
  // Posts at (3, +-1): distance sqrt 10, bearing +-atan(1/3).
  const SeenObject* left = find(seen, "yellow_goal_left");
  ASSERT_NE(left, nullptr);
  EXPECT_EQ(left->membership_class, "GoalPost");
  EXPECT_NEAR(left->distance, std::sqrt(10.0), 1e-12);
  EXPECT_NEAR(left->bearing, std::atan(1.0 / 3.0), 1e-12);
  const SeenObject* ball = find(seen, "ball");
  ASSERT_NE(ball, nullptr);
  EXPECT_NEAR(ball->bearing, -kPi / 4, 1e-12);
  const SeenObject* mate = find(seen, "mate");
  ASSERT_NE(mate, nullptr);
  EXPECT_EQ(mate->membership_class, "Robot");
  EXPECT_EQ(mate->color, "cyan");
  EXPECT_NEAR(mate->bearing, kPi, 1e-12);
  int lines = 0;
  for (const SeenObject& o : seen) {
    if (o.membership_class != "Line") continue;
    ++lines;
    // Points at x = -0.875, -0.625, ... 0.875 on y = 1: nearest is 1.0077 m.
    EXPECT_GE(o.distance, std::hypot(0.125, 1.0) - 1e-12);
  }
  EXPECT_EQ(lines, 8);
}

TEST(Vision, OnlyLinePointsInRange) {
  // A 40 m line along y = 1 cut into 160 pieces of 0.25 m: middles at
  // x = -19.875, -19.625, ..., 19.875. In range (6 m) where |x| <= sqrt(35)
  // = 5.916: x = -5.875 ... 5.875, that is 48 points.
  World w;
  w.field_lines.push_back({{-20.0, 1.0}, {20.0, 1.0}});
  SensorsConfig cfg;
  const auto seen = vision_percepts(w, {}, Pose2D(), cfg);
  ASSERT_EQ(seen.size(), 48u);
  double min_x = 1e9, max_x = -1e9;
  for (const SeenObject& o : seen) {
    const double x = o.distance * std::cos(o.bearing);
    min_x = std::min(min_x, x);
    max_x = std::max(max_x, x);
  }
  EXPECT_NEAR(min_x, -5.875, 1e-9);
  EXPECT_NEAR(max_x, 5.875, 1e-9);
}
