// airboard_node's dynamic_reconfigure against airboard_emulator (IANUS3:
// wheel radius 0.05 m, track 0.38 m, ~base/max_wheel_speed 24 rad/s).
// cmd_vel vx 0.6 m/s, omega 1 rad/s asks for the wheel speeds
// (0.6 -+ 1 * 0.38 / 2) / 0.05 = (8.2, 15.8) rad/s, under 24 rad/s. With
// max_wheel_speed 6 rad/s through airboard/set_parameters the node scales
// the pair by 6 / 15.8 (the direction of motion kept): (3.1139, 6.0). The
// board (the emulator) reports the set-points it received in wheel_state;
// the node ramps between them at ~base/max_wheel_accel (120 rad/s^2), so the
// cap holds from the first capped set-point on.
#include <dynamic_reconfigure/Reconfigure.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rostest_airboard_fixture.h"

namespace {

using namespace airboard_test;

bool set_double(const std::string& name, double value, dynamic_reconfigure::Config& out) {
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::DoubleParameter p;
  p.name = name;
  p.value = value;
  srv.request.config.doubles.push_back(p);
  if (!ros::service::call("airboard/set_parameters", srv)) return false;
  out = srv.response.config;
  return true;
}

double value_of(const dynamic_reconfigure::Config& c, const std::string& name) {
  for (const auto& d : c.doubles)
    if (d.name == name) return d.value;
  return NAN;
}

TEST_F(Airboard, ReconfiguredSpeedLimitCapsTheWheelSetPoints) {
  ASSERT_TRUE(ros::service::waitForService("airboard/set_parameters", ros::Duration(20)));
  const auto last_setpoints = [&](double left, double right) {
    if (wheels_.empty() || wheels_.back().setpoint.size() != 2) return false;
    return std::fabs(wheels_.back().setpoint[0] - left) < 2e-3 && std::fabs(wheels_.back().setpoint[1] - right) < 2e-3;
  };
  // drives until the board reports the set-points (a starved node may see
  // a watchdog trip on this shared machine: the drive goes on)
  const auto drive_until = [&](double left, double right) {
    for (int i = 0; i < 50; ++i) {
      drive(0.1, 0.6, 0.0, 1.0);
      if (last_setpoints(left, right)) return true;
    }
    return false;
  };
  // the start-up limit (24 rad/s) leaves the request as it is
  EXPECT_TRUE(drive_until(8.2, 15.8)) << (wheels_.empty() ? -1.0 : wheels_.back().setpoint[1]);

  dynamic_reconfigure::Config applied;
  ASSERT_TRUE(set_double("max_wheel_speed", 6.0, applied));
  EXPECT_DOUBLE_EQ(value_of(applied, "max_wheel_speed"), 6.0);
  EXPECT_DOUBLE_EQ(value_of(applied, "max_wheel_accel"), 120.0);  // ianus3.yaml's, untouched
  wheels_.clear();
  EXPECT_TRUE(drive_until(8.2 * 6.0 / 15.8, 6.0)) << (wheels_.empty() ? -1.0 : wheels_.back().setpoint[1]);
  drive(1.0, 0.6, 0.0, 1.0);
  // from the first set-points after the change on, none beyond the limit
  bool capped = false;
  for (const auto& w : wheels_) {
    capped = capped || std::fabs(w.setpoint[1] - 6.0) < 2e-3;
    if (capped) {
      EXPECT_LE(std::fabs(w.setpoint[0]), 6.0 + 2e-3);
      EXPECT_LE(std::fabs(w.setpoint[1]), 6.0 + 2e-3);
    }
  }
  EXPECT_TRUE(capped);

  // back to 24 rad/s: the request passes unscaled again
  ASSERT_TRUE(set_double("max_wheel_speed", 24.0, applied));
  EXPECT_TRUE(drive_until(8.2, 15.8));
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "airboard_reconfigure_rostest");
  ros::NodeHandle nh;  // keep the node alive for the whole run
  return RUN_ALL_TESTS();
}
