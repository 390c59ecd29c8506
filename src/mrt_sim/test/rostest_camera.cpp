// rostest of sim_node's rendered camera (msl_field.yaml): camera/image_raw
// and camera/camera_info at the configured rate in sim time, with the
// configured size and encoding, in the viewpoint frame, and the static
// transform of that frame at the URDF's mount.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

template <class M>
struct Recorder {
  std::vector<M> msgs;
  void on(const typename M::ConstPtr& m) { msgs.push_back(*m); }
};

// The camera_info's description of msl_field.yaml's camera.
void expect_omni_profile(const sensor_msgs::CameraInfo& ci) {
  // Not a pinhole camera (README "CameraInfo of the omnidirectional
  // camera"): K and P hold only the mirror centre (fx = fy = 0), R the
  // identity, binning and roi their defaults.
  EXPECT_EQ(ci.distortion_model, "mrt_omni_profile");
  const std::vector<double> k(ci.K.begin(), ci.K.end()), p(ci.P.begin(), ci.P.end()), r(ci.R.begin(), ci.R.end());
  EXPECT_EQ(k, (std::vector<double>{0, 0, 320, 0, 0, 240, 0, 0, 1}));
  EXPECT_EQ(p, (std::vector<double>{0, 0, 320, 0, 0, 0, 240, 0, 0, 0, 1, 0}));
  EXPECT_EQ(r, (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(ci.binning_x, 0u);
  EXPECT_EQ(ci.roi.width, 0u);
  // D = [roll, pitch, (theta, r) ...]: msl_field.yaml's untilted isometric
  // mirror, viewpoint 0.7 m up (URDF), 0.02 m/px to 3 m, then 560 px/rad to
  // 1.5 rad: the inner part's knot at atan(3 / 0.7) = 1.341564 rad is
  // 3 / 0.02 = 150 px, the rim 150 + (1.5 - 1.341564) * 560 = 238.724 px;
  // the floor 1 m away (theta atan(1 / 0.7)) 1 / 0.02 = 50 px out.
  ASSERT_GE(ci.D.size(), 6u);
  ASSERT_EQ(ci.D.size() % 2, 0u);
  EXPECT_EQ(ci.D[0], 0.0);
  EXPECT_EQ(ci.D[1], 0.0);
  EXPECT_EQ(ci.D[2], 0.0);
  EXPECT_NEAR(ci.D[ci.D.size() - 2], 1.5, 1e-9);
  EXPECT_NEAR(ci.D.back(), 238.724, 1e-3);
  const double t1 = std::atan2(1.0, 0.7), tb = std::atan2(3.0, 0.7);
  bool knot = false;
  for (std::size_t i = 4; i < ci.D.size(); i += 2) {
    EXPECT_GT(ci.D[i], ci.D[i - 2]);
    knot = knot || (std::abs(ci.D[i] - tb) < 1e-9 && std::abs(ci.D[i + 1] - 150.0) < 1e-6);
    if (ci.D[i - 2] <= t1 && ci.D[i] >= t1) {
      const double a = (t1 - ci.D[i - 2]) / (ci.D[i] - ci.D[i - 2]);
      EXPECT_NEAR(ci.D[i - 1] + a * (ci.D[i + 1] - ci.D[i - 1]), 50.0, 0.01);
    }
  }
  EXPECT_TRUE(knot);
}

}  // namespace

TEST(SimCamera, ImageAndInfoAtTheConfiguredRate) {
  ros::NodeHandle nh;
  tf2_ros::Buffer tf_buffer;
  tf2_ros::TransformListener tf_listener(tf_buffer);
  Recorder<sensor_msgs::Image> images;
  Recorder<sensor_msgs::CameraInfo> infos;
  ros::Subscriber si = nh.subscribe("/robot1/camera/image_raw", 200, &Recorder<sensor_msgs::Image>::on, &images);
  ros::Subscriber sc =
      nh.subscribe("/robot1/camera/camera_info", 200, &Recorder<sensor_msgs::CameraInfo>::on, &infos);
  // 2 s of sim time after the first frame (wall time is capped so a slow
  // machine fails the count instead of hanging).
  ASSERT_TRUE(mrt::ros_common::wait_for([&] { return !images.msgs.empty(); }, 20.0)) << "no image";
  mrt::ros_common::wait_for(
      [&] { return (images.msgs.back().header.stamp - images.msgs.front().header.stamp).toSec() >= 2.0; }, 30.0);
  ASSERT_GE(images.msgs.size(), 20u);
  ASSERT_GE(infos.msgs.size(), 20u);

  // 30 Hz at a 1 ms step is a frame every round(1000 / 30) = 33 steps:
  // consecutive stamps 0.033 s apart (30.3 Hz), none missing.
  for (std::size_t i = 1; i < images.msgs.size(); ++i)
    EXPECT_NEAR((images.msgs[i].header.stamp - images.msgs[i - 1].header.stamp).toSec(), 0.033, 1e-6) << i;
  const sensor_msgs::Image& im = images.msgs.back();
  EXPECT_EQ(im.width, 640u);
  EXPECT_EQ(im.height, 480u);
  EXPECT_EQ(im.encoding, "rgb8");
  EXPECT_EQ(im.step, 640u * 3u);
  ASSERT_EQ(im.data.size(), 640u * 480u * 3u);
  EXPECT_EQ(im.header.frame_id, "robot1/omni_mirror");
  // The own body at the centre is black (noise 2 levels: below 16), the
  // floor 2 m behind (radius 100 px, down in the image) is carpet green.
  const std::size_t centre = (240 * 640 + 320) * 3;
  EXPECT_LT(im.data[centre] + im.data[centre + 1] + im.data[centre + 2], 16);
  const std::size_t floor = (340 * 640 + 320) * 3;
  EXPECT_GT(im.data[floor + 1], im.data[floor] + 40);
  EXPECT_GT(im.data[floor + 1], im.data[floor + 2] + 40);

  const sensor_msgs::CameraInfo& ci = infos.msgs.back();
  EXPECT_EQ(ci.header.frame_id, "robot1/omni_mirror");
  EXPECT_EQ(ci.width, 640u);
  EXPECT_EQ(ci.height, 480u);
  expect_omni_profile(ci);

  // The viewpoint frame hangs off the true body at ianus3.urdf's
  // omni_mirror joint: (0, 0, 0.7).
  geometry_msgs::TransformStamped t;
  ASSERT_TRUE(mrt::ros_common::wait_for(
      [&] { return tf_buffer.canTransform("robot1/base_link_truth", "robot1/omni_mirror", ros::Time(0)); }, 10.0));
  t = tf_buffer.lookupTransform("robot1/base_link_truth", "robot1/omni_mirror", ros::Time(0));
  EXPECT_NEAR(t.transform.translation.x, 0.0, 1e-9);
  EXPECT_NEAR(t.transform.translation.z, 0.7, 1e-9);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_camera_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
