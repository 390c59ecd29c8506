#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"
#include "mrt_sim/simulator.h"

using namespace mrt::sim;
using mrt::common::deg_to_rad;
using mrt::common::kPi;

namespace {

// An empty 200 x 200 m world holding one robot of `base` at the origin.
Simulator open_field(const std::string& base) {
  return Simulator(parse_world("name: open\nbounds: [-100, -100, 100, 100]\n"
                               "robots:\n  - {name: r, base: " + base + ", pose: [0, 0, 0]}\n",
                               "open.yaml"),
                   0.001);
}

void run(Simulator& sim, double seconds) {
  const long n = std::lround(seconds / sim.dt());
  for (long i = 0; i < n; ++i) sim.step();
}

}  // namespace

TEST(Kinematics, DifferentialWheelSpeedsByHand) {
  // ianus3: r = 0.05, track = 0.38. v = 0.5, omega = 0.25:
  // left = (0.5 - 0.25 * 0.19) / 0.05 = 9.05, right = (0.5 + 0.0475) / 0.05 = 10.95 rad/s.
  const BaseConfig g = base_preset("ianus3");
  const auto w = twist_to_wheels(g, {0.5, 0.0, 0.25});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NEAR(w[0], 9.05, 1e-12);
  EXPECT_NEAR(w[1], 10.95, 1e-12);
}

TEST(Kinematics, DifferentialArcMatchesClosedForm) {
  // Wheels 9.05 / 10.95 rad/s give v = 0.5 m/s, omega = 0.25 rad/s; after
  // t = 4 s: x = (v/w) sin(wt) = 2 sin(1) = 1.682941969615793,
  // y = (v/w)(1 - cos(wt)) = 2 (1 - cos 1) = 0.919395388264,  theta = 1 rad.
  Simulator sim = open_field("ianus3");
  sim.set_wheel_speeds(0, {9.05, 10.95});
  run(sim, 4.0);
  const Pose2D& p = sim.robots()[0].pose;
  EXPECT_NEAR(p.x, 2.0 * std::sin(1.0), 1e-9);
  EXPECT_NEAR(p.y, 2.0 * (1.0 - std::cos(1.0)), 1e-9);
  EXPECT_NEAR(p.theta, 1.0, 1e-9);
  EXPECT_FALSE(sim.robots()[0].bumped);
}

TEST(Kinematics, TriskarSidewaysTranslation) {
  // Wheels at 90, 210, 330 deg, r = 0.04: vy = 0.3 gives cos(a) * 0.3 / 0.04
  // = 0, -6.4951905, +6.4951905 rad/s; 2 s later the robot is at (0, 0.6, 0).
  Simulator sim = open_field("triskar");
  sim.set_twist(0, {0.0, 0.3, 0.0});
  const auto& w = sim.robots()[0].wheel_setpoint;
  EXPECT_NEAR(w[0], 0.0, 1e-12);
  EXPECT_NEAR(w[1], -7.5 * std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(w[2], 7.5 * std::sqrt(3.0) / 2.0, 1e-12);
  run(sim, 2.0);
  const Pose2D& p = sim.robots()[0].pose;
  EXPECT_NEAR(p.x, 0.0, 1e-9);
  EXPECT_NEAR(p.y, 0.6, 1e-9);
  EXPECT_NEAR(p.theta, 0.0, 1e-9);
}

TEST(Kinematics, Omni4RotationInPlace) {
  // omega = 1 rad/s: every wheel turns at L * omega / r = 0.2 / 0.04 = 5 rad/s;
  // after 1.5 s theta = 1.5 rad and the centre has not moved.
  Simulator sim = open_field("omni4");
  sim.set_twist(0, {0.0, 0.0, 1.0});
  for (double w : sim.robots()[0].wheel_setpoint) EXPECT_NEAR(w, 5.0, 1e-12);
  run(sim, 1.5);
  const Pose2D& p = sim.robots()[0].pose;
  EXPECT_NEAR(p.x, 0.0, 1e-9);
  EXPECT_NEAR(p.y, 0.0, 1e-9);
  EXPECT_NEAR(p.theta, 1.5, 1e-9);
}

TEST(Kinematics, OmniArcWithSidewaysComponentMatchesClosedForm) {
  // Constant twist (vx, vy, w) = (0.4, 0.2, 0.5) for T = 2 s, so wT = 1:
  // p = [sin(wT)/w vx - (1 - cos wT)/w vy, (1 - cos wT)/w vx + sin(wT)/w vy]
  //   = [2 sin1 * 0.4 - 2 (1 - cos1) * 0.2, 2 (1 - cos1) * 0.4 + 2 sin1 * 0.2].
  const double s = 2.0 * std::sin(1.0), c = 2.0 * (1.0 - std::cos(1.0));
  for (const char* base : {"triskar", "omni4"}) {
    Simulator sim = open_field(base);
    sim.set_twist(0, {0.4, 0.2, 0.5});
    run(sim, 2.0);
    const Pose2D& p = sim.robots()[0].pose;
    EXPECT_NEAR(p.x, s * 0.4 - c * 0.2, 1e-9) << base;
    EXPECT_NEAR(p.y, c * 0.4 + s * 0.2, 1e-9) << base;
    EXPECT_NEAR(p.theta, 1.0, 1e-9) << base;
  }
}

TEST(Kinematics, RoundTripTwistWheelsTwist) {
  const Twist2D t{0.3, -0.2, 0.7};
  for (const char* name : {"ianus3", "p3at", "triskar", "omni4"}) {
    const BaseConfig g = base_preset(name);
    const Twist2D back = wheels_to_twist(g, twist_to_wheels(g, t));
    EXPECT_NEAR(back.vx, t.vx, 1e-12) << name;
    // A differential base cannot move sideways: vy is dropped.
    EXPECT_NEAR(back.vy, g.type == BaseType::kDifferential ? 0.0 : t.vy, 1e-12) << name;
    EXPECT_NEAR(back.omega, t.omega, 1e-12) << name;
  }
}

TEST(Kinematics, Omni4InconsistentWheelsLeastSquares) {
  // Rows (-sin a, cos a, L) for a = 45, 135, 225, 315 deg give
  // J^T J = diag(2, 2, 4 L^2). Only wheel 1 turning at 1 rad/s: surface
  // speeds v = (0.04, 0, 0, 0), J^T v = 0.04 (-1/sqrt2, 1/sqrt2, L), so
  // vx = -0.02/sqrt2, vy = +0.02/sqrt2, omega = 0.04 / (4 * 0.2) = 0.05.
  const Twist2D t = wheels_to_twist(base_preset("omni4"), {1.0, 0.0, 0.0, 0.0});
  EXPECT_NEAR(t.vx, -0.02 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(t.vy, 0.02 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(t.omega, 0.05, 1e-12);
}

TEST(Kinematics, SaturationPreservesDirection) {
  // v = 2, omega = 1 on ianus3: wheels (2 -+ 0.19) / 0.05 = 36.2, 43.8 rad/s;
  // max 24, so everything is scaled by 24 / 43.8.
  const BaseConfig g = base_preset("ianus3");
  auto w = twist_to_wheels(g, {2.0, 0.0, 1.0});
  const double k = saturate_wheels(g, w);
  EXPECT_NEAR(k, 24.0 / 43.8, 1e-12);
  EXPECT_NEAR(w[0], 36.2 * 24.0 / 43.8, 1e-12);
  EXPECT_NEAR(w[1], 24.0, 1e-12);
  const Twist2D t = wheels_to_twist(g, w);
  EXPECT_NEAR(t.omega / t.vx, 0.5, 1e-12);  // same curvature as commanded

  auto slow = twist_to_wheels(g, {0.1, 0.0, 0.0});
  EXPECT_EQ(saturate_wheels(g, slow), 1.0);

  // In the simulator the saturated robot reports it.
  Simulator sim = open_field("triskar");
  sim.set_twist(0, {3.0, 0.0, 0.0});
  sim.step();
  EXPECT_TRUE(sim.robots()[0].saturated);
  EXPECT_NEAR(sim.robots()[0].twist.vy, 0.0, 1e-12);
}

TEST(Kinematics, BadInputsThrow) {
  EXPECT_THROW(base_preset("roomba"), std::invalid_argument);
  EXPECT_THROW(wheels_to_twist(base_preset("triskar"), {1.0, 2.0}), std::invalid_argument);
  Simulator sim = open_field("ianus3");
  EXPECT_THROW(sim.set_wheel_speeds(0, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(sim.robot_index("nobody"), std::out_of_range);
}

// The simulator's base is the stack's one geometry type plus what the
// simulator adds: the same preset gives the same geometry as mrt_common's
// (and so as mrt_airboard's), and the world file's omni_radius is its
// wheel_distance. omni4 (wheels at 45, 135, 225, 315 deg, r 0.04 m), vy
// 1 m/s: w_i = cos(a_i) / 0.04 = +-17.6777 rad/s (cos 45 deg = 0.707107).
TEST(Kinematics, BaseConfigExtendsTheCommonBaseGeometry) {
  const BaseConfig b = base_preset("omni4");
  const mrt::common::BaseGeometry& g = b;
  const mrt::common::BasePreset& want = mrt::common::base_preset("omni4");
  EXPECT_EQ(g.type, want.geometry.type);
  EXPECT_EQ(g.wheel_distance, want.geometry.wheel_distance);
  EXPECT_EQ(g.wheel_angles, want.geometry.wheel_angles);
  EXPECT_EQ(b.max_wheel_speed, want.max_wheel_speed);
  EXPECT_EQ(b.body_radius, want.body_radius);
  const auto w = twist_to_wheels(b, {0.0, 1.0, 0.0});
  ASSERT_EQ(w.size(), 4u);
  EXPECT_NEAR(w[0], 17.677669529663689, 1e-9);
  EXPECT_NEAR(w[1], -17.677669529663689, 1e-9);
  EXPECT_NEAR(w[2], -17.677669529663689, 1e-9);
  EXPECT_NEAR(w[3], 17.677669529663689, 1e-9);
}

// Joint states for the robot description: the wheel joint names follow the
// WheelState order, and an encoder count is an angle. 2000 ticks per
// revolution: 500 ticks = a quarter turn = pi/2 = 1.570796 rad; -3000 ticks
// = -1.5 turns = -9.424778 rad.
TEST(Kinematics, WheelJointNamesAndTickAngles) {
  EXPECT_EQ(mrt::common::wheel_joint_names(base_preset("p3at")),
            (std::vector<std::string>{"left_wheel_joint", "right_wheel_joint"}));
  EXPECT_EQ(mrt::common::wheel_joint_names(base_preset("triskar")),
            (std::vector<std::string>{"wheel_0_joint", "wheel_1_joint", "wheel_2_joint"}));
  EXPECT_EQ(mrt::common::wheel_joint_names(base_preset("omni4")).size(), 4u);
  EXPECT_NEAR(mrt::common::encoder_angle(500, 2000), 1.5707963267948966, 1e-12);
  EXPECT_NEAR(mrt::common::encoder_angle(-3000, 2000), -9.42477796076938, 1e-12);
  EXPECT_EQ(mrt::common::encoder_angle(0, 2000), 0.0);
}
