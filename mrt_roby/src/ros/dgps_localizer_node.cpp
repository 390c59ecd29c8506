// dgps_localizer_node: Roby's pose from the DGPS fix and the wheel encoders.
// Wiring only: the projection, the kinematics and the filter are the core's
// DgpsLocalizer.
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/NavSatFix.h>

#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_roby/dgps_localizer.h"

namespace {

using mrt::roby::DgpsLocalizer;

class LocalizerNode {
 public:
  LocalizerNode(ros::NodeHandle& nh, DgpsLocalizer loc, std::string frame, std::string child)
      : loc_(std::move(loc)), frame_(std::move(frame)), child_(std::move(child)) {
    pub_ = nh.advertise<nav_msgs::Odometry>("pose", 20);
    fix_sub_ = nh.subscribe("dgps/fix", 5, &LocalizerNode::on_fix, this);
    wheel_sub_ = nh.subscribe("wheel_state", 50, &LocalizerNode::on_wheels, this);
  }

 private:
  void on_fix(const sensor_msgs::NavSatFix& f) {
    if (f.status.status < sensor_msgs::NavSatStatus::STATUS_FIX || !std::isfinite(f.latitude) ||
        !std::isfinite(f.longitude)) {
      ROS_WARN_THROTTLE(5, "dropped a DGPS message without a fix");
      return;
    }
    loc_.correct(mrt::common::GeoPoint{f.latitude, f.longitude});
    publish(f.header.stamp);
  }

  void on_wheels(const mrt_msgs::WheelState& w) {
    if (w.speed.size() != 2 || !std::isfinite(w.speed[0]) || !std::isfinite(w.speed[1])) {
      ROS_WARN_THROTTLE(5, "dropped a wheel state that is not [left, right]");
      return;
    }
    loc_.wheel_state(w.speed[0], w.speed[1], w.header.stamp.toSec());
    publish(w.header.stamp);
  }

  void publish(const ros::Time& t) {
    const auto& v = loc_.twist();
    pub_.publish(mrt::ros_common::to_odometry(loc_.pose(), v.vx, 0.0, v.omega, frame_, child_, t));
  }

  DgpsLocalizer loc_;
  std::string frame_, child_;
  ros::Publisher pub_;
  ros::Subscriber fix_sub_, wheel_sub_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "dgps_localizer");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader p(pnh);
    std::vector<double> initial{0.0, 0.0, 0.0}, datum{45.478, 9.227};
    std::string frame = "world", child = "base_link";
    mrt::roby::DgpsLocalizerOptions o;
    p.get("initial_pose", initial)
        .get("datum", datum)
        .get_positive("wheel_radius", o.wheel_radius)
        .get_positive("track", o.track)
        .get("frame", frame)
        .get("child_frame", child);
    p.check(initial.size() == 3, "initial_pose", "[x, y, theta_deg]");
    p.check(datum.size() == 2, "datum", "[latitude, longitude] in degrees");
    o.datum = {datum[0], datum[1]};
    try {
      o.validate();
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("~") + e.what());
    }
    const mrt::common::Pose2D start(initial[0], initial[1], mrt::common::deg_to_rad(initial[2]));
    LocalizerNode node(nh, DgpsLocalizer(start, o), frame, child);
    ros::spin();
    return 0;
  });
}
