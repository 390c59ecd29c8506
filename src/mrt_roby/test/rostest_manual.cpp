// Manual mode (the Status flag of manual §10.4.10): Roby follows the remote
// controller, and AvoidObstacle still refuses to drive it into the wall.
#include <geometry_msgs/Twist.h>
#include <std_msgs/String.h>

#include <cmath>

#include "roby_observer.h"

namespace {
// Drives with a constant remote command for `seconds` of sim time at 10 Hz.
void drive(roby_test::Observer& obs, ros::Publisher& pub, double v, double w, double seconds) {
  geometry_msgs::Twist t;
  t.linear.x = v;
  t.angular.z = w;
  const ros::Time end = ros::Time::now() + ros::Duration(seconds);
  ros::Time next = ros::Time::now();
  obs.wait([&] {
    if (ros::Time::now() >= next) {
      pub.publish(t);
      next = ros::Time::now() + ros::Duration(0.1);
    }
    return ros::Time::now() >= end;
  }, seconds + 1.0, 120.0);
}
}  // namespace

TEST(RobyManual, FollowsRemoteButRefusesObstacle) {
  ros::NodeHandle nh, pnh("~");
  std::string world;
  ASSERT_TRUE(pnh.getParam("world", world));
  roby_test::Observer obs(world);
  ros::Publisher remote = nh.advertise<geometry_msgs::Twist>("remote_cmd", 10);
  ASSERT_TRUE(obs.wait([&] { return obs.truths_ > 0 && obs.last_.mode == "manual"; }, 20.0, 60.0))
      << "not in manual mode";
  // The sequencer starts in Manual (~mode): the planner's path point (3, 0)
  // is ahead, but nothing drives there on its own: without remote commands
  // the robot stands still.
  obs.wait([] { return false; }, 3.0, 30.0);
  EXPECT_LT(std::hypot(obs.x_, obs.y_), 0.02) << "drove off without a remote command";
  EXPECT_EQ(obs.last_.reached, 0u);

  // Backing up is allowed, but not into the wall 1.6 m behind: the robot
  // stops (after 12 s at 0.2 m/s it would be 0.8 m past the wall).
  drive(obs, remote, -0.2, 0.0, 12.0);
  const double x_back = obs.x_;
  EXPECT_LT(x_back, -0.3) << "did not back up";
  drive(obs, remote, -0.2, 0.0, 2.0);
  EXPECT_NEAR(obs.x_, x_back, 0.05) << "still backing into the wall";
  EXPECT_GE(obs.min_clearance_, 0.3) << "nearest: " << obs.nearest_;
  const double back_clearance = obs.min_clearance_;

  // Follows the remote: forward and left, then forward and right.
  const double x_start = obs.x_;
  drive(obs, remote, 0.3, 0.3, 2.0);
  const double th_left = obs.theta_, x_left = obs.x_;
  EXPECT_GT(th_left, 0.3) << "did not turn left";
  EXPECT_GT(x_left, x_start + 0.2) << "did not move forward";
  drive(obs, remote, 0.3, -0.3, 2.0);
  EXPECT_LT(obs.theta_, th_left - 0.3) << "did not turn right";
  EXPECT_GT(obs.x_, x_left + 0.2);

  // Then full speed at the wall at x = 5 for 25 s: it must stop short of it.
  drive(obs, remote, 0.5, 0.0, 25.0);
  const double x_stopped = obs.x_;
  drive(obs, remote, 0.5, 0.0, 3.0);
  EXPECT_NEAR(obs.x_, x_stopped, 0.05) << "still moving into the wall";
  EXPECT_GT(obs.x_, 3.0) << "stopped too early";
  EXPECT_GE(obs.min_clearance_, 0.3) << "nearest: " << obs.nearest_;

  // Backing away is still allowed.
  drive(obs, remote, -0.2, 0.0, 3.0);
  EXPECT_LT(obs.x_, x_stopped - 0.2) << "did not back away";

  // The operator hands the robot back to Mr. BRIAN.
  ros::Publisher mode = nh.advertise<std_msgs::String>("mode", 1, true);
  std_msgs::String m;
  m.data = "auto";
  mode.publish(m);
  EXPECT_TRUE(obs.wait([&] { return obs.last_.mode == "auto"; }, 5.0, 30.0)) << "did not switch to auto";
  RecordProperty("stopped_at_x", std::to_string(x_stopped));
  RecordProperty("min_clearance_m", std::to_string(obs.min_clearance_));
  RecordProperty("backed_to_x", std::to_string(x_back));
  RecordProperty("min_clearance_backing_m", std::to_string(back_clearance));
  std::printf("manual: backed to x = %.2f (clearance %.3f m); stopped at x = %.2f, min clearance %.3f m (%s)\n",
              x_back, back_clearance, x_stopped, obs.min_clearance_, obs.nearest_.c_str());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "roby_manual_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
