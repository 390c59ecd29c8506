// mice_odometry_node: raw readings of the two mice -> nav_msgs/Odometry,
// tf odom -> base_link (optional), error statistics and diagnostics.
// The node is wiring: parameters are read once into the core's structs,
// messages are converted at the boundary, all the work is MiceOdometry's.
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/TransformStamped.h>
#include <mrt_msgs/MiceErrorStats.h>
#include <mrt_msgs/MiceReading.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_mice/mice_io.h"
#include "mrt_mice/mice_odometry.h"

namespace mrt::mice::node {
namespace {

using mrt::ros_common::ParamReader;

struct NodeOptions {
  std::string params_file;  // ~params_file (required)
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  std::string frame_prefix;  // ~frame_prefix, e.g. "robot1/"
  bool publish_tf = false;
  int max_count = 100000;    // ~max_count: larger |counts| in one sample are malformed
  double stale_timeout = 0.25;  // ~stale_timeout: s without readings before diagnostics say so
  double time_jump_reset = 1.0;  // ~time_jump_reset: a stamp this far back (s) resets the odometry
  OdometryOptions odometry;
};

NodeOptions load_options(const ros::NodeHandle& pnh) {
  NodeOptions o;
  ParamReader p(pnh);
  p.require("params_file", o.params_file, "the path of the mice YAML parameter file")
      .get("odom_frame", o.odom_frame)
      .get("base_frame", o.base_frame)
      .get("frame_prefix", o.frame_prefix)
      .get("publish_tf", o.publish_tf)
      .get_positive("max_count", o.max_count)
      .get_positive("stale_timeout", o.stale_timeout)
      .get_positive("time_jump_reset", o.time_jump_reset)
      .get("reduce_errors", o.odometry.reduce_errors)
      .get("var_xy_per_m", o.odometry.var_xy_per_m)
      .get("var_theta_per_rad", o.odometry.var_theta_per_rad)
      .get("var_theta_per_m", o.odometry.var_theta_per_m)
      .get("flagged_gain", o.odometry.flagged_gain);
  ParamReader::check(!o.params_file.empty(), "params_file", "the path of the mice YAML parameter file");
  ParamReader::check(!o.odom_frame.empty(), "odom_frame", "a non-empty frame id");
  ParamReader::check(!o.base_frame.empty(), "base_frame", "a non-empty frame id");
  try {
    o.odometry.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("~") + e.what());
  }
  return o;
}

class MiceOdometryNode {
 public:
  MiceOdometryNode(ros::NodeHandle& nh, ros::NodeHandle& pnh)
      : opt_(load_options(pnh)),
        odo_(load_params(opt_.params_file), opt_.odometry),
        odom_frame_(opt_.frame_prefix + opt_.odom_frame),
        base_frame_(opt_.frame_prefix + opt_.base_frame) {
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 50);
    stats_pub_ = nh.advertise<mrt_msgs::MiceErrorStats>("mice_errors", 50);
    if (opt_.publish_tf) tf_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    sub_ = nh.subscribe("mice", 100, &MiceOdometryNode::on_mice, this);
    diag_.setHardwareID("mice_odometry");
    diag_.add("mice odometry", this, &MiceOdometryNode::diagnose);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
    const ManualGeometry g = manual_geometry(odo_.model().params());
    ROS_INFO("mice_odometry: %s, D = %.1f mm, delta = %.2f deg, publishing %s -> %s%s",
             opt_.params_file.c_str(), g.D * 1000.0, g.delta * 180.0 / M_PI, odom_frame_.c_str(),
             base_frame_.c_str(), opt_.publish_tf ? " with tf" : "");
  }

 private:
  void on_mice(const mrt_msgs::MiceReading::ConstPtr& m) {
    const long long lim = opt_.max_count;
    auto bad = [lim](long long v) { return v > lim || v < -lim; };
    if (bad(m->left.dx) || bad(m->left.dy) || bad(m->right.dx) || bad(m->right.dy)) {
      ++dropped_;
      ROS_WARN_THROTTLE(5.0, "mice_odometry: dropped a reading with |counts| > %d (%llu dropped)",
                        opt_.max_count, static_cast<unsigned long long>(dropped_));
      return;
    }
    ros::Time stamp = m->header.stamp.isZero() ? ros::Time::now() : m->header.stamp;
    if (have_last_ && stamp < last_stamp_) {
      if ((last_stamp_ - stamp).toSec() > opt_.time_jump_reset) {
        // Time jumped back (a bag played in a loop, the simulator
        // restarted): start again from the origin instead of dropping
        // every reading until time passes the old stamp.
        ++resets_;
        ROS_WARN("mice_odometry: time jumped back %.3f s; odometry reset (%llu resets)",
                 (last_stamp_ - stamp).toSec(), static_cast<unsigned long long>(resets_));
        odo_.reset();
        have_last_ = false;
      } else {
        ++dropped_;
        ++out_of_order_;
        ROS_WARN_THROTTLE(5.0, "mice_odometry: dropped a reading older than the previous one");
        return;
      }
    } else if (have_last_ && stamp == last_stamp_) {
      // The same instant twice: a duplicated message (a bag written twice,
      // a driver resending); integrating it would count its motion twice.
      ++duplicates_;
      ROS_WARN_THROTTLE(5.0, "mice_odometry: dropped a reading stamped like the previous one");
      return;
    }
    MiceCounts c;
    c.left_dx = m->left.dx;
    c.left_dy = m->left.dy;
    c.right_dx = m->right.dx;
    c.right_dy = m->right.dy;
    const StepResult r = odo_.update(c);
    // No twist across a gap in the readings: the sample after it need not
    // cover the whole gap (the driver drops what a mouse did while the
    // other was unplugged).
    double dt = have_last_ ? (stamp - last_stamp_).toSec() : 0.0;
    if (dt > opt_.stale_timeout) {
      dt = 0.0;
      ++gaps_;
    }
    have_last_ = true;
    last_stamp_ = stamp;
    last_wall_ = ros::WallTime::now();
    publish(stamp, r, dt);
  }

  void publish(const ros::Time& stamp, const StepResult& r, double dt) {
    namespace rc = mrt::ros_common;
    const Pose2D& p = odo_.pose();
    const double k = dt > 0.0 ? 1.0 / dt : 0.0;
    nav_msgs::Odometry o = rc::to_odometry(p, r.delta.x * k, r.delta.y * k, r.delta.theta * k, odom_frame_,
                                           base_frame_, stamp);
    // 6x6 (x, y, z, roll, pitch, yaw); z, roll and pitch are not measured.
    rc::set_planar_covariance(odo_.covariance(), o.pose.covariance, 1e6);
    odom_pub_.publish(o);
    if (tf_) tf_->sendTransform(rc::to_transform(p, odom_frame_, base_frame_, stamp));
    const ErrorStats& s = odo_.stats();
    mrt_msgs::MiceErrorStats e;
    e.header = o.header;
    e.residual = r.detection.residual;
    e.threshold = r.detection.threshold;
    e.flagged = r.detection.flagged;
    e.correction = to_string(r.reduction.correction);
    e.samples = s.samples;
    e.flagged_samples = s.flagged;
    e.corrected_samples = s.corrected;
    e.uncorrectable_samples = s.uncorrectable;
    e.rms_residual = s.rms_residual();
    e.max_abs_residual = s.max_abs_residual;
    e.distance = odo_.distance();
    stats_pub_.publish(e);
  }

  static std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", s);
    return buf;
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    const ErrorStats& s = odo_.stats();
    const double age = have_last_ ? (ros::WallTime::now() - last_wall_).toSec() : -1.0;
    const double rate = s.samples ? static_cast<double>(s.flagged) / s.samples : 0.0;
    if (!have_last_)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no readings yet");
    else if (age > opt_.stale_timeout)
      // The pose is kept as it was, not extrapolated.
      st.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "no mice readings for " + seconds(age) + " s");
    else if (rate > 0.2)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "many samples flagged as erroneous");
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
    st.add("samples", s.samples);
    st.add("flagged", s.flagged);
    st.add("corrected", s.corrected);
    st.add("uncorrectable", s.uncorrectable);
    st.add("dropped (malformed)", dropped_);
    st.add("resets (time jumped back)", resets_);
    st.add("out-of-order stamps (dropped)", out_of_order_);
    st.add("duplicate stamps (dropped)", duplicates_);
    st.add("stamp gaps (no twist)", gaps_);
    st.add("rms residual (m)", s.rms_residual());
    st.add("distance (m)", odo_.distance());
    st.add("seconds since last reading", age);
  }

  NodeOptions opt_;
  MiceOdometry odo_;
  std::string odom_frame_, base_frame_;
  ros::Publisher odom_pub_, stats_pub_;
  ros::Subscriber sub_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_;
  diagnostic_updater::Updater diag_;
  ros::Timer diag_timer_;
  bool have_last_ = false;
  ros::Time last_stamp_;
  ros::WallTime last_wall_;
  std::uint64_t dropped_ = 0;
  std::uint64_t resets_ = 0;
  std::uint64_t out_of_order_ = 0, duplicates_ = 0, gaps_ = 0;
};

}  // namespace
}  // namespace mrt::mice::node

int main(int argc, char** argv) {
  ros::init(argc, argv, "mice_odometry");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::mice::node::MiceOdometryNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
