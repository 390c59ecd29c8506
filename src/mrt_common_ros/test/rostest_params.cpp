#include <gtest/gtest.h>
#include <ros/ros.h>

#include "mrt_common_ros/params.h"

using mrt::ros_common::ParamError;
using mrt::ros_common::ParamReader;

TEST(ParamReader, ReadsKeepsDefaultsAndNamesTheBadParameter) {
  ParamReader p(ros::NodeHandle("~"));
  double rate = 0.0, absent = 7.5, neg = 0.0;
  int count = 0;
  std::string frame = "odom";
  p.get("rate", rate).get("count", count).get("frame", frame).get("absent", absent);
  EXPECT_EQ(rate, 20.0);
  EXPECT_EQ(count, 3);
  EXPECT_EQ(frame, "map");
  EXPECT_EQ(absent, 7.5);  // the default stays

  try {
    p.get_positive("negative", neg);
    FAIL() << "a negative value passed get_positive";
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "~negative: expected a finite number > 0");
  }
  try {
    double x = 0.0;
    p.get("wrong_type", x);
    FAIL() << "a string was read as a number";
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "~wrong_type: expected a number");
  }
  try {
    std::string s;
    p.require("map_file", s, "the path of the map");
    FAIL() << "a missing required parameter passed";
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "~map_file: expected the path of the map (required)");
  }
  EXPECT_EQ(mrt::ros_common::run_node([] () -> int { throw ParamError("x", "y"); }), 1);
  EXPECT_EQ(mrt::ros_common::run_node([] { return 0; }), 0);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "params_test");
  return RUN_ALL_TESTS();
}
