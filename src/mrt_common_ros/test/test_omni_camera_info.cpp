// The omnidirectional camera's CameraInfo: the layout written by hand,
// read back, and what is wrong with a malformed one.
#include <gtest/gtest.h>

#include "mrt_common_ros/omni_camera_info.h"

using mrt::common::MirrorProfile;
using mrt::common::OmniCamera;
using namespace mrt::ros_common;

namespace {
OmniCamera camera() {
  OmniCamera c;
  c.width = 640;
  c.height_px = 480;
  c.cx = 321.5;
  c.cy = 239.5;
  c.roll = 0.01;
  c.pitch = -0.02;
  c.profile = MirrorProfile({{0.0, 0.0}, {0.5, 100.0}, {1.0, 180.0}});
  return c;
}
}  // namespace

TEST(OmniCameraInfo, LayoutAndRoundTrip) {
  const sensor_msgs::CameraInfo info = to_camera_info(camera(), "robot1/omni_mirror", ros::Time(12.5));
  EXPECT_EQ(info.header.frame_id, "robot1/omni_mirror");
  EXPECT_EQ(info.header.stamp, ros::Time(12.5));
  EXPECT_EQ(info.distortion_model, "mrt_omni_profile");
  EXPECT_EQ(info.width, 640u);
  EXPECT_EQ(info.height, 480u);
  const boost::array<double, 9> k{0, 0, 321.5, 0, 0, 239.5, 0, 0, 1};
  EXPECT_EQ(info.K, k);
  const boost::array<double, 12> p{0, 0, 321.5, 0, 0, 0, 239.5, 0, 0, 0, 1, 0};
  EXPECT_EQ(info.P, p);
  EXPECT_EQ(info.D, (std::vector<double>{0.01, -0.02, 0.0, 0.0, 0.5, 100.0, 1.0, 180.0}));
  OmniCamera back;
  ASSERT_EQ(from_camera_info(info, &back), "");
  EXPECT_EQ(back.width, 640);
  EXPECT_EQ(back.height_px, 480);
  EXPECT_EQ(back.cx, 321.5);
  EXPECT_EQ(back.cy, 239.5);
  EXPECT_EQ(back.roll, 0.01);
  EXPECT_EQ(back.pitch, -0.02);
  EXPECT_EQ(back.profile.table(), camera().profile.table());
  EXPECT_DOUBLE_EQ(back.profile.radius(0.75), 140.0);  // linear between (0.5, 100) and (1, 180)
}

TEST(OmniCameraInfo, MalformedNamed) {
  sensor_msgs::CameraInfo info = to_camera_info(camera(), "c", ros::Time());
  OmniCamera out;
  info.distortion_model = "plumb_bob";
  EXPECT_EQ(from_camera_info(info, &out), "distortion model 'plumb_bob', expected 'mrt_omni_profile'");
  info.distortion_model = kOmniProfileModel;
  info.D.pop_back();
  EXPECT_EQ(from_camera_info(info, &out),
            "D holds 7 values (expected roll, pitch and 2 or more (theta, r) pairs)");
  info.D = {0.0, 0.0, 0.0, 0.0, 0.5, 100.0, 0.4, 180.0};
  EXPECT_EQ(from_camera_info(info, &out),
            "D's profile: mirror profile: samples must increase strictly in angle and radius (sample 2)");
}
