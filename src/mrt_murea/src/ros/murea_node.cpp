// murea_node: MUREA localization with the interface amcl users know.
// Percepts (mrt_msgs/Percept) and odometry (tf odom -> base_link or a
// nav_msgs/Odometry topic) in; pose (PoseWithCovarianceStamped), tf
// map -> odom, evidence markers and diagnostics out; initialpose,
// global_localization and relocalize. The node is wiring: all the work is
// the core's Tracker.
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "mrt_common_ros/percept_conversions.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_world/occupancy_map.h"
#include "ros/markers.h"
#include "ros/node_options.h"

namespace mrt::murea::node {
namespace {

namespace rc = mrt::ros_common;

class MureaNode {
 public:
  MureaNode(ros::NodeHandle& nh, const ros::NodeHandle& pnh)
      : opt_(read_options(pnh)),
        map_(mrt::world::load_map_world(opt_.map_file)),
        tracker_(map_, opt_.tracker),
        odom_frame_(opt_.frame_prefix + opt_.odom_frame),
        base_frame_(opt_.frame_prefix + opt_.base_frame),
        tf_listener_(tf_buffer_) {
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("pose", 10, true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("evidence_markers", 5);
    percept_sub_ = nh.subscribe("percepts", 10, &MureaNode::on_percept_msg, this);
    if (opt_.odom_topic.empty()) {
      // Odometry from tf: each frame waits in the filter until odom ->
      // base_link is known at its stamp (the odometry may lag the camera).
      tf_filter_ = std::make_unique<tf2_ros::MessageFilter<mrt_msgs::Percept>>(tf_buffer_, odom_frame_, 20, nh);
      tf_filter_->registerCallback([this](const mrt_msgs::Percept::ConstPtr& m) { on_percept(*m); });
      tf_filter_->registerFailureCallback(
          [this](const mrt_msgs::Percept::ConstPtr&, tf2_ros::filter_failure_reasons::FilterFailureReason) {
            no_odometry();
          });
    }
    initial_sub_ = nh.subscribe("initialpose", 2, &MureaNode::on_initial_pose, this);
    if (!opt_.odom_topic.empty()) odom_sub_ = nh.subscribe(opt_.odom_topic, 50, &MureaNode::on_odom, this);
    global_srv_ = nh.advertiseService("global_localization", &MureaNode::on_global, this);
    relocalize_srv_ = nh.advertiseService("relocalize", &MureaNode::on_relocalize, this);
    if (opt_.publish_tf)
      tf_timer_ = nh.createTimer(ros::Duration(1.0 / opt_.tf_rate), [this](const ros::TimerEvent&) { send_tf(); });
    if (opt_.initial_pose) {
      tracker_.set_pose(*opt_.initial_pose, opt_.initial_cov);
      ROS_INFO("murea: initial pose (%.2f, %.2f, %.1f deg) from the parameters", opt_.initial_pose->x,
               opt_.initial_pose->y, opt_.initial_pose->theta * 180 / M_PI);
    }
    diag_.setHardwareID("murea");
    diag_.add("murea localization", this, &MureaNode::diagnose);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
    ROS_INFO("murea: map %s, %.3f m / %.2f deg, timeout %.3f s, odometry from %s, frames %s -> %s -> %s",
             opt_.map_file.c_str(), opt_.tracker.search.accuracy_xy, opt_.tracker.search.accuracy_theta * 180 / M_PI,
             opt_.tracker.search.timeout, opt_.odom_topic.empty() ? "tf" : opt_.odom_topic.c_str(),
             opt_.map_frame.c_str(), odom_frame_.c_str(), base_frame_.c_str());
  }

 private:
  // The odometry pose of base_link at `stamp`: from tf (the filter let the
  // frame through once it was known) or the odometry topic's latest.
  std::optional<Pose2D> odom_at(const ros::Time& stamp) {
    if (!opt_.odom_topic.empty()) return last_odom_msg_;
    try {
      return rc::to_pose2d(transform_to_pose(tf_buffer_.lookupTransform(odom_frame_, base_frame_, stamp)));
    } catch (const tf2::TransformException&) {
      return std::nullopt;
    }
  }

  void no_odometry() {
    ++no_odom_;
    ROS_WARN_THROTTLE(5.0, "murea: no odometry (%s -> %s) at a frame's stamp: frame skipped", odom_frame_.c_str(),
                      base_frame_.c_str());
  }

  static geometry_msgs::Pose transform_to_pose(const geometry_msgs::TransformStamped& t) {
    geometry_msgs::Pose p;
    p.position.x = t.transform.translation.x;
    p.position.y = t.transform.translation.y;
    p.orientation = t.transform.rotation;
    return p;
  }

  // The pose of the percept frame in base_link (identity for base_link).
  std::optional<Pose2D> sensor_mount(const std::string& frame, const ros::Time& stamp) {
    if (frame == base_frame_) return Pose2D();
    try {
      return rc::to_pose2d(transform_to_pose(tf_buffer_.lookupTransform(base_frame_, frame, stamp)));
    } catch (const tf2::TransformException&) {
      return std::nullopt;
    }
  }

  void on_odom(const nav_msgs::Odometry& m) {
    last_odom_msg_ = rc::to_pose2d(m.pose.pose);
    odom_stamp_ = m.header.stamp;
  }

  // A frame in a frame tf does not know is dropped here (it would wait in
  // the filter for ever); the others go to the filter or, with an odometry
  // topic, straight on.
  void on_percept_msg(const mrt_msgs::Percept::ConstPtr& msg) {
    ++frames_;
    if (!sensor_mount(msg->header.frame_id, ros::Time(0))) return drop_frame(*msg);
    if (tf_filter_) tf_filter_->add(msg);
    else on_percept(*msg);
  }

  void drop_frame(const mrt_msgs::Percept& msg) {
    dropped_frame_ += msg.objects.size();
    ROS_WARN_THROTTLE(5.0, "murea: percepts in frame '%s' dropped (no transform to '%s')", msg.header.frame_id.c_str(),
                      base_frame_.c_str());
  }

  void on_percept(const mrt_msgs::Percept& msg) {
    const std::optional<Pose2D> mount = sensor_mount(msg.header.frame_id, msg.header.stamp);
    if (!mount) return drop_frame(msg);
    std::vector<Percept> ps = to_percepts(msg, drops_);
    to_base_frame(ps, *mount);
    const std::optional<Pose2D> odom = odom_at(msg.header.stamp);
    if (!odom) return no_odometry();
    last_percepts_ = ps;
    const auto t0 = std::chrono::steady_clock::now();
    const TrackResult r = track_frame(tracker_, &last_odom_, *odom, ps, opt_);
    last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (r.mode == TrackMode::Tracking) {
      if (tracked_ms_.size() >= 1000) tracked_ms_.erase(tracked_ms_.begin());
      tracked_ms_.push_back(last_ms_);
    }
    last_ = r;
    resolved_ += r.resolved;
    publish(r, msg.header.stamp, *odom);
  }

  void publish(const TrackResult& r, const ros::Time& stamp, const Pose2D& odom) {
    if (!tracker_.tracking()) return;  // lost: keep the last map -> odom
    geometry_msgs::PoseWithCovarianceStamped m;
    m.header.stamp = stamp;
    m.header.frame_id = opt_.map_frame;
    m.pose.pose = rc::to_pose(r.pose);
    rc::set_planar_covariance(r.covariance, m.pose.covariance);
    pose_pub_.publish(m);
    map_to_odom_ = r.pose * odom.inverse();
    if (opt_.publish_tf) send_tf();
    if (markers_pub_.getNumSubscribers() > 0)
      markers_pub_.publish(evidence_markers(r, tracker_, opt_.map_frame, stamp));
  }

  void send_tf() {
    if (!map_to_odom_) return;
    const ros::Time stamp = ros::Time::now() + ros::Duration(opt_.transform_tolerance);
    if (stamp <= last_tf_stamp_) return;  // once per time stamp (tf2 ignores repeats)
    last_tf_stamp_ = stamp;
    tf_broadcaster_.sendTransform(rc::to_transform(*map_to_odom_, opt_.map_frame, odom_frame_, stamp));
  }

  void on_initial_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    Covariance3 c{};
    static constexpr int kIdx[3] = {0, 1, 5};
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) c[3 * r + k] = m.pose.covariance[kIdx[r] * 6 + kIdx[k]];
    tracker_.set_pose(rc::to_pose2d(m.pose.pose), c);
    ROS_INFO("murea: initial pose (%.2f, %.2f, %.1f deg)", m.pose.pose.position.x, m.pose.pose.position.y,
             rc::quaternion_to_yaw(m.pose.pose.orientation) * 180 / M_PI);
  }

  bool on_global(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    tracker_.reset();
    ROS_INFO("murea: global localization requested");
    return true;
  }

  // One-shot: a global search on the last frame of percepts, now.
  bool on_relocalize(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    tracker_.reset();
    const TrackResult r = tracker_.update(last_percepts_);
    char buf[200];
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.2f deg) evidence %.2f of %.2f%s", r.pose.x, r.pose.y,
                  r.pose.theta * 180 / M_PI, r.search.best.evidence, r.max_evidence,
                  r.search.ambiguous ? ", ambiguous" : "");
    res.success = tracker_.tracking();
    res.message = res.success ? buf : std::string("not localized: ") + buf;
    last_ = r;
    if (res.success && last_odom_) publish(r, ros::Time::now(), *last_odom_);
    return true;
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    const bool ambiguous = last_ && last_->search.ambiguous && !last_->resolved;
    s.summary(tracker_.tracking() && last_ && !ambiguous ? 0 : 1,
              !tracker_.tracking() ? "lost: searching globally" : (ambiguous ? "tracking, ambiguous" : "tracking"));
    s.add("percept frames", frames_);
    s.add("dropped: unknown frame", dropped_frame_);
    s.add("dropped: non-finite", drops_.non_finite);
    s.add("ignored: not a map class", drops_.non_map_class);
    mrt::ros_common::report(s, drops_.ontology);
    s.add("frames without odometry", no_odom_);
    s.add("last update ms", last_ms_);
    if (!tracked_ms_.empty()) {  // over the last 1000 tracked frames
      std::vector<double> v = tracked_ms_;
      std::sort(v.begin(), v.end());
      s.add("tracked update median ms", v[v.size() / 2]);
      s.add("tracked update p95 ms", v[std::min(v.size() - 1, v.size() * 95 / 100)]);
    }
    if (last_) {
      s.add("mode", last_->mode == TrackMode::Global ? "global" : "tracking");
      s.add("evidence", last_->search.best.evidence);
      s.add("max evidence", last_->max_evidence);
      s.add("ambiguous", last_->search.ambiguous);
      s.add("complete", last_->search.complete);
    }
    s.add("ambiguities resolved by the prior", resolved_);
  }

  NodeOptions opt_;
  FeatureMap map_;
  Tracker tracker_;
  std::string odom_frame_, base_frame_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Publisher pose_pub_, markers_pub_;
  ros::Subscriber percept_sub_, initial_sub_, odom_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<mrt_msgs::Percept>> tf_filter_;
  ros::ServiceServer global_srv_, relocalize_srv_;
  ros::Timer tf_timer_, diag_timer_;
  diagnostic_updater::Updater diag_;
  std::optional<Pose2D> last_odom_, last_odom_msg_, map_to_odom_;
  ros::Time odom_stamp_, last_tf_stamp_;
  std::vector<Percept> last_percepts_;
  std::optional<TrackResult> last_;
  DropCounts drops_;
  std::size_t frames_ = 0, dropped_frame_ = 0, no_odom_ = 0, resolved_ = 0;
  double last_ms_ = 0.0;
  std::vector<double> tracked_ms_;
};

}  // namespace
}  // namespace mrt::murea::node

int main(int argc, char** argv) {
  ros::init(argc, argv, "murea");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::murea::node::MureaNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
