#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_sim/simulator.h"

using namespace mrt::sim;
using mrt::common::kPi;

namespace {

void run(Simulator& sim, double seconds) {
  const long n = std::lround(seconds / sim.dt());
  for (long i = 0; i < n; ++i) sim.step();
}

Simulator make(const std::string& body, const std::string& robots) {
  return Simulator(parse_world("name: t\nbounds: [-5, -5, 5, 5]\n" + body + "robots:\n" + robots, "t.yaml"),
                   0.001);
}

const char* kOneRobot = "  - {name: r, base: ianus3, pose: [0, 0, 0]}\n";

// Everything one robot's sensors produced during `seconds`, flattened.
std::vector<double> record(Simulator& sim, double seconds) {
  std::vector<double> out;
  const long n = std::lround(seconds / sim.dt());
  for (long i = 0; i < n; ++i) {
    sim.step();
    const RobotState& r = sim.robots()[0];
    if (r.mice_ready)
      out.insert(out.end(), {double(r.mice.left_dx), double(r.mice.left_dy), double(r.mice.right_dx),
                             double(r.mice.right_dy)});
    if (r.sonar_ready) out.insert(out.end(), r.sonar.begin(), r.sonar.end());
    if (r.vision_ready)
      for (const SeenObject& o : r.vision) out.insert(out.end(), {o.distance, o.bearing});
    if (r.dgps_ready) out.insert(out.end(), {r.dgps.x, r.dgps.y});
  }
  return out;
}

World msl(std::uint64_t seed) {
  World w = load_world(std::string(MRT_WORLDS_DIR) + "/msl_field.yaml");
  w.seed = seed;
  w.robots[0].sensors.rate_dgps = 5.0;
  w.robots[0].sensors.mice[0].noise = 0.02;
  w.robots[0].sensors.mice[0].fault_rate = 0.01;
  return w;
}

}  // namespace

TEST(Simulator, SensorsFireOnWholeStepPeriods) {
  Simulator sim = make("", "  - name: r\n    base: ianus3\n    pose: [0, 0, 0]\n"
                           "    sensors: {mice: {rate: 50}, sonar: {rate: 10, count: 2}, encoders: {rate: 300}}\n");
  // 1 / (50 Hz * 1 ms) = 20 steps; 10 Hz -> 100; 300 Hz -> 3.33 -> 3 steps.
  EXPECT_EQ(sim.period(50.0), 20u);
  EXPECT_EQ(sim.period(10.0), 100u);
  EXPECT_EQ(sim.period(300.0), 3u);
  EXPECT_EQ(sim.period(0.0), 0u);
  std::vector<int> mice, sonar;
  for (int k = 1; k <= 200; ++k) {
    sim.step();
    if (sim.robots()[0].mice_ready) mice.push_back(k);
    if (sim.robots()[0].sonar_ready) sonar.push_back(k);
    EXPECT_EQ(sim.robots()[0].encoders_ready, k % 3 == 0);
    EXPECT_FALSE(sim.robots()[0].vision_ready);  // no vision section: off
  }
  ASSERT_EQ(mice.size(), 10u);
  EXPECT_EQ(mice.front(), 20);
  EXPECT_EQ(mice.back(), 200);
  EXPECT_EQ(sonar, (std::vector<int>{100, 200}));
  EXPECT_NEAR(sim.time(), 0.2, 1e-12);
}

TEST(Simulator, MiceSamplesAddUpToTheModel) {
  // Rotation in place at pi/2 rad/s for 1 s, mice at (0, +-0.1) facing
  // forward: left dx = -0.1 * pi/2 * 15748 = -2473.69 -> floor -2474
  // counts read in all, right +2473.69 -> floor +2473; dy = 0.
  Simulator sim = make("", "  - name: r\n    base: ianus3\n    pose: [0, 0, 0]\n"
                           "    sensors: {mice: {counts_per_m: 15748}}\n");
  sim.set_twist(0, {0.0, 0.0, kPi / 2});
  int ldx = 0, ldy = 0, rdx = 0, samples = 0;
  for (int k = 0; k < 1000; ++k) {
    sim.step();
    const RobotState& r = sim.robots()[0];
    if (!r.mice_ready) continue;
    ++samples;
    ldx += r.mice.left_dx;
    ldy += r.mice.left_dy;
    rdx += r.mice.right_dx;
    EXPECT_EQ(r.mice.left_id, "left");
    EXPECT_FALSE(r.mice.left_fault);
  }
  EXPECT_EQ(samples, 50);
  EXPECT_EQ(ldx, -2474);
  EXPECT_EQ(ldy, 0);
  EXPECT_EQ(rdx, 2473);
}

TEST(Simulator, EncoderTicksByHand) {
  // Wheels at -1 and +1 rad/s for 1 s: angles -1 and +1 rad;
  // ticks = floor(angle * 2000 / 2pi) = floor(-+318.31) = -319 and 318.
  Simulator sim = make("", kOneRobot);
  sim.set_wheel_speeds(0, {-1.0, 1.0});
  run(sim, 1.0);
  const RobotState& r = sim.robots()[0];
  EXPECT_NEAR(r.wheel_angle[0], -1.0, 1e-12);
  EXPECT_EQ(r.ticks[0], -319);
  EXPECT_EQ(r.ticks[1], 318);
}

TEST(Simulator, RobotStopsAtWallWhileWheelsSlip) {
  // Wall at x = 1; body radius 0.25: the centre can get to x = 0.75 at most.
  Simulator sim = make("walls:\n  - [1, -5, 1, 5]\n",
                       "  - name: r\n    base: ianus3\n    pose: [0, 0, 0]\n    sensors: {mice: {}}\n");
  sim.set_twist(0, {0.5, 0.0, 0.0});
  run(sim, 3.0);
  const RobotState& r = sim.robots()[0];
  EXPECT_TRUE(r.bumped);
  EXPECT_LE(r.pose.x, 0.75);
  EXPECT_GT(r.pose.x, 0.75 - 0.0005 - 1e-12);  // less than one 0.5 mm step short
  EXPECT_EQ(r.twist.vx, 0.0);
  // The wheels keep turning (10 rad/s for 3 s) while the mice see nothing.
  EXPECT_NEAR(r.wheel_angle[0], 30.0, 1e-9);
  run(sim, 0.1);
  EXPECT_EQ(r.mice.left_dx, 0);
  EXPECT_EQ(r.mice.right_dx, 0);
  // Backing off is allowed.
  sim.set_twist(0, {-0.5, 0.0, 0.0});
  run(sim, 1.0);
  EXPECT_FALSE(r.bumped);
  EXPECT_NEAR(r.pose.x, 0.25, 0.001);
}

TEST(Simulator, RobotAgainstAWallStillTurnsAndDrivesOff) {
  // Touching the wall at x = 1 (centre at 0.75, facing it), forward 0.5
  // m/s while turning 1 rad/s: every step has a +x component while the
  // heading is below 90 degrees, so the robot stays at x = 0.75 but turns
  // on the spot: 1.0 rad after 1 s. Past pi/2 (1.57 s) the arc leads away
  // from the wall: after 2 s it has left it.
  Simulator sim = make("walls:\n  - [1, -5, 1, 5]\n", "  - {name: r, base: ianus3, pose: [0.75, 0, 0]}\n");
  sim.set_twist(0, {0.5, 0.0, 1.0});
  run(sim, 1.0);
  const RobotState& r = sim.robots()[0];
  EXPECT_TRUE(r.bumped);
  EXPECT_EQ(r.pose.x, 0.75);
  EXPECT_NEAR(r.pose.theta, 1.0, 1e-9);
  EXPECT_NEAR(r.twist.omega, 1.0, 1e-9);
  run(sim, 1.0);
  EXPECT_FALSE(r.bumped);
  EXPECT_LT(r.pose.x, 0.75);
}

TEST(Simulator, OverlapCanBeLeftNotDeepened) {
  // The robot starts overlapping a post 0.3 m ahead (0.25 + 0.1 > 0.3).
  Simulator sim = make("posts:\n  - {name: p, x: 0.3, y: 0, radius: 0.1}\n", kOneRobot);
  sim.set_twist(0, {0.2, 0.0, 0.0});
  run(sim, 0.5);
  EXPECT_TRUE(sim.robots()[0].bumped);
  EXPECT_EQ(sim.robots()[0].pose.x, 0.0);
  sim.set_twist(0, {-0.2, 0.0, 0.0});
  run(sim, 0.5);
  EXPECT_FALSE(sim.robots()[0].bumped);
  EXPECT_NEAR(sim.robots()[0].pose.x, -0.1, 1e-9);
}

TEST(Simulator, RobotsBlockEachOtherAndSonarSeesThem) {
  Simulator sim = make("", "  - name: a\n    base: ianus3\n    pose: [0, 0, 0]\n"
                           "    sensors: {sonar: {count: 4, fov: 20, noise: 0}}\n"
                           "  - {name: b, base: triskar, pose: [1.5, 0, 0]}\n");
  run(sim, 0.1);
  // Front sonar of a at (0.25, 0); b's body (r 0.25) starts at x = 1.25: 1.0 m.
  EXPECT_NEAR(sim.robots()[0].sonar[0], 1.0, 1e-12);
  sim.set_twist(0, {0.5, 0.0, 0.0});
  run(sim, 3.0);
  EXPECT_TRUE(sim.robots()[0].bumped);
  EXPECT_LE(sim.robots()[0].pose.x, 1.0);
  EXPECT_GT(sim.robots()[0].pose.x, 0.999);
  EXPECT_EQ(sim.robots()[1].pose.x, 1.5);
}

TEST(Simulator, MoversFollowWaypoints) {
  // Square loop of 8 m at 1 m/s: after 3 s it is 1 m up the second side at
  // (2, 1); after 9 s it has gone round once and 1 m more: (1, 0).
  // The open path stops at its last waypoint (0, 1) after 1 s.
  Simulator sim = make("movers:\n"
                       "  - {name: walker, speed: 1, waypoints: [[0, 0], [2, 0], [2, 2], [0, 2]]}\n"
                       "  - {name: once, speed: 1, loop: false, waypoints: [[0, 0], [0, 1]]}\n",
                       "  - {name: r, base: ianus3, pose: [-4, -4, 0]}\n");
  run(sim, 3.0);
  const Mover& m = sim.world().movers[0];
  EXPECT_NEAR(m.position.x, 2.0, 1e-9);
  EXPECT_NEAR(m.position.y, 1.0, 1e-9);
  EXPECT_NEAR(m.velocity.y, 1.0, 1e-6);
  run(sim, 6.0);
  EXPECT_NEAR(m.position.x, 1.0, 1e-9);
  EXPECT_NEAR(m.position.y, 0.0, 1e-9);
  const Mover& once = sim.world().movers[1];
  EXPECT_TRUE(once.done);
  EXPECT_NEAR(once.position.y, 1.0, 1e-12);
  EXPECT_EQ(once.velocity.y, 0.0);
}

TEST(Simulator, PersonWaitsForRobot) {
  // A person walking along y = 0 towards a robot parked at (2, 0) stops when
  // their circles touch: 2 - 0.25 - 0.25 = 1.5 m.
  Simulator sim = make("movers:\n  - {name: p, speed: 1, waypoints: [[0, 0], [4, 0]]}\n",
                       "  - {name: r, base: ianus3, pose: [2, 0, 0]}\n");
  run(sim, 3.0);
  EXPECT_NEAR(sim.world().movers[0].position.x, 1.5, 0.001);
  EXPECT_LE(sim.world().movers[0].position.x, 1.5);
}

TEST(Simulator, SteeredMoverWalksStraightAndStops) {
  // A scripted walker taken over (FollowMe's visitor): from (0, 0) straight
  // to (0, 2) at 0.5 m/s: 0.5 m after 1 s, there and standing after 4 s
  // (2 m / 0.5 m/s); speed 0 stands at once. Unknown names throw.
  Simulator sim = make("movers:\n  - {name: guest, speed: 1, waypoints: [[0, 0], [3, 0]]}\n",
                       "  - {name: r, base: ianus3, pose: [-4, -4, 0]}\n");
  const std::size_t g = sim.mover_index("guest");
  EXPECT_THROW(sim.mover_index("nobody"), std::out_of_range);
  EXPECT_THROW(sim.steer_mover(7, {0, 0}, 1.0), std::out_of_range);
  sim.steer_mover(g, {0.0, 2.0}, 0.5);
  run(sim, 1.0);
  EXPECT_NEAR(sim.world().movers[g].position.x, 0.0, 1e-12);
  EXPECT_NEAR(sim.world().movers[g].position.y, 0.5, 1e-9);
  run(sim, 4.0);
  EXPECT_NEAR(sim.world().movers[g].position.y, 2.0, 1e-12);
  EXPECT_TRUE(sim.world().movers[g].done);
  sim.steer_mover(g, {3.0, 2.0}, 0.0);
  run(sim, 1.0);
  EXPECT_NEAR(sim.world().movers[g].position.x, 0.0, 1e-12);
}

TEST(Simulator, AddedWallBlocksTheRobot) {
  // A door closing in front of a robot driving +x at 0.5 m/s from the
  // origin: a wall at x = 1 stops its 0.25 m body at x = 0.75 (within one
  // 1 ms step of 0.5 mm).
  Simulator sim = make("", kOneRobot);
  sim.add_wall({{1.0, -5.0}, {1.0, 5.0}});
  sim.set_twist(0, {0.5, 0.0, 0.0});
  run(sim, 3.0);
  EXPECT_NEAR(sim.robots()[0].pose.x, 0.75, 0.001);
  EXPECT_LE(sim.robots()[0].pose.x, 0.75);
  EXPECT_TRUE(sim.robots()[0].bumped);
}

TEST(Simulator, BallRollsToAStop) {
  // v0 = 1 m/s, deceleration 0.4 m/s^2: stops after 2.5 s having rolled
  // v0^2 / (2 a) = 1.25 m (the 1 ms steps lose half a step, 0.5 mm).
  Simulator sim = make("ball: {x: -2, y: 0, vx: 1, friction: 0.4}\n", "  - {name: r, base: ianus3, pose: [0, 3, 0]}\n");
  run(sim, 3.0);
  const Ball& b = sim.world().ball;
  EXPECT_NEAR(b.position.x, -2.0 + 1.25, 1e-3);
  EXPECT_EQ(b.velocity.x, 0.0);
}

TEST(Simulator, BallBouncesWithRestitution) {
  // 2 m/s towards a wall at x = 1, restitution 0.5, no friction: contact
  // when x = 1 - 0.11 = 0.89 at t = 0.445 s, then back at 1 m/s; at t = 1 s
  // x = 0.89 - 0.555 = 0.335.
  Simulator sim = make("walls:\n  - [1, -5, 1, 5]\nball: {vx: 2, friction: 0, restitution: 0.5}\n",
                       "  - {name: r, base: ianus3, pose: [0, 3, 0]}\n");
  run(sim, 1.0);
  const Ball& b = sim.world().ball;
  EXPECT_NEAR(b.velocity.x, -1.0, 1e-12);
  EXPECT_NEAR(b.position.x, 0.335, 3e-3);
}

TEST(Simulator, RobotPushesBall) {
  Simulator sim = make("ball: {x: 1, y: 0, friction: 0.4}\n", kOneRobot);
  sim.set_twist(0, {0.5, 0.0, 0.0});
  run(sim, 2.0);
  const RobotState& r = sim.robots()[0];
  const Ball& b = sim.world().ball;
  EXPECT_FALSE(r.bumped);  // the ball is pushed, not an obstacle
  EXPECT_NEAR(r.pose.x, 1.0, 1e-9);
  EXPECT_GE(b.position.x, r.pose.x + 0.25 + 0.11 - 1e-9);  // in front, not overlapping
  EXPECT_NEAR(b.position.y, 0.0, 1e-9);
  EXPECT_GT(b.velocity.x, 0.0);
}

TEST(Simulator, BallPinnedAgainstWallBlocksRobot) {
  // Wall at x = 1: the ball (r 0.11) can get to x = 0.89 at most, so the
  // robot (r 0.25) pushing it stops with its centre at 0.89 - 0.36 = 0.53.
  Simulator sim = make("walls:\n  - [1, -5, 1, 5]\nball: {x: 0.7, y: 0, friction: 0.4, restitution: 0.6}\n",
                       kOneRobot);
  sim.set_twist(0, {0.5, 0.0, 0.0});
  double max_ball_x = 0.0;
  for (int k = 0; k < 4000; ++k) {
    sim.step();
    max_ball_x = std::max(max_ball_x, sim.world().ball.position.x);
  }
  EXPECT_LE(max_ball_x, 0.89 + 1e-9);  // never into the wall
  EXPECT_TRUE(sim.robots()[0].bumped);
  EXPECT_LE(sim.robots()[0].pose.x, 0.53 + 1e-9);
  EXPECT_GT(sim.robots()[0].pose.x, 0.52);
}

TEST(Simulator, SameSeedSameOutputDifferentSeedDifferent) {
  Simulator a(msl(5)), b(msl(5)), c(msl(6));
  for (Simulator* s : {&a, &b, &c}) s->set_twist(0, {0.4, 0.0, 0.3});
  const auto ra = record(a, 2.0), rb = record(b, 2.0), rc = record(c, 2.0);
  ASSERT_GT(ra.size(), 100u);
  EXPECT_EQ(ra, rb);  // bit for bit
  EXPECT_NE(ra, rc);
  EXPECT_EQ(a.robots()[0].pose.x, b.robots()[0].pose.x);
}

TEST(Simulator, NoiseHasTheConfiguredSpread) {
  // DGPS at 100 Hz with sigma 0.05 m for 100 s: 10000 samples; the sample
  // mean error is within 4 sigma / sqrt(n) = 0.002 m, the std within 5 %.
  Simulator sim = make("", "  - name: r\n    base: ianus3\n    pose: [1, 2, 0]\n"
                           "    sensors: {dgps: {rate: 100, noise: 0.05}}\n");
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (int k = 0; k < 100000; ++k) {
    sim.step();
    const RobotState& r = sim.robots()[0];
    if (!r.dgps_ready) continue;
    const double e = r.dgps.x - 1.0;
    sum += e;
    sum2 += e * e;
    ++n;
  }
  ASSERT_EQ(n, 10000);
  EXPECT_NEAR(sum / n, 0.0, 0.002);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.05, 0.0025);
}

TEST(Simulator, EncoderNoiseHasTheConfiguredSpread) {
  // A Triskar base commanded to rotate in place at 1 rad/s: every wheel turns
  // at omega * d / r. With noise 0.02 each step's measured increment is
  // w dt (1 + 0.02 N(0,1)): over 20000 steps (3 wheels) the sample mean of
  // the relative error is within 4 * 0.02 / sqrt(60000) < 4e-4 of 0 and its
  // std within 3 % of 0.02; the wheel angle itself stays exact.
  Simulator sim = make("", "  - name: r\n    base: triskar\n    pose: [0, 0, 0]\n"
                           "    sensors: {encoders: {rate: 50, noise: 0.02}}\n");
  sim.set_twist(0, Twist2D{0.0, 0.0, 1.0});
  std::vector<double> prev(3, 0.0);
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (int k = 0; k < 20000; ++k) {
    sim.step();
    const RobotState& r = sim.robots()[0];
    for (std::size_t w = 0; w < 3; ++w) {
      const double true_step = r.wheel_speed[w] * 0.001;
      ASSERT_GT(std::abs(true_step), 0.0);
      const double e = (r.encoder_angle[w] - prev[w]) / true_step - 1.0;
      prev[w] = r.encoder_angle[w];
      sum += e;
      sum2 += e * e;
      ++n;
    }
  }
  const RobotState& r = sim.robots()[0];
  EXPECT_NEAR(sum / n, 0.0, 4e-4);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.02, 0.0006);
  for (std::size_t w = 0; w < 3; ++w) {
    EXPECT_NEAR(r.wheel_angle[w], r.wheel_speed[w] * 20.0, 1e-9);
    EXPECT_EQ(r.ticks[w], static_cast<std::int64_t>(std::floor(r.encoder_angle[w] * 2000 / (2 * M_PI))));
  }
}

TEST(Simulator, VisionWithoutNoiseMatchesThePerceptModel) {
  World w = load_world(std::string(MRT_WORLDS_DIR) + "/msl_field.yaml");
  w.robots[0].sensors.vision_distance_noise = 0.0;
  w.robots[0].sensors.vision_bearing_noise = 0.0;
  Simulator sim(w);
  run(sim, 0.1);  // the 10 Hz camera fires at step 100
  const RobotState& r = sim.robots()[0];
  ASSERT_TRUE(r.vision_ready);
  const auto expect = vision_percepts(sim.world(), {}, r.pose, r.config.sensors);
  ASSERT_EQ(r.vision.size(), expect.size());
  for (std::size_t i = 0; i < expect.size(); ++i) {
    EXPECT_EQ(r.vision[i].name, expect[i].name);
    EXPECT_EQ(r.vision[i].distance, expect[i].distance);
  }
  // The ball at the centre is seen 2 m straight ahead of robot1 at (-2, 0, 0).
  bool ball = false;
  for (const SeenObject& o : r.vision)
    if (o.membership_class == "Ball") {
      ball = true;
      EXPECT_NEAR(o.distance, 2.0, 1e-12);
      EXPECT_NEAR(o.bearing, 0.0, 1e-12);
    }
  EXPECT_TRUE(ball);
}
