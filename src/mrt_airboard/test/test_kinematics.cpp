#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mrt_airboard/kinematics.h"

using namespace mrt::airboard;

namespace {
constexpr double kS = 0.70710678118654752440;  // sin 45 deg
constexpr double kC30 = 0.86602540378443864676; // cos 30 deg

void expect_wheels(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "wheel " << i;
}
}  // namespace

// Hand-computed: w = (vx -+ omega * track / 2) / r with r 0.05, track 0.38.
TEST(Differential, HandComputedWheelSpeeds) {
  auto k = make_kinematics(base_preset("ianus3"));
  expect_wheels(k->inverse({1.0, 0.0, 0.0}), {20.0, 20.0});
  expect_wheels(k->inverse({0.0, 1.0, 0.0}), {0.0, 0.0});  // cannot move sideways
  expect_wheels(k->inverse({0.0, 0.0, 1.0}), {-3.8, 3.8});
}

// Triskar, wheels at 90/210/330 deg, L 0.2, r 0.04: w_i = (-sin a vx + cos a vy + L omega) / r.
TEST(Triskar, HandComputedWheelSpeeds) {
  auto k = make_kinematics(base_preset("triskar"));
  expect_wheels(k->inverse({1.0, 0.0, 0.0}), {-25.0, 12.5, 12.5});
  expect_wheels(k->inverse({0.0, 1.0, 0.0}), {0.0, -kC30 / 0.04, kC30 / 0.04});
  expect_wheels(k->inverse({0.0, 0.0, 1.0}), {5.0, 5.0, 5.0});
}

TEST(Omni4, HandComputedWheelSpeeds) {
  auto k = make_kinematics(base_preset("omni4"));
  const double w = kS / 0.04;
  expect_wheels(k->inverse({1.0, 0.0, 0.0}), {-w, -w, w, w});
  expect_wheels(k->inverse({0.0, 1.0, 0.0}), {w, -w, -w, w});
  expect_wheels(k->inverse({0.0, 0.0, 1.0}), {5.0, 5.0, 5.0, 5.0});
}

TEST(Kinematics, InverseThenForwardIsIdentity) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (const char* name : {"ianus3", "triskar", "omni4"}) {
    auto k = make_kinematics(base_preset(name));
    for (int i = 0; i < 1000; ++i) {
      Twist2D t{u(rng), k->holonomic() ? u(rng) : 0.0, u(rng)};
      const Twist2D b = k->forward(k->inverse(t));
      EXPECT_NEAR(b.vx, t.vx, 1e-12) << name;
      EXPECT_NEAR(b.vy, t.vy, 1e-12) << name;
      EXPECT_NEAR(b.omega, t.omega, 1e-12) << name;
    }
  }
}

TEST(Kinematics, ForwardRejectsWrongSize) {
  auto k = make_kinematics(base_preset("triskar"));
  EXPECT_THROW(k->forward({1.0, 2.0}), std::invalid_argument);
  auto d = make_kinematics(base_preset("ianus3"));
  EXPECT_THROW(d->forward({1.0, 2.0, 3.0}), std::invalid_argument);
}

TEST(Kinematics, DegenerateOmniIsRejected) {
  BaseParams p = base_preset("triskar");
  p.wheel_angles = {0.0, 0.0, 0.0};
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = base_preset("ianus3");
  p.track = -1.0;
  try {
    p.validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'track'"), std::string::npos);
  }
  EXPECT_THROW(base_preset("nope"), std::invalid_argument);
  EXPECT_THROW(parse_base_type("tank"), std::invalid_argument);
}

TEST(Saturation, KeepsDirectionOfMotion) {
  for (const char* name : {"ianus3", "triskar", "omni4"}) {
    BaseParams p = base_preset(name);
    auto k = make_kinematics(p);
    const Twist2D req{3.0, k->holonomic() ? 2.0 : 0.0, 4.0};
    std::vector<double> w = k->inverse(req);
    const double s = saturate_preserving_direction(w, p.max_wheel_speed);
    EXPECT_LT(s, 1.0) << name;
    double peak = 0.0;
    for (double v : w) peak = std::max(peak, std::fabs(v));
    EXPECT_NEAR(peak, p.max_wheel_speed, 1e-12) << name;
    const Twist2D got = k->forward(w);
    EXPECT_NEAR(got.vx, s * req.vx, 1e-12) << name;
    EXPECT_NEAR(got.vy, s * req.vy, 1e-12) << name;
    EXPECT_NEAR(got.omega, s * req.omega, 1e-12) << name;
  }
  std::vector<double> w{1.0, -2.0};
  EXPECT_EQ(saturate_preserving_direction(w, 5.0), 1.0);
  EXPECT_EQ(w[1], -2.0);
}

TEST(VelocityLimiter, DeadbandSaturationAndAcceleration) {
  BaseParams p = base_preset("triskar");
  p.deadband_linear = 0.01;
  p.deadband_angular = 0.02;
  p.max_wheel_accel = 100.0;
  VelocityLimiter lim(p);
  auto r = lim.update({0.005, 0.0, 0.01}, 0.02);
  for (double w : r.wheels) EXPECT_EQ(w, 0.0);
  // From rest, a step to 1 m/s forward is limited to 100 * 0.02 = 2 rad/s on
  // the fastest wheel, in the direction of the request.
  r = lim.update({1.0, 0.0, 0.0}, 0.02);
  EXPECT_TRUE(r.accel_limited);
  expect_wheels(r.wheels, {-2.0, 1.0, 1.0});
  for (int i = 0; i < 20; ++i) r = lim.update({1.0, 0.0, 0.0}, 0.02);
  EXPECT_FALSE(r.accel_limited);
  expect_wheels(r.wheels, {-25.0, 12.5, 12.5});
  // Too fast: the whole vector is scaled to the 40 rad/s limit.
  p.max_wheel_accel = 0.0;
  VelocityLimiter fast(p);
  r = fast.update({2.0, 0.0, 0.0}, 0.02);
  EXPECT_TRUE(r.saturated);
  expect_wheels(r.wheels, {-40.0, 20.0, 20.0});
  // A ramp starts from held set-points.
  p.max_wheel_accel = 100.0;
  VelocityLimiter held(p);
  held.hold({-25.0, 12.5, 12.5});
  r = held.update({1.0, 0.0, 0.0}, 0.02);
  EXPECT_FALSE(r.accel_limited);
  expect_wheels(r.wheels, {-25.0, 12.5, 12.5});
  // Differential bases drop vy.
  VelocityLimiter diff(base_preset("ianus3"));
  r = diff.update({0.0, 1.0, 0.0}, 0.02);
  expect_wheels(r.wheels, {0.0, 0.0});
}

// After a watchdog trip the board's set-points are 0: the ramp restarts from
// rest instead of stepping from the old target (triskar, 100 rad/s^2, 20 ms:
// one step is 2 rad/s on the fastest wheel; 1 m/s forward is
// (-25, 12.5, 12.5) rad/s, so the first step is (-2, 1, 1)).
TEST(VelocityLimiter, RestartsTheRampWhenTheBoardStopped) {
  BaseParams p = base_preset("triskar");
  p.max_wheel_accel = 100.0;
  VelocityLimiter lim(p);
  VelocityLimiter::Result r;
  for (int i = 0; i < 20; ++i) r = lim.update({1.0, 0.0, 0.0}, 0.02);
  expect_wheels(r.wheels, {-25.0, 12.5, 12.5});
  EXPECT_FALSE(lim.board_stopped());
  lim.set_board_stopped(true);
  EXPECT_TRUE(lim.board_stopped());
  // While the board reports it stopped, every command is the first step:
  // whichever of them the board applies first is one step from 0.
  for (int i = 0; i < 3; ++i) {
    r = lim.update({1.0, 0.0, 0.0}, 0.02);
    EXPECT_TRUE(r.accel_limited);
    expect_wheels(r.wheels, {-2.0, 1.0, 1.0});
  }
  // A state without the bit: the ramp goes on from the applied step.
  lim.set_board_stopped(false);
  r = lim.update({1.0, 0.0, 0.0}, 0.02);
  expect_wheels(r.wheels, {-4.0, 2.0, 2.0});
  r = lim.update({1.0, 0.0, 0.0}, 0.02);
  expect_wheels(r.wheels, {-6.0, 3.0, 3.0});
  // reset() (link lost) also ramps from rest and clears the flag.
  lim.set_board_stopped(true);
  lim.reset();
  EXPECT_FALSE(lim.board_stopped());
  r = lim.update({-1.0, 0.0, 0.0}, 0.01);
  expect_wheels(r.wheels, {1.0, -0.5, -0.5});
}

// airboard_node's dynamic_reconfigure: IANUS3 (r 0.05 m, track 0.38 m),
// vx 0.6 m/s, omega 1 rad/s: w = (0.6 -+ 0.19) / 0.05 = (8.2, 15.8) rad/s.
// A 6 rad/s limit scales both by 6 / 15.8: (3.113924, 6). Then 50 rad/s^2 at
// 20 ms: a stop is a step of at most 1 rad/s on the fastest wheel, from the
// last set-points: (3.113924 - 3.113924 / 6, 5). A negative limit is refused
// and nothing changes.
TEST(VelocityLimiter, SetLimitsAppliesFromTheNextUpdate) {
  BaseParams p = base_preset("ianus3");
  p.max_wheel_accel = 0.0;
  VelocityLimiter lim(p);
  auto r = lim.update({0.6, 0.0, 1.0}, 0.02);
  EXPECT_FALSE(r.saturated);
  expect_wheels(r.wheels, {8.2, 15.8});
  lim.set_limits(6.0, 0.0);
  r = lim.update({0.6, 0.0, 1.0}, 0.02);
  EXPECT_TRUE(r.saturated);
  EXPECT_NEAR(r.wheels[0], 8.2 * 6.0 / 15.8, 1e-12);
  EXPECT_NEAR(r.wheels[1], 6.0, 1e-12);
  lim.set_limits(6.0, 50.0);
  r = lim.update({0.0, 0.0, 0.0}, 0.02);
  EXPECT_TRUE(r.accel_limited);
  EXPECT_NEAR(r.wheels[0], 8.2 * 6.0 / 15.8 * (5.0 / 6.0), 1e-12);
  EXPECT_NEAR(r.wheels[1], 5.0, 1e-12);
  EXPECT_THROW(lim.set_limits(-1.0, 50.0), std::invalid_argument);
  EXPECT_THROW(lim.set_limits(6.0, std::nan("")), std::invalid_argument);
  EXPECT_DOUBLE_EQ(lim.params().max_wheel_speed, 6.0);
  EXPECT_DOUBLE_EQ(lim.params().max_wheel_accel, 50.0);
}

// The board's base parameters are the stack's one geometry type plus the
// board's limits: a preset carries mrt_common's geometry unchanged, and the
// kinematics of the geometry alone equals the board's. Triskar, vx 1 m/s:
// w_i = -sin(a_i) / 0.04 = -25, 12.5, 12.5 rad/s (a = 90, 210, 330 deg).
TEST(BaseParams, ExtendsTheCommonBaseGeometry) {
  const BaseParams p = base_preset("triskar");
  const mrt::common::BaseGeometry& g = p;
  const mrt::common::BaseGeometry& want = mrt::common::base_preset("triskar").geometry;
  EXPECT_EQ(g.type, want.type);
  EXPECT_EQ(g.wheel_radius, want.wheel_radius);
  EXPECT_EQ(g.wheel_distance, want.wheel_distance);
  EXPECT_EQ(g.wheel_angles, want.wheel_angles);
  EXPECT_EQ(p.wheel_count(), 3u);
  const std::vector<double> w = mrt::common::inverse(g, {1.0, 0.0, 0.0});
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NEAR(w[0], -25.0, 1e-9);
  EXPECT_NEAR(w[1], 12.5, 1e-9);
  EXPECT_NEAR(w[2], 12.5, 1e-9);
  const std::vector<double> board = make_kinematics(p)->inverse({1.0, 0.0, 0.0});
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(board[i], w[i]);
}

// Joint states for the robot description. 8192 counts per revolution:
// 2048 counts = a quarter turn = pi/2 = 1.570796 rad; -12288 counts = -1.5
// turns = -9.424778 rad. Names in the motor (WheelState) order.
TEST(WheelJoints, NamesAndCountAngles) {
  using mrt::common::encoder_angle;
  using mrt::common::wheel_joint_names;
  mrt::common::BaseGeometry diff;
  mrt::common::BaseGeometry omni;
  omni.type = mrt::common::BaseType::kOmni;
  omni.wheel_angles = {0.0, 2.0, 4.0};
  EXPECT_EQ(wheel_joint_names(diff), (std::vector<std::string>{"left_wheel_joint", "right_wheel_joint"}));
  EXPECT_EQ(wheel_joint_names(omni), (std::vector<std::string>{"wheel_0_joint", "wheel_1_joint", "wheel_2_joint"}));
  EXPECT_NEAR(encoder_angle(2048, 8192), 1.5707963267948966, 1e-12);
  EXPECT_NEAR(encoder_angle(-12288, 8192), -9.42477796076938, 1e-12);
  EXPECT_EQ(encoder_angle(0, 8192), 0.0);
}
