// brian_cmd_vel_node: Mr. BRIAN's commands as a body twist on cmd_vel, for
// running without the AIRBoard (rostests, a base driven by twist), through
// the one Mr. BRIAN mapping (mrt_common/brian_mapping.h, the AIRBoard
// driver's too; unicycle: Speed cm/s, Jog deg/s).
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/CommandArray.h>
#include <ros/ros.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "mrt_common/brian_mapping.h"
#include "mrt_common_ros/params.h"

namespace {

class CmdVelNode {
 public:
  CmdVelNode(ros::NodeHandle& nh, mrt::common::BrianMappingParams p) : mapping_(std::move(p)) {
    pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    sub_ = nh.subscribe("commands", 10, &CmdVelNode::on_commands, this);
    diag_.setHardwareID("none");
    diag_.add("Mr. BRIAN to cmd_vel", this, &CmdVelNode::diagnose);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
  }

 private:
  void on_commands(const mrt_msgs::CommandArray& m) {
    commands_.clear();
    for (const auto& c : m.commands) commands_.emplace_back(c.name, c.value);
    const auto t = mapping_.to_twist(commands_);  // absent commands are 0
    if (!t) {
      ++dropped_;
      ROS_WARN_THROTTLE(5, "dropped a command array with a non-finite Speed or Jog");
      return;
    }
    ++sent_;
    last_ = ros::Time::now();
    geometry_msgs::Twist out;
    out.linear.x = t->vx;
    out.linear.y = t->vy;
    out.angular.z = t->omega;
    pub_.publish(out);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    const double age = last_.isZero() ? -1.0 : (ros::Time::now() - last_).toSec();
    if (age < 0.0 || age > 1.0)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no commands from Mr. BRIAN for more than 1 s");
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "forwarding");
    st.add("twists sent", sent_);
    st.add("command arrays dropped", dropped_);
    st.add("last command age (s)", age);
  }

  mrt::common::BrianMapping mapping_;
  diagnostic_updater::Updater diag_;
  ros::Timer diag_timer_;
  ros::Time last_;
  int sent_ = 0, dropped_ = 0;
  std::vector<std::pair<std::string, double>> commands_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "brian_cmd_vel");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader p(pnh);
    mrt::common::BrianMappingParams m;  // unicycle: Speed, Jog, cm/s and deg/s to SI
    p.get("speed", m.speed_name)
        .get("jog", m.rotation_name)
        .get("speed_scale", m.speed_scale)
        .get("jog_scale", m.rotation_scale);
    p.check(!m.speed_name.empty(), "speed", "a command name");
    p.check(!m.rotation_name.empty(), "jog", "a command name");
    p.check(std::isfinite(m.speed_scale), "speed_scale", "a finite number");
    p.check(std::isfinite(m.rotation_scale), "jog_scale", "a finite number");
    CmdVelNode node(nh, m);
    ros::spin();
    return 0;
  });
}
