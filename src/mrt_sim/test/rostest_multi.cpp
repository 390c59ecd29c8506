// rostest of sim_node with several robots (two_robots.yaml, real-time
// factor 4): namespaces and frame prefixes, independent commands, the
// simulated clock running faster than the wall clock; and sim_node on a
// malformed world exiting with status 2 and naming the file and line.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "mrt_common_ros/rostest_helpers.h"

extern char** environ;

namespace {

struct Robot {
  nav_msgs::Odometry first, last;
  int count = 0;
  void on(const nav_msgs::Odometry::ConstPtr& m) {
    if (count++ == 0) first = *m;
    last = *m;
  }
};

TEST(SimMulti, TwoRobotsInTheirNamespacesFasterThanRealTime) {
  ros::NodeHandle nh;
  tf2_ros::Buffer tf_buffer;
  tf2_ros::TransformListener tf_listener(tf_buffer);
  Robot r1, r2;
  ros::Subscriber s1 = nh.subscribe("/robot1/ground_truth", 100, &Robot::on, &r1);
  ros::Subscriber s2 = nh.subscribe("/robot2/ground_truth", 100, &Robot::on, &r2);
  ros::Publisher cmd2 = nh.advertise<geometry_msgs::Twist>("/robot2/cmd_vel", 10);

  mrt::ros_common::wait_for([&] { return r1.count > 0 && r2.count > 0 && cmd2.getNumSubscribers() > 0; }, 30.0);
  ASSERT_GT(r1.count, 0) << "no /robot1/ground_truth";
  ASSERT_GT(r2.count, 0) << "no /robot2/ground_truth";
  EXPECT_EQ(r1.last.child_frame_id, "robot1/base_link_truth");
  EXPECT_EQ(r2.last.child_frame_id, "robot2/base_link_truth");

  // Drive robot2 sideways (a Triskar can) at 0.2 m/s for 3 wall seconds.
  geometry_msgs::Twist t;
  t.linear.y = 0.2;
  const nav_msgs::Odometry r1_start = r1.last, r2_start = r2.last;
  const ros::WallTime w0 = ros::WallTime::now();
  while (ros::ok() && ros::WallTime::now() - w0 < ros::WallDuration(3.0)) {
    cmd2.publish(t);
    ros::spinOnce();
    ros::WallDuration(0.02).sleep();
  }
  const double wall = (ros::WallTime::now() - w0).toSec();
  const double sim = (r2.last.header.stamp - r2_start.header.stamp).toSec();
  // Requested 4x; on a loaded machine it may lag, but it must run ahead of the wall clock.
  EXPECT_GT(sim / wall, 2.0) << "simulated " << sim << " s in " << wall << " s";

  // robot2 moved along +y (the world's y: it faces +x), robot1 stayed put.
  const auto& a = r2_start.pose.pose.position;
  const auto& b = r2.last.pose.pose.position;
  EXPECT_NEAR(b.x - a.x, 0.0, 1e-6);
  EXPECT_GT(b.y - a.y, 0.2 * sim * 0.8);
  EXPECT_NEAR(r1.last.pose.pose.position.x, r1_start.pose.pose.position.x, 1e-9);
  EXPECT_NEAR(r1.last.pose.pose.position.y, r1_start.pose.pose.position.y, 1e-9);

  // Each robot's frames are on the tf tree under the world frame.
  for (const char* f : {"robot1/base_link_truth", "robot2/base_link_truth"}) {
    EXPECT_TRUE(tf_buffer.canTransform("world", f, ros::Time(0), ros::Duration(5.0))) << f;
  }
  const auto tr = tf_buffer.lookupTransform("world", "robot2/base_link_truth", ros::Time(0), ros::Duration(5.0));
  EXPECT_NEAR(tr.transform.translation.x, 0.0, 1e-6);
  EXPECT_GT(tr.transform.translation.y, -3.0 + 0.2 * sim * 0.8);
  std::printf("multi: %.1f simulated s in %.1f wall s (factor %.2f); robot2 moved %.3f m sideways\n", sim, wall,
              sim / wall, b.y - a.y);
}

TEST(SimMulti, MalformedWorldExitsWithTwoNamingFileAndLine) {
  ros::NodeHandle pnh("~");
  std::string bad;
  ASSERT_TRUE(pnh.getParam("bad_world", bad));
  const std::string log = "/tmp/mrt_sim_bad_world_" + std::to_string(::getpid()) + ".log";
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<std::string> args = {"rosrun", "mrt_sim", "sim_node", "__name:=bad_sim", "_world:=" + bad};
  std::vector<char*> argv;
  for (auto& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawnp(&pid, "rosrun", &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  int status = 0;
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(30.0);
  while (waitpid(pid, &status, WNOHANG) != pid) {
    ASSERT_LT(ros::WallTime::now(), end) << "sim_node kept running on a malformed world";
    ros::WallDuration(0.05).sleep();
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  // wrong_type.yaml line 7, column 13: "radius: big".
  EXPECT_NE(text.str().find("wrong_type.yaml:7:13"), std::string::npos) << text.str();
  std::remove(log.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "multi_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
