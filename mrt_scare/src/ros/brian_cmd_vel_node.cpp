// brian_cmd_vel_node: Mr. BRIAN's Speed (cm/s) and Jog (deg/s) as a body
// twist on cmd_vel, for running without the AIRBoard (rostests, a base
// driven by twist).
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/CommandArray.h>
#include <ros/ros.h>

#include <cmath>

namespace {
ros::Publisher pub;
std::string speed_name, jog_name;
double speed_scale, jog_scale;

void on_commands(const mrt_msgs::CommandArray& m) {
  geometry_msgs::Twist t;  // absent commands are 0
  for (const auto& c : m.commands) {
    if (!std::isfinite(c.value)) {
      ROS_WARN_THROTTLE(5, "dropped a non-finite command %s", c.name.c_str());
      continue;
    }
    if (c.name == speed_name) t.linear.x = c.value * speed_scale;
    if (c.name == jog_name) t.angular.z = c.value * jog_scale;
  }
  pub.publish(t);
}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "brian_cmd_vel");
  ros::NodeHandle nh, pnh("~");
  pnh.param<std::string>("speed", speed_name, "Speed");
  pnh.param<std::string>("jog", jog_name, "Jog");
  pnh.param("speed_scale", speed_scale, 0.01);
  pnh.param("jog_scale", jog_scale, M_PI / 180.0);
  if (!std::isfinite(speed_scale) || !std::isfinite(jog_scale)) {
    ROS_FATAL("bad parameter ~speed_scale or ~jog_scale: must be finite");
    return 1;
  }
  pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);
  ros::Subscriber sub = nh.subscribe("commands", 10, on_commands);
  ros::spin();
  return 0;
}
