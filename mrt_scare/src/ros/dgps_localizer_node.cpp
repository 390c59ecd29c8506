// dgps_localizer_node: Roby's pose from the DGPS fix and the wheel encoders.
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/NavSatFix.h>

#include <cmath>

#include "mrt_common/angle.h"
#include "mrt_scare/dgps_localizer.h"

namespace {

using mrt::common::deg_to_rad;
constexpr double kEarthRadius = 6378137.0;  // m, as mrt_sim's equirectangular projection

class LocalizerNode {
 public:
  LocalizerNode(ros::NodeHandle& nh, mrt::scare::DgpsLocalizer loc, double lat0, double lon0, double r,
                double track, std::string frame, std::string child)
      : loc_(loc), lat0_(lat0), lon0_(lon0), r_(r), track_(track), frame_(std::move(frame)),
        child_(std::move(child)) {
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
    const double y = deg_to_rad(f.latitude - lat0_) * kEarthRadius;
    const double x = deg_to_rad(f.longitude - lon0_) * kEarthRadius * std::cos(deg_to_rad(lat0_));
    loc_.correct(x, y);
    publish(f.header.stamp);
  }

  void on_wheels(const mrt_msgs::WheelState& w) {
    if (w.speed.size() != 2 || !std::isfinite(w.speed[0]) || !std::isfinite(w.speed[1])) {
      ROS_WARN_THROTTLE(5, "dropped a wheel state that is not [left, right]");
      return;
    }
    const ros::Time t = w.header.stamp;
    if (!last_.isZero() && t > last_) {
      const double vx = r_ * (w.speed[0] + w.speed[1]) / 2.0;
      const double om = r_ * (w.speed[1] - w.speed[0]) / track_;
      loc_.predict(vx, om, (t - last_).toSec());
      vx_ = vx;
      om_ = om;
    }
    last_ = t;
    publish(t);
  }

  void publish(const ros::Time& t) {
    nav_msgs::Odometry o;
    o.header.stamp = t;
    o.header.frame_id = frame_;
    o.child_frame_id = child_;
    const auto& p = loc_.pose();
    o.pose.pose.position.x = p.x;
    o.pose.pose.position.y = p.y;
    o.pose.pose.orientation.z = std::sin(p.theta / 2.0);
    o.pose.pose.orientation.w = std::cos(p.theta / 2.0);
    o.twist.twist.linear.x = vx_;
    o.twist.twist.angular.z = om_;
    pub_.publish(o);
  }

  mrt::scare::DgpsLocalizer loc_;
  double lat0_, lon0_, r_, track_;
  std::string frame_, child_;
  ros::Time last_;
  double vx_ = 0.0, om_ = 0.0;
  ros::Publisher pub_;
  ros::Subscriber fix_sub_, wheel_sub_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "dgps_localizer");
  ros::NodeHandle nh, pnh("~");
  std::vector<double> initial{0.0, 0.0, 0.0}, datum{45.478, 9.227};
  double r, track;
  std::string frame, child;
  pnh.getParam("initial_pose", initial);
  pnh.getParam("datum", datum);
  pnh.param("wheel_radius", r, 0.11);
  pnh.param("track", track, 0.40);
  pnh.param<std::string>("frame", frame, "world");
  pnh.param<std::string>("child_frame", child, "base_link");
  if (initial.size() != 3) {
    ROS_FATAL("bad parameter ~initial_pose: expected [x, y, theta_deg]");
    return 1;
  }
  if (datum.size() != 2 || std::fabs(datum[0]) >= 90.0) {
    ROS_FATAL("bad parameter ~datum: expected [latitude, longitude] in degrees, |latitude| < 90");
    return 1;
  }
  if (!(r > 0) || !(track > 0)) {
    ROS_FATAL("bad parameter ~wheel_radius or ~track: must be > 0");
    return 1;
  }
  mrt::scare::DgpsLocalizer loc(mrt::common::Pose2D(initial[0], initial[1], deg_to_rad(initial[2])));
  LocalizerNode node(nh, loc, datum[0], datum[1], r, track, frame, child);
  ros::spin();
  return 0;
}
