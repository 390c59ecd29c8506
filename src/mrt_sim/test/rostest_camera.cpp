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
  EXPECT_EQ(ci.distortion_model, "omni_mirror");
  EXPECT_EQ(ci.K[2], 320.0);
  EXPECT_EQ(ci.K[5], 240.0);

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
