// mice_calibrate on bags: the protocol is driven in mrt_sim, every run is
// recorded as a bag of mrt_msgs/MiceReading, the tool recovers the mice.
#include <gtest/gtest.h>
#include <mrt_msgs/MiceReading.h>
#include <ros/time.h>
#include <rosbag/bag.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "mrt_common/angle.h"
#include "mrt_mice/mice_io.h"
#include "sim_protocol.h"

using namespace mrt::mice;

namespace {

TEST(MiceCalibrateBags, RecoversMiceFromSimulatedBags) {
  ros::Time::init();
  sim::SimMice m;
  m.truth.left.mount = Pose2D(0.11, 0.09, mrt::common::deg_to_rad(1.5));
  m.truth.left.counts_per_m = 16100;
  m.truth.right.mount = Pose2D(-0.13, 0.05, mrt::common::deg_to_rad(-2.0));
  m.truth.right.counts_per_m = 15500;
  mrt::sim::Simulator s(sim::make_world(m, 4));
  const std::string dir = ::testing::TempDir() + "mrt_mice_" + std::to_string(::getpid()) + "_";
  std::string args;
  sim::settle(s, nullptr);
  for (int k = 0; k < 6; ++k) {
    const bool push = k < 4;
    const std::string path = dir + "mrt_mice_run" + std::to_string(k) + ".bag";
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    auto rec = [&](const mrt::sim::RobotState& r) {
      mrt_msgs::MiceReading msg;
      msg.header.stamp = ros::Time(1.0 + s.time());
      msg.left.dx = r.mice.left_dx;
      msg.left.dy = r.mice.left_dy;
      msg.right.dx = r.mice.right_dx;
      msg.right.dy = r.mice.right_dy;
      bag.write("/robot1/mice", msg.header.stamp, msg);
    };
    if (push)
      sim::drive(s, {0.25, 0.0, 0.0}, 2000, rec);
    else
      sim::drive(s, {0.0, 0.0, M_PI / 2}, 4000, rec);
    sim::settle(s, rec);
    bag.close();
    args += (push ? " --push-bag " : " --turn-bag ") + path;
  }
  const std::string out = dir + "mrt_mice_bags.yaml";
  const std::string tool = std::string(MRT_MICE_TOOL_DIR) + "/mice_calibrate";
  int st = std::system((tool + args + " --topic robot1/mice --out " + out + " > /dev/null").c_str());
  ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0);
  const MiceParams p = load_params(out);
  EXPECT_NEAR(p.distance(), m.truth.distance(), 0.005 * m.truth.distance());
  EXPECT_NEAR(p.left.counts_per_m, 16100, 0.005 * 16100);
  EXPECT_NEAR(p.right.mount.theta, m.truth.right.mount.theta, mrt::common::deg_to_rad(0.2));
  // A bag without readings is bad input.
  {
    rosbag::Bag empty(dir + "mrt_mice_empty.bag", rosbag::bagmode::Write);
  }
  st = std::system((tool + args + " --push-bag " + dir + "mrt_mice_empty.bag --out " + out + " 2>/dev/null").c_str());
  EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 2);
}

}  // namespace
