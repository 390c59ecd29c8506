// pose_odometry_node: MUREA's pose (geometry_msgs/PoseWithCovarianceStamped
// on `pose`) republished as nav_msgs/Odometry on `odometry` (same header,
// pose and covariance; child frame ~child_frame, twist zero with unknown
// covariance -1), for the nodes that take the robot's pose as Odometry
// (scare_coordinator's `pose`). One per robot, in its namespace
// (robot.launch). The bringup's node: README "The RoboCup bringup".
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "mrt_common_ros/params.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "pose_odometry");
  return mrt::ros_common::run_node([]() -> int {
    ros::NodeHandle nh, pnh("~");
    std::string child;
    mrt::ros_common::ParamReader(pnh).get("child_frame", child);
    ros::Publisher pub = nh.advertise<nav_msgs::Odometry>("odometry", 10);
    ros::Subscriber sub = nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
        "pose", 10, [&](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
          nav_msgs::Odometry o;
          o.header = m->header;
          o.child_frame_id = child;
          o.pose = m->pose;
          o.twist.covariance[0] = -1.0;  // REP-145 style: the twist is unknown
          pub.publish(o);
        });
    ros::spin();
    return 0;
  });
}
