// figure_eight_node: drives a robot along a figure eight by publishing
// geometry_msgs/Twist on `cmd_vel`: a full counter-clockwise circle of
// ~radius at ~speed, then a full clockwise one, tangent at the start point.
// Runs on ROS time, so under /use_sim_time it follows the simulator's clock.
// Diagnostics "figure eight": no input (it only commands), the commands
// published and the circles driven, the current circle's direction.
#include <cmath>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"

namespace {

constexpr double kTwoPi = 6.283185307179586;

struct Options {
  double speed = 0.6;   // ~speed, m/s
  double radius = 1.5;  // ~radius, m
  double rate = 20.0;   // ~rate, Hz
};

int run(const Options& o);

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "figure_eight");
  return mrt::ros_common::run_node([] {
    Options o;
    mrt::ros_common::ParamReader(ros::NodeHandle("~"))
        .get_positive("speed", o.speed)
        .get_positive("radius", o.radius)
        .get_positive("rate", o.rate);
    return run(o);
  });
}

namespace {

int run(const Options& o) {
  const double speed = o.speed, radius = o.radius, rate = o.rate;
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);

  if (!ros::Time::waitForValid()) return 0;  // the simulator's first /clock
  const ros::Time start = ros::Time::now();
  const double loop = kTwoPi * radius / speed;  // time of one circle, s
  ROS_INFO("figure eight: speed %.2f m/s, radius %.2f m, %.1f s per loop", speed, radius, loop);
  bool first_circle = true;
  double t = 0.0;
  mrt::ros_common::NodeDiagnostics diag(nh, "figure eight", "simulation", [&](auto& st) {
    st.add("speed (m/s)", speed);
    st.add("radius (m)", radius);
    st.add("circles driven", static_cast<long>(t / loop));
    st.add("circle", first_circle ? "counter-clockwise" : "clockwise");
  });

  ros::Rate r(rate);
  while (ros::ok()) {
    t = (ros::Time::now() - start).toSec();
    first_circle = std::fmod(t, 2.0 * loop) < loop;
    geometry_msgs::Twist cmd;
    cmd.linear.x = speed;
    cmd.angular.z = (first_circle ? 1.0 : -1.0) * speed / radius;
    pub.publish(cmd);
    diag.count("commands published");
    ros::spinOnce();
    r.sleep();
  }
  // Stop the robot on the way out.
  pub.publish(geometry_msgs::Twist());
  return 0;
}

}  // namespace
