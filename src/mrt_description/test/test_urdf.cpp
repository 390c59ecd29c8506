// Every URDF of mrt_description parses with urdf::Model and has the joints
// and frames the stack expects (names, types, positions from the presets of
// mrt_common/base_kinematics.h and the world files of mrt_sim).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <urdf/model.h>

namespace {

urdf::Model load(const std::string& base) {
  urdf::Model m;
  const std::string path = std::string(MRT_DESCRIPTION_URDF) + "/" + base + ".urdf";
  EXPECT_TRUE(m.initFile(path)) << path;
  return m;
}

urdf::JointConstSharedPtr joint(const urdf::Model& m, const std::string& name) {
  urdf::JointConstSharedPtr j = m.getJoint(name);
  EXPECT_TRUE(j) << m.getName() << ": no joint " << name;
  return j;
}

// Only the WheelState wheels (and the P3-AT's mimicking rear wheels) move.
int moving_joints(const urdf::Model& m) {
  int n = 0;
  for (const auto& kv : m.joints_)
    if (kv.second->type != urdf::Joint::FIXED) ++n;
  return n;
}

TEST(Urdf, Ianus3) {
  const urdf::Model m = load("ianus3");
  EXPECT_EQ(m.getRoot()->name, "base_link");
  EXPECT_EQ(moving_joints(m), 2);
  // Wheels [left, right] at y = +-track/2 = +-0.19 m, axle at the wheel radius 0.05 m.
  const auto l = joint(m, "left_wheel_joint"), r = joint(m, "right_wheel_joint");
  ASSERT_TRUE(l && r);
  EXPECT_EQ(l->type, urdf::Joint::CONTINUOUS);
  EXPECT_NEAR(l->parent_to_joint_origin_transform.position.y, 0.19, 1e-9);
  EXPECT_NEAR(r->parent_to_joint_origin_transform.position.y, -0.19, 1e-9);
  EXPECT_NEAR(l->parent_to_joint_origin_transform.position.z, 0.05, 1e-9);
  EXPECT_DOUBLE_EQ(l->axis.y, 1.0);
  // Mice at y = +-0.10 m (worlds/msl_field.yaml), named like the simulator's frames.
  EXPECT_NEAR(joint(m, "mouse_left_joint")->parent_to_joint_origin_transform.position.y, 0.10, 1e-9);
  EXPECT_NEAR(joint(m, "mouse_right_joint")->parent_to_joint_origin_transform.position.y, -0.10, 1e-9);
  for (const char* n : {"omni_camera", "omni_mirror", "kicker_front", "kicker_back", "sonar_7"})
    EXPECT_TRUE(m.getLink(n)) << n;
}

TEST(Urdf, TriskarWheelsAt120Degrees) {
  const urdf::Model m = load("triskar");
  EXPECT_EQ(moving_joints(m), 3);
  // wheel_1 at 210 deg, 0.20 m: (0.2 cos 210, 0.2 sin 210) = (-0.173205, -0.1).
  const auto w = joint(m, "wheel_1_joint");
  ASSERT_TRUE(w);
  EXPECT_NEAR(w->parent_to_joint_origin_transform.position.x, -0.1732050808, 1e-8);
  EXPECT_NEAR(w->parent_to_joint_origin_transform.position.y, -0.1, 1e-9);
  EXPECT_NEAR(w->parent_to_joint_origin_transform.position.z, 0.04, 1e-9);
  EXPECT_DOUBLE_EQ(w->axis.x, -1.0);
  EXPECT_FALSE(m.getJoint("wheel_3_joint"));
}

TEST(Urdf, Omni4) {
  const urdf::Model m = load("omni4");
  EXPECT_EQ(moving_joints(m), 4);
  // wheel_3 at 315 deg: (0.141421, -0.141421).
  const auto w = joint(m, "wheel_3_joint");
  ASSERT_TRUE(w);
  EXPECT_NEAR(w->parent_to_joint_origin_transform.position.x, 0.1414213562, 1e-8);
  EXPECT_NEAR(w->parent_to_joint_origin_transform.position.y, -0.1414213562, 1e-8);
  EXPECT_TRUE(m.getLink("omni_mirror"));
}

TEST(Urdf, P3atSonarBeltAndSkidSteer) {
  const urdf::Model m = load("p3at");
  // One motor per side: the front wheels are the joints; the rear wheels
  // are fixed (drawn only), 0.268 m behind them.
  EXPECT_EQ(moving_joints(m), 2);
  const auto rl = joint(m, "rear_left_wheel_joint");
  ASSERT_TRUE(rl);
  EXPECT_EQ(rl->type, urdf::Joint::FIXED);
  EXPECT_NEAR(rl->parent_to_joint_origin_transform.position.x, -0.134, 1e-9);
  // Wheel radius 0.11 m, track 0.40 m.
  EXPECT_NEAR(joint(m, "right_wheel_joint")->parent_to_joint_origin_transform.position.y, -0.20, 1e-9);
  EXPECT_NEAR(joint(m, "right_wheel_joint")->parent_to_joint_origin_transform.position.z, 0.11, 1e-9);
  // 16 sonars on the 0.33 m footprint circle, sonar_i at 22.5 i degrees:
  // sonar_4 at 90 deg: (0, 0.33); sonar_10 at 225 deg: (-0.233345, -0.233345).
  for (int i = 0; i < 16; ++i) EXPECT_TRUE(m.getLink("sonar_" + std::to_string(i))) << i;
  EXPECT_FALSE(m.getLink("sonar_16"));
  const auto s4 = joint(m, "sonar_4_joint")->parent_to_joint_origin_transform;
  EXPECT_NEAR(s4.position.x, 0.0, 1e-8);
  EXPECT_NEAR(s4.position.y, 0.33, 1e-8);
  const auto s10 = joint(m, "sonar_10_joint")->parent_to_joint_origin_transform;
  EXPECT_NEAR(s10.position.x, -0.2333452378, 1e-8);
  double roll, pitch, yaw;
  s10.rotation.getRPY(roll, pitch, yaw);
  EXPECT_NEAR(std::remainder(yaw - 3.926990817, 2 * M_PI), 0.0, 1e-8);  // 225 deg
  for (const char* n : {"mouse_left", "mouse_right", "gps"}) EXPECT_TRUE(m.getLink(n)) << n;
}

}  // namespace
