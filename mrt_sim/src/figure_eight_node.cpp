// figure_eight_node: drives a robot along a figure eight by publishing
// geometry_msgs/Twist on `cmd_vel`: a full counter-clockwise circle of
// ~radius at ~speed, then a full clockwise one, tangent at the start point.
// Runs on ROS time, so under /use_sim_time it follows the simulator's clock.
#include <cmath>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

namespace {

constexpr double kTwoPi = 6.283185307179586;

double positive_param(ros::NodeHandle& pnh, const std::string& name, double fallback) {
  double v = fallback;
  pnh.param(name, v, fallback);
  if (!(v > 0.0) || !std::isfinite(v)) {
    ROS_FATAL("bad parameter ~%s: must be a finite number > 0, got %g", name.c_str(), v);
    ros::shutdown();
    std::exit(1);
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "figure_eight");
  ros::NodeHandle nh, pnh("~");
  const double speed = positive_param(pnh, "speed", 0.6);    // m/s
  const double radius = positive_param(pnh, "radius", 1.5);  // m
  const double rate = positive_param(pnh, "rate", 20.0);     // Hz
  ros::Publisher pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);

  if (!ros::Time::waitForValid()) return 0;  // the simulator's first /clock
  const ros::Time start = ros::Time::now();
  const double loop = kTwoPi * radius / speed;  // time of one circle, s
  ROS_INFO("figure eight: speed %.2f m/s, radius %.2f m, %.1f s per loop", speed, radius, loop);

  ros::Rate r(rate);
  while (ros::ok()) {
    const double t = (ros::Time::now() - start).toSec();
    const bool first_circle = std::fmod(t, 2.0 * loop) < loop;
    geometry_msgs::Twist cmd;
    cmd.linear.x = speed;
    cmd.angular.z = (first_circle ? 1.0 : -1.0) * speed / radius;
    pub.publish(cmd);
    ros::spinOnce();
    r.sleep();
  }
  // Stop the robot on the way out.
  pub.publish(geometry_msgs::Twist());
  return 0;
}
