// encoder_odometry_node: the wheel encoders' odometry without the AIRBoard
// (followme.launch airboard:=false, which lets the simulation run faster
// than real time; the AIRBoard emulator runs in real time). Integrates the
// cumulative ticks of wheel_state (mrt_sim's simulated encoders, or any
// driver's) with mrt_common's wheel odometry (wheel_odometry.h) and
// publishes tf <prefix>odom -> <prefix>base_link and odom. The base (wheel
// radius, track, ticks per revolution) is the world file's robot.
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <memory>
#include <string>

#include "mrt_common_ros/conversions.h"
#include "mrt_common/wheel_odometry.h"
#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_msgs/WheelState.h"
#include "mrt_sim/world.h"

namespace {

class EncoderOdometryNode {
 public:
  EncoderOdometryNode(ros::NodeHandle& nh, ros::NodeHandle& pnh) : diag_(nh, "encoder odometry", "encoders") {
    mrt::ros_common::ParamReader p(pnh);
    std::string world, robot = "robot1";
    p.require("world", world, "the mrt_sim world file of the robot's base and encoders").get("robot", robot);
    const mrt::sim::World w = mrt::sim::load_world(world);
    for (const auto& rc : w.robots)
      if (rc.name == robot && rc.sensors.ticks_per_rev > 0)
        odo_ = std::make_unique<mrt::common::WheelOdometry>(rc.base, rc.sensors.ticks_per_rev);
    if (!odo_) throw mrt::ros_common::ParamError("robot", "a robot of ~world with encoders");
    odom_frame_ = robot + "/odom";
    base_frame_ = robot + "/base_link";
    pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    sub_ = nh.subscribe("wheel_state", 20, &EncoderOdometryNode::on_state, this);
    diag_.input("wheel_state", 1.0);
  }

 private:
  void on_state(const mrt_msgs::WheelState& m) {
    diag_.received("wheel_state");
    if (m.ticks.size() != odo_->geometry().wheel_count()) {  // malformed: dropped, the node goes on
      ROS_WARN_THROTTLE(5.0, "wheel_state with %zu ticks for %zu wheels: dropped", m.ticks.size(),
                        odo_->geometry().wheel_count());
      diag_.count("malformed wheel_state dropped");
      return;
    }
    odo_->update(m.ticks);
    tf_.sendTransform(mrt::ros_common::to_transform(odo_->pose(), odom_frame_, base_frame_, m.header.stamp));
    pub_.publish(mrt::ros_common::to_odometry(odo_->pose(), 0.0, 0.0, 0.0, odom_frame_, base_frame_, m.header.stamp));
  }

  std::unique_ptr<mrt::common::WheelOdometry> odo_;
  std::string odom_frame_, base_frame_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
  tf2_ros::TransformBroadcaster tf_;
  mrt::ros_common::NodeDiagnostics diag_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "encoder_odometry");
  ros::NodeHandle nh, pnh("~");
  return mrt::ros_common::run_node([&] {
    EncoderOdometryNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
