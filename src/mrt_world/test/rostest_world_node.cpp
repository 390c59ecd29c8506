// world_node publishes the two test rooms at 0.5 m as a latched
// nav_msgs/OccupancyGrid: 20 x 10 cells from (0, 0) in `map`, 76 occupied
// (counted by hand in test_occupancy_map.cpp), the rest free; and the
// metadata alike; the static_map service answers the same map.
#include <gtest/gtest.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "mrt_common_ros/rostest_helpers.h"

TEST(WorldNode, PublishesTheLatchedMap) {
  ros::NodeHandle nh;
  nav_msgs::OccupancyGrid map;
  nav_msgs::MapMetaData meta;
  bool got_map = false, got_meta = false;
  auto s1 = nh.subscribe<nav_msgs::OccupancyGrid>("map", 1, [&](const auto& m) { map = *m, got_map = true; });
  auto s2 = nh.subscribe<nav_msgs::MapMetaData>("map_metadata", 1, [&](const auto& m) { meta = *m, got_meta = true; });
  ASSERT_TRUE(mrt::ros_common::wait_for([&] { return got_map && got_meta; }, 20.0));
  EXPECT_EQ(map.header.frame_id, "map");
  EXPECT_EQ(map.info.width, 20u);
  EXPECT_EQ(map.info.height, 10u);
  EXPECT_FLOAT_EQ(map.info.resolution, 0.5f);
  EXPECT_DOUBLE_EQ(map.info.origin.position.x, 0.0);
  ASSERT_EQ(map.data.size(), 200u);
  EXPECT_EQ(std::count(map.data.begin(), map.data.end(), 100), 76);
  EXPECT_EQ(std::count(map.data.begin(), map.data.end(), 0), 124);
  EXPECT_EQ(map.data[0], 100);        // the corner cell, on the outer walls
  EXPECT_EQ(map.data[1 * 20 + 1], 0); // (0.75, 0.75): inside the west room
  EXPECT_EQ(meta.width, 20u);
  nav_msgs::GetMap srv;
  ASSERT_TRUE(ros::service::waitForService("static_map", 10000));
  ASSERT_TRUE(ros::service::call("static_map", srv));
  EXPECT_EQ(srv.response.map.info.width, 20u);
  EXPECT_EQ(srv.response.map.header.frame_id, "map");
  EXPECT_EQ(srv.response.map.data, map.data);
}

// A node that stops on bad input says why (run_node's ROS_FATAL: its
// NodeHandles' shutdown used to silence it) and exits 1.
TEST(WorldNode, BadMapFileIsNamedOnStderr) {
  const std::string cmd = std::string(WORLD_NODE) + " __name:=bad_world _map:=/nonexistent/museum.yaml 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  const int status = pclose(p);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
  EXPECT_NE(out.find("[FATAL]"), std::string::npos) << out;
  EXPECT_NE(out.find("/nonexistent/museum.yaml"), std::string::npos) << out;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rostest_world_node");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
