// murea_node: MUREA localization with the interface amcl users know.
// Percepts (mrt_msgs/Percept) and laser scans (sensor_msgs/LaserScan, each
// beam a wall point), odometry (tf odom -> base_link or a
// nav_msgs/Odometry topic) and the map (~map or, with use_map_topic, the
// `map` topic) in; amcl_pose and pose (PoseWithCovarianceStamped),
// particlecloud, tf map -> odom, evidence markers and diagnostics out;
// initialpose, global_localization, request_nomotion_update, set_map and
// relocalize. The node is wiring: all the work is the core's Tracker.
// dynamic_reconfigure (cfg/Murea.cfg): the search's accuracy, timeout and
// tolerances, from the next frame. The node spins one thread (ros::spin):
// the reconfiguration runs between frames, as every other callback.
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/SetMap.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
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
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>

#include "mrt_common_ros/percept_conversions.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_murea/MureaConfig.h"
#include "mrt_world/occupancy_map.h"
#include "mrt_world/ros/occupancy_grid.h"
#include "ros/markers.h"
#include "ros/node_options.h"

namespace mrt::murea::node {
namespace {

namespace rc = mrt::ros_common;
using mrt_murea::MureaConfig;

// The reconfigurable values of search options, and back (tolerances as
// ~tolerance_<class>'s [base, per_metre], by class).
MureaConfig to_config(const SearchOptions& s) {
  MureaConfig c = MureaConfig::__getDefault__();
  c.accuracy_xy = s.accuracy_xy;
  c.accuracy_theta = s.accuracy_theta;
  c.timeout = s.timeout;
  c.timeout_cpu = s.timeout_cpu;
  double* t[kFeatureClassCount][2] = {{&c.tolerance_line_base, &c.tolerance_line_per_metre},
                                      {&c.tolerance_goal_base, &c.tolerance_goal_per_metre},
                                      {&c.tolerance_goalpost_base, &c.tolerance_goalpost_per_metre},
                                      {&c.tolerance_landmark_base, &c.tolerance_landmark_per_metre},
                                      {&c.tolerance_wall_base, &c.tolerance_wall_per_metre}};
  for (int k = 0; k < kFeatureClassCount; ++k) *t[k][0] = s.tolerance[k].base, *t[k][1] = s.tolerance[k].per_metre;
  return c;
}

SearchOptions from_config(SearchOptions s, const MureaConfig& c) {
  s.accuracy_xy = c.accuracy_xy;
  s.accuracy_theta = c.accuracy_theta;
  s.timeout = c.timeout;
  s.timeout_cpu = c.timeout_cpu;
  const double t[kFeatureClassCount][2] = {{c.tolerance_line_base, c.tolerance_line_per_metre},
                                           {c.tolerance_goal_base, c.tolerance_goal_per_metre},
                                           {c.tolerance_goalpost_base, c.tolerance_goalpost_per_metre},
                                           {c.tolerance_landmark_base, c.tolerance_landmark_per_metre},
                                           {c.tolerance_wall_base, c.tolerance_wall_per_metre}};
  for (int k = 0; k < kFeatureClassCount; ++k) s.tolerance[k] = {t[k][0], t[k][1]};
  return s;
}

class MureaNode {
 public:
  MureaNode(ros::NodeHandle& nh, ros::NodeHandle& pnh)
      : opt_(read_options(pnh)),
        odom_frame_(opt_.frame_prefix + opt_.odom_frame),
        base_frame_(opt_.frame_prefix + opt_.base_frame),
        tf_listener_(tf_buffer_) {
    pending_pose_ = opt_.initial_pose;
    pending_cov_ = opt_.initial_cov;
    if (opt_.use_map_topic) map_sub_ = nh.subscribe("map", 1, &MureaNode::on_map, this);
    else set_world(mrt::world::load_map_world(opt_.map_file), opt_.map_file);
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("pose", 10, true);
    amcl_pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 10, true);
    cloud_pub_ = nh.advertise<geometry_msgs::PoseArray>("particlecloud", 2, true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("evidence_markers", 5);
    percept_sub_ = nh.subscribe("percepts", 10, &MureaNode::on_percept_msg, this);
    scan_sub_ = nh.subscribe("scan", 10, &MureaNode::on_scan_msg, this);
    if (opt_.odom_topic.empty()) {
      // Odometry from tf: each frame waits in the filter until odom ->
      // base_link is known at its stamp (the odometry may lag the camera).
      percept_filter_ = make_filter<mrt_msgs::Percept>(nh, [this](const mrt_msgs::Percept& m) { on_percept(m); });
      scan_filter_ = make_filter<sensor_msgs::LaserScan>(nh, [this](const sensor_msgs::LaserScan& m) { on_scan(m); });
    }
    initial_sub_ = nh.subscribe("initialpose", 2, &MureaNode::on_initial_pose, this);
    if (!opt_.odom_topic.empty()) odom_sub_ = nh.subscribe(opt_.odom_topic, 50, &MureaNode::on_odom, this);
    global_srv_ = nh.advertiseService("global_localization", &MureaNode::on_global, this);
    relocalize_srv_ = nh.advertiseService("relocalize", &MureaNode::on_relocalize, this);
    nomotion_srv_ = nh.advertiseService("request_nomotion_update", &MureaNode::on_nomotion, this);
    set_map_srv_ = nh.advertiseService("set_map", &MureaNode::on_set_map, this);
    if (opt_.publish_tf)
      tf_timer_ = nh.createTimer(ros::Duration(1.0 / opt_.tf_rate), [this](const ros::TimerEvent&) { send_tf(); });
    diag_.setHardwareID("murea");
    diag_.add("murea localization", this, &MureaNode::diagnose);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
    ROS_INFO("murea: map %s, %.3f m / %.2f deg, timeout %.3f s, odometry from %s, frames %s -> %s -> %s",
             opt_.use_map_topic ? "from the topic" : opt_.map_file.c_str(), opt_.tracker.search.accuracy_xy,
             opt_.tracker.search.accuracy_theta * 180 / M_PI, opt_.tracker.search.timeout,
             opt_.odom_topic.empty() ? "tf" : opt_.odom_topic.c_str(), opt_.map_frame.c_str(), odom_frame_.c_str(),
             base_frame_.c_str());
    // last: the reconfiguration starts from the validated parameters
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<MureaConfig>>(reconfigure_mutex_, pnh);
    reconfigure_->updateConfig(to_config(opt_.tracker.search));
    reconfigure_->setCallback([this](MureaConfig& c, uint32_t) { on_reconfigure(c); });
  }

 private:
  // New search options for the tracker (from its next frame) and for the
  // trackers of later maps; values the tracker refuses on its map are
  // logged and `c` gets the current ones back. Without a map yet, the
  // cfg's ranges are the check (the tracker of the map checks them again).
  void on_reconfigure(MureaConfig& c) {
    const SearchOptions s = from_config(opt_.tracker.search, c);
    try {
      if (tracker_) tracker_->set_search_options(s);
      opt_.tracker.search = s;
      ROS_INFO("murea: reconfigured: %.3f m / %.2f deg, timeout %.3f s (%s), tolerance line [%.3f, %.3f], goal "
               "[%.3f, %.3f], goalpost [%.3f, %.3f], landmark [%.3f, %.3f], wall [%.3f, %.3f]",
               s.accuracy_xy, s.accuracy_theta * 180 / M_PI, s.timeout, s.timeout_cpu ? "CPU" : "wall-clock",
               s.tolerance[0].base, s.tolerance[0].per_metre, s.tolerance[1].base, s.tolerance[1].per_metre,
               s.tolerance[2].base, s.tolerance[2].per_metre, s.tolerance[3].base, s.tolerance[3].per_metre,
               s.tolerance[4].base, s.tolerance[4].per_metre);
    } catch (const std::invalid_argument& e) {
      ROS_WARN("murea: reconfiguration refused: %s", e.what());
    }
    c = to_config(opt_.tracker.search);
  }

  // A new map (at start, from the topic, from set_map): a new tracker on
  // it, tracking from the pending pose (the parameters' or set_map's) when
  // there is one, else searching globally.
  void set_world(const mrt::world::World& world, const std::string& name) {
    tracker_.reset();  // it refers to the old map
    map_ = std::make_unique<FeatureMap>(world);
    tracker_ = std::make_unique<Tracker>(*map_, opt_.tracker);
    last_.reset();
    ROS_INFO("murea: map %s (%.1f x %.1f m)", name.c_str(), map_->max_x() - map_->min_x(),
             map_->max_y() - map_->min_y());
    if (pending_pose_) {
      tracker_->set_pose(*pending_pose_, pending_cov_);
      ROS_INFO("murea: initial pose (%.2f, %.2f, %.1f deg)", pending_pose_->x, pending_pose_->y,
               pending_pose_->theta * 180 / M_PI);
      pending_pose_.reset();
    }
  }

  // The walls of an occupancy grid (a malformed or empty grid throws).
  static mrt::world::World world_from_grid(const nav_msgs::OccupancyGrid& g, const std::string& name) {
    if (g.info.width == 0 || g.info.height == 0 || g.data.size() != std::size_t{g.info.width} * g.info.height ||
        !(g.info.resolution > 0.0f) || !std::isfinite(g.info.resolution))
      throw std::runtime_error(name + ": width x height must match the data, resolution > 0");
    const mrt::world::OccupancyMap m = mrt::world::from_msg(g, name);
    if (m.count_occupied() == 0) throw std::runtime_error(name + ": no occupied cell");
    return mrt::world::occupied_walls(m);
  }

  // use_map_topic: the first map received (as amcl's first_map_only).
  void on_map(const nav_msgs::OccupancyGrid& m) {
    if (map_) return;
    if (!m.header.frame_id.empty() && m.header.frame_id != opt_.map_frame)
      ROS_WARN("murea: the map is in frame '%s', taken as '%s'", m.header.frame_id.c_str(), opt_.map_frame.c_str());
    try {
      set_world(world_from_grid(m, "topic map"), "from the topic map");
    } catch (const std::exception& e) {
      ROS_ERROR("murea: the map on the topic is unusable: %s", e.what());
      return;
    }
    map_sub_.shutdown();
  }

  template <class M>
  std::unique_ptr<tf2_ros::MessageFilter<M>> make_filter(ros::NodeHandle& nh, std::function<void(const M&)> f) {
    auto filter = std::make_unique<tf2_ros::MessageFilter<M>>(tf_buffer_, odom_frame_, 20, nh);
    filter->registerCallback([f](const boost::shared_ptr<const M>& m) { f(*m); });
    filter->registerFailureCallback(
        [this](const boost::shared_ptr<const M>&, tf2_ros::filter_failure_reasons::FilterFailureReason) {
          no_odometry();
        });
    return filter;
  }

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

  // A frame (percepts or scan) in a frame tf does not know is dropped here
  // (it would wait in the filter for ever); the others go to the filter
  // or, with an odometry topic, straight on.
  template <class M>
  void on_frame_msg(const boost::shared_ptr<const M>& msg, tf2_ros::MessageFilter<M>* filter,
                    void (MureaNode::*handle)(const M&), std::size_t objects) {
    ++frames_;
    if (!sensor_mount(msg->header.frame_id, ros::Time(0))) return drop_frame(msg->header.frame_id, objects);
    if (filter) filter->add(msg);
    else (this->*handle)(*msg);
  }
  void on_percept_msg(const mrt_msgs::Percept::ConstPtr& msg) {
    on_frame_msg(msg, percept_filter_.get(), &MureaNode::on_percept, msg->objects.size());
  }
  void on_scan_msg(const sensor_msgs::LaserScan::ConstPtr& msg) {
    on_frame_msg(msg, scan_filter_.get(), &MureaNode::on_scan, msg->ranges.size());
  }

  void drop_frame(const std::string& frame, std::size_t objects) {
    dropped_frame_ += objects;
    ROS_WARN_THROTTLE(5.0, "murea: percepts in frame '%s' dropped (no transform to '%s')", frame.c_str(),
                      base_frame_.c_str());
  }

  void on_percept(const mrt_msgs::Percept& msg) {
    process(msg.header, msg.objects.size(), to_percepts(msg, drops_));
  }
  void on_scan(const sensor_msgs::LaserScan& msg) {
    std::vector<Percept> ps = scan_to_percepts(msg, opt_.scan_max_beams, scan_counts_);
    last_beams_ = ps.size();
    process(msg.header, msg.ranges.size(), std::move(ps));
  }

  // One frame of percepts in the frame of `h`: into base_link, odometry's
  // prediction, the tracker's update, the outputs.
  void process(const std_msgs::Header& h, std::size_t objects, std::vector<Percept> ps) {
    const std::optional<Pose2D> mount = sensor_mount(h.frame_id, h.stamp);
    if (!mount) return drop_frame(h.frame_id, objects);
    if (!tracker_) {
      ++before_map_;
      ROS_WARN_THROTTLE(5.0, "murea: no map yet (use_map_topic: waiting for `map`): frame skipped");
      return;
    }
    to_base_frame(ps, *mount);
    const std::optional<Pose2D> odom = odom_at(h.stamp);
    if (!odom) return no_odometry();
    last_percepts_ = ps;
    last_stamp_ = h.stamp;
    const auto t0 = std::chrono::steady_clock::now();
    const TrackResult r = track_frame(*tracker_, &last_odom_, *odom, ps, opt_);
    last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (r.mode == TrackMode::Tracking) {
      if (tracked_ms_.size() >= 1000) tracked_ms_.erase(tracked_ms_.begin());
      tracked_ms_.push_back(last_ms_);
    }
    last_ = r;
    resolved_ += r.resolved;
    publish(r, h.stamp, *odom);
  }

  void publish(const TrackResult& r, const ros::Time& stamp, const Pose2D& odom) {
    // The modes, also while lost (the ambiguous ones), as amcl's particles.
    cloud_pub_.publish(particle_cloud(r, opt_.map_frame, stamp));
    if (!tracker_->tracking()) return;  // lost: keep the last map -> odom
    if (!tracker_->settled()) return;  // a global fix not yet confirmed (~settle_frames)
    geometry_msgs::PoseWithCovarianceStamped m;
    m.header.stamp = stamp;
    m.header.frame_id = opt_.map_frame;
    m.pose.pose = rc::to_pose(r.pose);
    rc::set_planar_covariance(r.covariance, m.pose.covariance);
    pose_pub_.publish(m);
    amcl_pose_pub_.publish(m);
    map_to_odom_ = r.pose * odom.inverse();
    if (opt_.publish_tf) send_tf();
    if (markers_pub_.getNumSubscribers() > 0)
      markers_pub_.publish(evidence_markers(r, *tracker_, opt_.map_frame, stamp));
  }

  void send_tf() {
    if (!map_to_odom_) return;
    const ros::Time stamp = ros::Time::now() + ros::Duration(opt_.transform_tolerance);
    if (stamp <= last_tf_stamp_) return;  // once per time stamp (tf2 ignores repeats)
    last_tf_stamp_ = stamp;
    tf_broadcaster_.sendTransform(rc::to_transform(*map_to_odom_, opt_.map_frame, odom_frame_, stamp));
  }

  static Covariance3 planar_covariance(const geometry_msgs::PoseWithCovarianceStamped& m) {
    Covariance3 c{};
    static constexpr int kIdx[3] = {0, 1, 5};
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) c[3 * r + k] = m.pose.covariance[kIdx[r] * 6 + kIdx[k]];
    return c;
  }

  void on_initial_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    const Pose2D p = rc::to_pose2d(m.pose.pose);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta)) {
      ROS_WARN("murea: initialpose with non-finite values ignored");
      return;
    }
    if (!tracker_) {  // no map yet: applied when it comes
      pending_pose_ = p;
      pending_cov_ = planar_covariance(m);
      return;
    }
    tracker_->set_pose(p, planar_covariance(m));
    ROS_INFO("murea: initial pose (%.2f, %.2f, %.1f deg)", p.x, p.y, p.theta * 180 / M_PI);
  }

  bool on_global(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    if (tracker_) tracker_->reset();
    ROS_INFO("murea: global localization requested");
    return true;
  }

  // amcl's request_nomotion_update: an update on the last frame without
  // motion (no prediction), published with that frame's stamp.
  bool on_nomotion(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    if (!tracker_ || !last_odom_ || last_percepts_.empty()) {
      ROS_WARN("murea: request_nomotion_update: no frame yet");
      return true;
    }
    const TrackResult r = tracker_->update(last_percepts_);
    last_ = r;
    ++nomotion_;
    publish(r, last_stamp_, *last_odom_);
    return true;
  }

  // amcl's set_map: the new map, tracking from the request's initial pose.
  bool on_set_map(nav_msgs::SetMap::Request& req, nav_msgs::SetMap::Response& res) {
    const Pose2D p = rc::to_pose2d(req.initial_pose.pose.pose);
    res.success = false;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta)) {
      ROS_WARN("murea: set_map: non-finite initial pose refused");
      return true;
    }
    try {
      const mrt::world::World w = world_from_grid(req.map, "set_map");
      pending_pose_ = p;
      pending_cov_ = planar_covariance(req.initial_pose);
      set_world(w, "from set_map");
      map_sub_.shutdown();  // a map from the service replaces the topic's
      res.success = true;
    } catch (const std::exception& e) {
      pending_pose_.reset();
      ROS_WARN("murea: set_map: unusable map refused: %s", e.what());
    }
    return true;
  }

  // One-shot: a global search on the last frame of percepts, now.
  bool on_relocalize(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    if (!tracker_) {
      res.success = false;
      res.message = "no map yet";
      return true;
    }
    tracker_->reset();
    const TrackResult r = tracker_->update(last_percepts_);
    char buf[200];
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.2f deg) evidence %.2f of %.2f%s", r.pose.x, r.pose.y,
                  r.pose.theta * 180 / M_PI, r.search.best.evidence, r.max_evidence,
                  r.search.ambiguous ? ", ambiguous" : "");
    res.success = tracker_->tracking();
    res.message = res.success ? buf : std::string("not localized: ") + buf;
    last_ = r;
    if (res.success && last_odom_) publish(r, ros::Time::now(), *last_odom_);
    return true;
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    const bool tracking = tracker_ && tracker_->tracking();
    const bool ambiguous = last_ && last_->search.ambiguous && !last_->resolved;
    s.summary(tracking && last_ && !ambiguous ? 0 : 1,
              !tracker_ ? "no map yet" : !tracking ? "lost: searching globally" : (ambiguous ? "tracking, ambiguous" : "tracking"));
    s.add("percept frames", frames_);
    s.add("laser scans", scan_counts_.scans);
    s.add("laser beams out of range", scan_counts_.invalid);
    s.add("laser beams used, last scan", last_beams_);
    s.add("dropped: unknown frame", dropped_frame_);
    s.add("dropped: non-finite", drops_.non_finite);
    s.add("ignored: not a map class", drops_.non_map_class);
    mrt::ros_common::report(s, drops_.ontology);
    s.add("frames without odometry", no_odom_);
    s.add("frames before the map", before_map_);
    s.add("no-motion updates", nomotion_);
    s.add("last update ms", last_ms_);
    const SearchOptions& so = tracker_ ? tracker_->options().search : opt_.tracker.search;  // the options in use
    s.add("accuracy xy m", so.accuracy_xy);
    s.add("accuracy theta rad", so.accuracy_theta);
    s.add("timeout s", so.timeout);
    s.add("tolerance wall base m", so.tolerance[static_cast<int>(FeatureClass::Wall)].base);
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
      s.add("modes carried", last_->modes);
      s.add("last search cells", last_->search.cells);
    }
    s.add("ambiguities resolved by the prior", resolved_);
  }

  NodeOptions opt_;
  std::unique_ptr<FeatureMap> map_;   // none until use_map_topic's map comes
  std::unique_ptr<Tracker> tracker_;  // on *map_
  std::optional<Pose2D> pending_pose_;  // applied to the next map
  Covariance3 pending_cov_{};
  std::string odom_frame_, base_frame_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Publisher pose_pub_, amcl_pose_pub_, cloud_pub_, markers_pub_;
  ros::Subscriber map_sub_, percept_sub_, scan_sub_, initial_sub_, odom_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<mrt_msgs::Percept>> percept_filter_;
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::LaserScan>> scan_filter_;
  ros::ServiceServer global_srv_, relocalize_srv_, nomotion_srv_, set_map_srv_;
  ros::Timer tf_timer_, diag_timer_;
  diagnostic_updater::Updater diag_;
  std::optional<Pose2D> last_odom_, last_odom_msg_, map_to_odom_;
  ros::Time odom_stamp_, last_tf_stamp_, last_stamp_;
  std::vector<Percept> last_percepts_;
  std::optional<TrackResult> last_;
  DropCounts drops_;
  ScanCounts scan_counts_;
  std::size_t frames_ = 0, dropped_frame_ = 0, no_odom_ = 0, resolved_ = 0, before_map_ = 0, nomotion_ = 0, last_beams_ = 0;
  double last_ms_ = 0.0;
  std::vector<double> tracked_ms_;
  boost::recursive_mutex reconfigure_mutex_;  // the server's own, held around on_reconfigure
  std::unique_ptr<dynamic_reconfigure::Server<MureaConfig>> reconfigure_;
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
