// dgps_localizer_node: Roby's pose from the DGPS fix and the wheel encoders.
// Wiring only: the projection, the kinematics and the filter are the core's
// DgpsLocalizer.
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <mrt_msgs/WheelState.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/NavSatFix.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <stdexcept>

#include "mrt_common/angle.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_roby/dgps_localizer.h"

namespace {

using mrt::roby::DgpsLocalizer;

struct Frames {
  std::string frame = "map", odom;  // odom empty: no map -> odom tf
};

class LocalizerNode {
 public:
  LocalizerNode(ros::NodeHandle& nh, DgpsLocalizer loc, Frames f) : loc_(std::move(loc)), f_(std::move(f)) {
    pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("pose", 20);
    fix_sub_ = nh.subscribe("dgps/fix", 5, &LocalizerNode::on_fix, this);
    wheel_sub_ = nh.subscribe("wheel_state", 50, &LocalizerNode::on_wheels, this);
    if (!f_.odom.empty()) odom_sub_ = nh.subscribe("odom", 50, &LocalizerNode::on_odom, this);
    diag_.setHardwareID("DGPS");
    diag_.add("DGPS localizer", this, &LocalizerNode::diagnose);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
  }

 private:
  void on_fix(const sensor_msgs::NavSatFix& f) {
    const bool known = f.position_covariance_type != sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
    const double var = loc_.fix_variance(f.status.status, known, f.position_covariance[0], f.position_covariance[4]);
    if (var < 0.0 || !std::isfinite(f.latitude) || !std::isfinite(f.longitude)) {
      ++fixes_dropped_;
      ROS_WARN_THROTTLE(5, "dropped a DGPS message without a fix (%d dropped)", fixes_dropped_);
      return;
    }
    loc_.correct(mrt::common::GeoPoint{f.latitude, f.longitude}, var);
    last_fix_ = ros::Time::now();
    last_fix_status_ = f.status.status;
    last_fix_var_ = var;
    publish(f.header.stamp);
  }

  void on_wheels(const mrt_msgs::WheelState& w) {
    if (w.speed.size() != 2 || !std::isfinite(w.speed[0]) || !std::isfinite(w.speed[1])) {
      ++wheels_dropped_;
      ROS_WARN_THROTTLE(5, "dropped a wheel state that is not [left, right]");
      return;
    }
    loc_.wheel_state(w.speed[0], w.speed[1], w.header.stamp.toSec());
    publish(w.header.stamp);
  }

  // REP-105: the odometry gives odom -> base_link; this node publishes
  // map -> odom = (map -> base_link) * (odom -> base_link)^-1.
  void on_odom(const nav_msgs::Odometry& o) {
    odom_pose_ = mrt::ros_common::to_pose2d(o.pose.pose);
    have_odom_ = true;
  }

  // The estimate as the stack's localizers give it (MUREA too): the pose in
  // ~frame with the filter's planar covariance (z, roll, pitch 0: not given).
  void publish(const ros::Time& t) {
    geometry_msgs::PoseWithCovarianceStamped m;
    m.header.stamp = t;
    m.header.frame_id = f_.frame;
    m.pose.pose = mrt::ros_common::to_pose(loc_.pose());
    mrt::ros_common::set_planar_covariance(loc_.covariance(), m.pose.covariance);
    pub_.publish(m);
    if (have_odom_ && t > last_tf_) {
      const mrt::common::Pose2D map_odom = loc_.pose() * odom_pose_.inverse();
      tf_.sendTransform(mrt::ros_common::to_transform(map_odom, f_.frame, f_.odom, t));
      last_tf_ = t;
    }
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    const double age = last_fix_.isZero() ? -1.0 : (ros::Time::now() - last_fix_).toSec();
    if (loc_.fixes() == 0)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no DGPS fix yet: dead reckoning");
    else if (age > 5.0)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no DGPS fix for more than 5 s: dead reckoning");
    else if (last_fix_status_ < sensor_msgs::NavSatStatus::STATUS_GBAS_FIX)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "fix without differential correction");
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "differential fixes");
    const auto c = loc_.covariance();
    st.add("fixes", loc_.fixes());
    st.add("fixes dropped", fixes_dropped_);
    st.add("wheel states dropped", wheels_dropped_);
    st.add("last fix age (s)", age);
    st.add("last fix status", last_fix_status_);
    st.add("last fix sigma (m)", std::sqrt(std::max(last_fix_var_, 0.0)));
    st.add("position sigma (m)", std::sqrt(c[0]));
    st.add("heading sigma (deg)", std::sqrt(c[8]) * 180.0 / M_PI);
    st.add("map -> odom tf", have_odom_ ? "published" : (f_.odom.empty() ? "off" : "waiting for odom"));
  }

  DgpsLocalizer loc_;
  Frames f_;
  ros::Publisher pub_;
  ros::Subscriber fix_sub_, wheel_sub_, odom_sub_;
  tf2_ros::TransformBroadcaster tf_;
  mrt::common::Pose2D odom_pose_;
  bool have_odom_ = false;
  ros::Time last_tf_, last_fix_;
  int last_fix_status_ = -1;
  double last_fix_var_ = -1.0;
  int fixes_dropped_ = 0, wheels_dropped_ = 0;
  diagnostic_updater::Updater diag_;
  ros::Timer diag_timer_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "dgps_localizer");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader p(pnh);
    std::vector<double> initial{0.0, 0.0, 0.0}, datum{45.478, 9.227};
    Frames fr;
    mrt::roby::DgpsLocalizerOptions o;
    p.get("initial_pose", initial)
        .get("datum", datum)
        .get_positive("wheel_radius", o.wheel_radius)
        .get_positive("track", o.track)
        .get("frame", fr.frame)
        .get("odom_frame", fr.odom)
        .get_positive("sigma_gbas", o.sigma_gbas)
        .get_positive("sigma_sbas", o.sigma_sbas)
        .get_positive("sigma_fix", o.sigma_fix);
    p.check(initial.size() == 3, "initial_pose", "[x, y, theta] (m, m, rad)");
    p.check(datum.size() == 2, "datum", "[latitude, longitude] in degrees");
    o.datum = {datum[0], datum[1]};
    try {
      o.validate();
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("~") + e.what());
    }
    const mrt::common::Pose2D start(initial[0], initial[1], initial[2]);
    LocalizerNode node(nh, DgpsLocalizer(start, o), fr);
    ros::spin();
    return 0;
  });
}
