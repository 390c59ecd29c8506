// recvision_node reading a video file through ~device (test/device.test):
// one percept message per frame of the video, in order, and in each the
// ball within 3 % in distance (the 2 % plus MJPG's blurred edges)
// and 0.03 rad in bearing of the truth written with the video; the raw
// frames are republished on camera/image_raw.
#include <gtest/gtest.h>

#include <mrt_msgs/Percept.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

#include <cmath>
#include <fstream>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::wait_for;

namespace {
double attr(const mrt_msgs::PerceptObject& o, const std::string& name) {
  for (const auto& a : o.attributes)
    if (a.name == name) return a.value;
  return NAN;
}
}  // namespace

TEST(Device, EveryFrameOfTheVideoBecomesPercepts) {
  ros::NodeHandle nh, pnh("~");
  std::string truth_file;
  ASSERT_TRUE(pnh.getParam("truth", truth_file));
  std::ifstream in(truth_file);
  std::vector<std::pair<double, double>> truth;  // distance, bearing per frame
  std::string line;
  std::getline(in, line);  // header
  for (int k = 0; std::getline(in, line);) {
    double d, b;
    ASSERT_EQ(std::sscanf(line.c_str(), "%d,%lf,%lf", &k, &d, &b), 3) << line;
    ASSERT_EQ(k, static_cast<int>(truth.size()));
    truth.emplace_back(d, b);
  }
  ASSERT_EQ(truth.size(), 40u);
  std::vector<mrt_msgs::Percept> got;
  int raw = 0;
  auto r_sub = nh.subscribe<sensor_msgs::Image>("/robot1/camera/image_raw", 50,
                                                [&](const sensor_msgs::ImageConstPtr& m) { raw += m->encoding == "rgb8"; });
  auto p_sub = nh.subscribe<mrt_msgs::Percept>("/robot1/percepts", 100,
                                               [&](const mrt_msgs::PerceptConstPtr& m) { got.push_back(*m); });
  ASSERT_TRUE(wait_for([&] { return got.size() >= truth.size(); }, 40.0)) << got.size() << " percept messages";
  ros::WallDuration(0.3).sleep();
  ros::spinOnce();
  EXPECT_EQ(got.size(), truth.size());  // the video is played once
  EXPECT_GE(raw, 30);                   // republished (a few may precede the subscription)
  for (std::size_t k = 0; k < got.size() && k < truth.size(); ++k) {
    int balls = 0;
    for (const auto& o : got[k].objects) {
      if (o.membership_class != "Ball") continue;
      ++balls;
      EXPECT_NEAR(attr(o, "distance"), truth[k].first, 0.03 * truth[k].first) << "frame " << k;
      EXPECT_NEAR(std::remainder(attr(o, "bearing") - truth[k].second, 2 * M_PI), 0.0, 0.03) << "frame " << k;
    }
    EXPECT_EQ(balls, 1) << "frame " << k;
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "recvision_device_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
