#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "mrt_common/base_kinematics.h"

using namespace mrt::common;

namespace {
constexpr double kS45 = 0.70710678118654752440;  // sin 45 deg = cos 45 deg
constexpr double kC30 = 0.86602540378443864676;  // cos 30 deg

void expect_wheels(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "wheel " << i;
}

const BaseGeometry& geometry(const char* name) { return base_preset(name).geometry; }
}  // namespace

// Differential: w = (vx -+ omega * track / 2) / r.
TEST(BaseKinematics, Ianus3HandComputedWheelSpeeds) {
  // r 0.05, track 0.38: vx 1 -> 1 / 0.05 = 20; omega 1 -> -+0.19 / 0.05 = -+3.8.
  const BaseGeometry& g = geometry("ianus3");
  expect_wheels(inverse(g, {1.0, 0.0, 0.0}), {20.0, 20.0});
  expect_wheels(inverse(g, {0.0, 1.0, 0.0}), {0.0, 0.0});  // cannot move sideways
  expect_wheels(inverse(g, {0.0, 0.0, 1.0}), {-3.8, 3.8});
}

TEST(BaseKinematics, P3atHandComputedWheelSpeeds) {
  // r 0.11, track 0.40: vx 1.1 -> 10; omega 1.1 -> -+0.22 / 0.11 = -+2.
  const BaseGeometry& g = geometry("p3at");
  expect_wheels(inverse(g, {1.1, 0.0, 0.0}), {10.0, 10.0});
  expect_wheels(inverse(g, {0.0, 1.1, 0.0}), {0.0, 0.0});
  expect_wheels(inverse(g, {0.0, 0.0, 1.1}), {-2.0, 2.0});
}

// Omni: w_i = (-sin a_i vx + cos a_i vy + L omega) / r.
TEST(BaseKinematics, TriskarHandComputedWheelSpeeds) {
  // a = 90, 210, 330 deg, L 0.2, r 0.04.
  // vx 1: -sin a = -1, 0.5, 0.5 -> -25, 12.5, 12.5.
  // vy 1: cos a = 0, -cos 30, cos 30 -> 0, -21.65, 21.65.
  // omega 1: 0.2 / 0.04 = 5 for every wheel.
  const BaseGeometry& g = geometry("triskar");
  expect_wheels(inverse(g, {1.0, 0.0, 0.0}), {-25.0, 12.5, 12.5});
  expect_wheels(inverse(g, {0.0, 1.0, 0.0}), {0.0, -kC30 / 0.04, kC30 / 0.04});
  expect_wheels(inverse(g, {0.0, 0.0, 1.0}), {5.0, 5.0, 5.0});
}

TEST(BaseKinematics, Omni4HandComputedWheelSpeeds) {
  // a = 45, 135, 225, 315 deg: -sin a = -s, -s, s, s; cos a = s, -s, -s, s.
  const BaseGeometry& g = geometry("omni4");
  const double w = kS45 / 0.04;
  expect_wheels(inverse(g, {1.0, 0.0, 0.0}), {-w, -w, w, w});
  expect_wheels(inverse(g, {0.0, 1.0, 0.0}), {w, -w, -w, w});
  expect_wheels(inverse(g, {0.0, 0.0, 1.0}), {5.0, 5.0, 5.0, 5.0});
}

TEST(BaseKinematics, DifferentialForwardByHand) {
  // ianus3, wheels 9.05 / 10.95 rad/s: vx = 0.05 * 20 / 2 = 0.5,
  // omega = 0.05 * 1.9 / 0.38 = 0.25.
  const Twist2D t = forward(geometry("ianus3"), {9.05, 10.95});
  EXPECT_NEAR(t.vx, 0.5, 1e-12);
  EXPECT_NEAR(t.vy, 0.0, 1e-12);
  EXPECT_NEAR(t.omega, 0.25, 1e-12);
}

TEST(BaseKinematics, InverseThenForwardIsIdentity) {
  const Twist2D twists[] = {{0.3, -0.2, 0.7}, {-1.5, 0.8, -2.0}, {0.0, 0.0, 0.0}, {1.0, 1.0, 0.0}};
  for (const BasePreset& p : base_presets()) {
    const bool holonomic = p.geometry.type == BaseType::kOmni;
    for (const Twist2D& t : twists) {
      const Twist2D back = forward(p.geometry, inverse(p.geometry, t));
      EXPECT_NEAR(back.vx, t.vx, 1e-12) << p.name;
      EXPECT_NEAR(back.vy, holonomic ? t.vy : 0.0, 1e-12) << p.name;  // vy dropped
      EXPECT_NEAR(back.omega, t.omega, 1e-12) << p.name;
    }
  }
}

TEST(BaseKinematics, Omni4ForwardIsLeastSquares) {
  // Rows (-sin a, cos a, L) for a = 45, 135, 225, 315 deg give
  // J^T J = diag(2, 2, 4 L^2). Only wheel 1 turning at 1 rad/s: surface
  // speeds (0.04, 0, 0, 0), J^T v = 0.04 (-s, s, L), so
  // vx = -0.02 s, vy = 0.02 s, omega = 0.04 / (4 * 0.2) = 0.05.
  const Twist2D t = forward(geometry("omni4"), {1.0, 0.0, 0.0, 0.0});
  EXPECT_NEAR(t.vx, -0.02 * kS45, 1e-12);
  EXPECT_NEAR(t.vy, 0.02 * kS45, 1e-12);
  EXPECT_NEAR(t.omega, 0.05, 1e-12);
}

TEST(BaseKinematics, SaturationKeepsDirection) {
  for (const BasePreset& p : base_presets()) {
    const bool holonomic = p.geometry.type == BaseType::kOmni;
    const Twist2D req{3.0, holonomic ? 2.0 : 0.0, 4.0};
    std::vector<double> w = inverse(p.geometry, req);
    const double s = saturate_preserving_direction(w, p.max_wheel_speed);
    EXPECT_GT(s, 0.0) << p.name;
    EXPECT_LT(s, 1.0) << p.name;
    double peak = 0.0;
    for (double v : w) peak = std::max(peak, std::fabs(v));
    EXPECT_NEAR(peak, p.max_wheel_speed, 1e-12) << p.name;
    const Twist2D got = forward(p.geometry, w);
    EXPECT_NEAR(got.vx, s * req.vx, 1e-12) << p.name;
    EXPECT_NEAR(got.vy, s * req.vy, 1e-12) << p.name;
    EXPECT_NEAR(got.omega, s * req.omega, 1e-12) << p.name;
  }
  // ianus3 by hand: v 2, omega 1 -> wheels 36.2, 43.8 rad/s, max 24: scale 24 / 43.8.
  std::vector<double> w = inverse(geometry("ianus3"), {2.0, 0.0, 1.0});
  EXPECT_NEAR(saturate_preserving_direction(w, 24.0), 24.0 / 43.8, 1e-12);
  expect_wheels(w, {36.2 * 24.0 / 43.8, 24.0});
  // Below the limit, or without one, nothing changes.
  std::vector<double> slow{1.0, -2.0};
  EXPECT_EQ(saturate_preserving_direction(slow, 5.0), 1.0);
  EXPECT_EQ(saturate_preserving_direction(slow, 0.0), 1.0);
  EXPECT_EQ(slow[0], 1.0);
  EXPECT_EQ(slow[1], -2.0);
}

TEST(BaseKinematics, PresetNumbers) {
  const BasePreset& ianus3 = base_preset("ianus3");
  EXPECT_EQ(ianus3.geometry.type, BaseType::kDifferential);
  EXPECT_EQ(ianus3.geometry.wheel_radius, 0.05);
  EXPECT_EQ(ianus3.geometry.track, 0.38);
  EXPECT_EQ(ianus3.max_wheel_speed, 24.0);
  EXPECT_EQ(ianus3.geometry.wheel_count(), 2u);
  const BasePreset& p3at = base_preset("p3at");
  EXPECT_EQ(p3at.geometry.wheel_radius, 0.11);
  EXPECT_EQ(p3at.geometry.track, 0.40);
  EXPECT_NEAR(p3at.max_wheel_speed * p3at.geometry.wheel_radius, 1.2, 1e-12);  // 1.2 m/s
  EXPECT_EQ(p3at.body_radius, 0.33);
  const BasePreset& triskar = base_preset("triskar");
  EXPECT_EQ(triskar.geometry.type, BaseType::kOmni);
  EXPECT_EQ(triskar.geometry.wheel_count(), 3u);
  EXPECT_NEAR(rad_to_deg(triskar.geometry.wheel_angles[1]), 210.0, 1e-12);
  EXPECT_EQ(triskar.geometry.wheel_distance, 0.20);
  EXPECT_EQ(base_preset("omni4").geometry.wheel_count(), 4u);
  EXPECT_EQ(base_presets().size(), 4u);
}

TEST(BaseKinematics, BadInputsThrow) {
  try {
    base_preset("roomba");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown base preset 'roomba' (expected ianus3, p3at, triskar or omni4)");
  }
  EXPECT_THROW(forward(geometry("triskar"), {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(forward(geometry("ianus3"), {1.0, 2.0, 3.0}), std::invalid_argument);
  BaseGeometry line = geometry("triskar");
  line.wheel_angles = {0.0, kPi, 0.0};  // all drive along y: vx undetermined
  EXPECT_FALSE(omni_spans_plane(line.wheel_distance, line.wheel_angles));
  EXPECT_THROW(forward(line, {0.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_TRUE(omni_spans_plane(0.2, geometry("omni4").wheel_angles));
  EXPECT_FALSE(omni_spans_plane(0.2, {0.0, kPi / 2}));  // two wheels
}
