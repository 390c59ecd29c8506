// spike_node: SPIKE as a ROS planner. make_plan (nav_msgs/GetPlan, as navfn:
// start and goal in any frame tf knows, the request's tolerance), goal (and
// rviz's move_base_simple/goal) -> plan from the robot's pose in tf, moving obstacles from percepts
// and (optionally) MAP's world model, re-planning when the plan becomes
// blocked, rviz markers, diagnostics. Wiring only: the algorithm is chosen
// by ~planner (planner_factory.h), the obstacles are the core's
// ObstacleTracker's (obstacle_tracker.h). dynamic_reconfigure (cfg/Spike.cfg):
// the inflation (rebuilds the planner), the horizon, the re-plan rate, the
// spacing; one mutex serializes every callback with the reconfiguration.
// ~smoothing (dubins | reeds_shepp): the published poses follow the core's
// CurvatureSmoother's curves of ~turning_radius through the waypoints.
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/PoseStamped.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WorldModel.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_common_ros/percept_conversions.h"
#include "mrt_spike/SpikeConfig.h"
#include "mrt_spike/curvature_smoother.h"
#include "mrt_spike/obstacle_tracker.h"
#include "mrt_spike/planner_factory.h"
#include "mrt_spike/world_planner.h"
#include "mrt_world/ros/occupancy_grid.h"
#include "spike_markers.h"

namespace {

using namespace mrt::spike;
using namespace mrt::spike::node;
using mrt_spike::SpikeConfig;

struct NodeOptions {
  std::string map;
  bool use_map_topic = false;  ///< the map from the `map` topic (as amcl), not the file
  double resolution = 0.1;
  std::string frame_id = "map";
  std::string base_frame = "base_link";
  double replan_rate = 10.0;
  bool use_world_model = false;  ///< also take the anchors of MAP's world model
  ObstacleTrackerOptions tracker;
  WorldPlannerOptions planner;
  std::string smoothing = "none";  ///< none | dubins | reeds_shepp
  SmoothingOptions smoothing_options;
};

class SpikeNode {
 public:
  SpikeNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const NodeOptions& o, const WorldGrid& map)
      : o_(o), planner_(map, o.planner), tracker_(o.tracker, planner_), listener_(tf_) {
    plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, true);
    marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
    service_ = nh.advertiseService("make_plan", &SpikeNode::make_plan, this);
    goal_sub_ = nh.subscribe("goal", 1, &SpikeNode::on_goal, this);
    rviz_goal_sub_ = nh.subscribe("move_base_simple/goal", 1, &SpikeNode::on_goal, this);
    percept_sub_ = nh.subscribe("percepts", 20, &SpikeNode::on_percept, this);
    if (o.use_world_model) model_sub_ = nh.subscribe("world_model", 5, &SpikeNode::on_world_model, this);
    diag_.setHardwareID("spike " + o.map);
    diag_.add("planner", this, &SpikeNode::diagnose);
    timer_ = nh.createTimer(ros::Duration(1.0 / o.replan_rate), &SpikeNode::on_timer, this);
    marker_pub_.publish(static_markers(planner_, o_.frame_id));
    ROS_INFO("spike_node: map %s, %d x %d cells of %.3f m, planner %s, %zu quadtree leaves, smoothing %s",
             o.map.c_str(), planner_.map().grid.width(), planner_.map().grid.height(),
             planner_.map().frame.resolution, o.planner.planner.c_str(),
             planner_.quadtree() ? planner_.quadtree()->leaves().size() : 0, o.smoothing.c_str());
    // last: the callbacks above may run once ros::spin() starts, the
    // reconfiguration from then on, starting from the validated parameters
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<SpikeConfig>>(reconfigure_mutex_, pnh);
    reconfigure_->updateConfig(current_config());
    reconfigure_->setCallback([this](SpikeConfig& c, uint32_t) { on_reconfigure(c); });
  }

 private:
  nav_msgs::Path to_path(const WorldPlan& p, double goal_yaw) const {
    nav_msgs::Path path;
    path.header.stamp = ros::Time::now();
    path.header.frame_id = o_.frame_id;
    for (size_t i = 0; i < p.poses.size(); ++i) {
      geometry_msgs::PoseStamped ps;
      ps.header = path.header;
      ps.pose = mrt::ros_common::to_pose({p.poses[i].x, p.poses[i].y, i + 1 == p.poses.size() ? goal_yaw : p.poses[i].yaw});
      path.poses.push_back(ps);
    }
    return path;
  }

  // A pose in the map frame: an empty frame id is the map's, another frame
  // goes through tf (at the pose's stamp, or the latest for stamp 0).
  bool in_map(const geometry_msgs::PoseStamped& in, geometry_msgs::PoseStamped& out, const char* what) {
    if (in.header.frame_id.empty() || in.header.frame_id == o_.frame_id) {
      out = in;
      out.header.frame_id = o_.frame_id;
      return true;
    }
    try {
      tf_.transform(in, out, o_.frame_id, ros::Duration(1.0));  // a just-started node may still wait for tf
      return true;
    } catch (const tf2::TransformException& e) {
      ROS_WARN("spike_node: the %s in %s is not in %s: %s", what, in.header.frame_id.c_str(), o_.frame_id.c_str(),
               e.what());
      return false;
    }
  }

  bool make_plan(nav_msgs::GetPlan::Request& req, nav_msgs::GetPlan::Response& res) {
    const std::lock_guard<std::mutex> lock(mutex_);
    res.plan.header.frame_id = o_.frame_id;
    res.plan.header.stamp = ros::Time::now();
    geometry_msgs::PoseStamped start, goal;
    if (!in_map(req.start, start, "start") || !in_map(req.goal, goal, "goal")) return true;  // an empty plan
    const auto& s = start.pose.position;
    const auto& g = goal.pose.position;
    const double goal_yaw = mrt::ros_common::quaternion_to_yaw(goal.pose.orientation);
    const WorldPlan p = timed_plan(s.x, s.y, g.x, g.y, std::max(0.0f, req.tolerance),
                                   mrt::ros_common::quaternion_to_yaw(start.pose.orientation), goal_yaw);
    if (!p.solved) {
      ROS_WARN("make_plan: no path: %s; nearest reachable point (%.2f, %.2f)", p.reason.c_str(), p.nearest_x, p.nearest_y);
      return true;  // an empty plan, as navfn
    }
    if (p.goal_relaxed)
      ROS_INFO("make_plan: %s; planned to the nearest reachable point, within the tolerance %.2f m", p.reason.c_str(),
               req.tolerance);
    res.plan = to_path(p, goal_yaw);
    return true;
  }

  bool current_pose(double& x, double& y, double& yaw) {
    try {
      const auto t = tf_.lookupTransform(o_.frame_id, o_.base_frame, ros::Time(0), ros::Duration(0.2));
      x = t.transform.translation.x, y = t.transform.translation.y;
      yaw = mrt::ros_common::quaternion_to_yaw(t.transform.rotation);
      return true;
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5, "spike_node: no pose of %s in %s: %s", o_.base_frame.c_str(), o_.frame_id.c_str(), e.what());
      return false;
    }
  }

  void replan(const char* why) {
    double x = 0, y = 0, yaw = 0;
    if (!has_goal_ || !current_pose(x, y, yaw)) return;
    const auto& g = goal_.pose.position;
    const double goal_yaw = mrt::ros_common::quaternion_to_yaw(goal_.pose.orientation);
    plan_ = timed_plan(x, y, g.x, g.y, 0.0, yaw, goal_yaw);
    ++replans_;
    if (!plan_.solved)
      ROS_WARN("spike_node (%s): no path: %s; nearest reachable point (%.2f, %.2f)", why, plan_.reason.c_str(),
               plan_.nearest_x, plan_.nearest_y);
    else
      ROS_INFO("spike_node (%s): plan of %.2f m, %zu poses", why, plan_.length, plan_.poses.size());
    plan_pub_.publish(to_path(plan_, goal_yaw));
  }

  void on_goal(const geometry_msgs::PoseStamped& g) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!std::isfinite(g.pose.position.x) || !std::isfinite(g.pose.position.y)) {
      ROS_WARN_THROTTLE(5, "spike_node: dropped a non-finite goal");
      return;
    }
    geometry_msgs::PoseStamped in_map_frame;
    if (!in_map(g, in_map_frame, "goal")) return;
    goal_ = in_map_frame;
    has_goal_ = true;
    replan("new goal");
  }

  void on_percept(const mrt_msgs::Percept& p);
  void on_world_model(const mrt_msgs::WorldModel& m);
  void on_reconfigure(SpikeConfig& c);
  SpikeConfig current_config() const;
  bool to_map(const std::string& frame, mrt::common::Pose2D& t);

  // every plan goes through here: its time (smoothing included) and its
  // failure for the diagnostics
  WorldPlan timed_plan(double x0, double y0, double x1, double y1, double tolerance, double yaw0, double yaw1) {
    const auto t0 = std::chrono::steady_clock::now();
    WorldPlan p = planner_.plan(x0, y0, x1, y1, tolerance);
    smooth(p, yaw0, yaw1);
    last_plan_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    max_plan_ms_ = std::max(max_plan_ms_, last_plan_ms_);
    ++plans_;
    if (!p.solved) {
      ++failures_;
      char buf[96];
      std::snprintf(buf, sizeof buf, " (%.2f, %.2f) -> (%.2f, %.2f)", x0, y0, x1, y1);
      last_failure_ = p.reason + buf;
    }
    last_solved_ = p.solved;
    return p;
  }

  // ~smoothing: the current grid (with the moving obstacles), poses every
  // ~spacing (the resolution for 0)
  CurvatureSmoother smoother() const {
    SmoothingOptions so = o_.smoothing_options;
    so.step = planner_.options().spacing > 0.0 ? planner_.options().spacing : planner_.map().frame.resolution;
    return CurvatureSmoother(planner_.with_obstacles(), planner_.map().frame, so);
  }

  void smooth(WorldPlan& p, double yaw0, double yaw1) {
    if (o_.smoothing_options.model == SmoothingOptions::Model::none || !p.solved) return;
    const SmoothedPath s = smoother().smooth(waypoint_poses(p.waypoints, planner_.map().frame), yaw0,
                                             std::isfinite(yaw1) ? std::optional<double>(yaw1) : std::nullopt);
    p.poses = s.poses;
    p.length = s.length;
    if (s.fully_smoothed) return;
    ++partial_smoothings_;
    ROS_WARN_THROTTLE(5, "spike_node: %s smoothing partial: %d straight segments kept (no curve of %.2f m fits)",
                      o_.smoothing.c_str(), s.kept_segments, o_.smoothing_options.turning_radius);
  }

  // the plan's straight segments and, when smoothed, its curves still free
  bool still_valid(const WorldPlan& p) const {
    if (!planner_.still_valid(p)) return false;
    return o_.smoothing_options.model == SmoothingOptions::Model::none || smoother().poses_free(p.poses);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    if (plans_ > 0 && !last_solved_)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "last plan failed: " + last_failure_);
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
    st.add("map", o_.map);
    st.add("map loaded", true);
    st.add("map cells", std::to_string(planner_.map().grid.width()) + " x " + std::to_string(planner_.map().grid.height()));
    st.add("resolution (m)", planner_.map().frame.resolution);
    st.add("planner", o_.planner.planner);
    if (planner_.quadtree()) st.add("quadtree leaves", planner_.quadtree()->leaves().size());
    st.add("obstacles", tracker_.size());
    st.add("plans", plans_);
    st.add("re-plans", replans_);
    st.add("failures", failures_);
    st.add("last plan time (ms)", last_plan_ms_);
    st.add("max plan time (ms)", max_plan_ms_);
    st.add("last failure", last_failure_.empty() ? std::string("none") : last_failure_);
    st.add("dropped messages", dropped_ + tracker_.dropped());
    mrt::ros_common::report(st, percept_drops_);
    st.add("world model", o_.use_world_model);
    st.add("smoothing", o_.smoothing);
    st.add("partial smoothings", partial_smoothings_);
  }

  void on_timer(const ros::TimerEvent&) {
    const std::lock_guard<std::mutex> lock(mutex_);
    tracker_.expire(ros::Time::now().toSec());
    if (tracker_.take_changed()) marker_pub_.publish(obstacle_markers(planner_, o_.frame_id));
    if (has_goal_ && plan_.solved && !still_valid(plan_)) replan("plan blocked");
    diag_.update();
  }

  std::mutex mutex_;  ///< every callback's: the reconfiguration changes planner_ and the timer
  NodeOptions o_;
  WorldPlanner planner_;
  ObstacleTracker tracker_;  ///< writes the obstacles into planner_
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  ros::Publisher plan_pub_, marker_pub_;
  ros::ServiceServer service_;
  ros::Subscriber goal_sub_, rviz_goal_sub_, percept_sub_, model_sub_;
  diagnostic_updater::Updater diag_;
  ros::Timer timer_;
  geometry_msgs::PoseStamped goal_;
  bool has_goal_ = false;
  WorldPlan plan_;
  mrt::common::PerceptDrops percept_drops_;  ///< objects the ontology refused
  int replans_ = 0;
  int plans_ = 0, failures_ = 0, partial_smoothings_ = 0;
  size_t dropped_ = 0;  ///< percepts and models in a frame not in tf
  bool last_solved_ = true;
  double last_plan_ms_ = 0.0, max_plan_ms_ = 0.0;
  std::string last_failure_;
  boost::recursive_mutex reconfigure_mutex_;  ///< the server's own, held around on_reconfigure
  std::unique_ptr<dynamic_reconfigure::Server<SpikeConfig>> reconfigure_;
};

SpikeConfig SpikeNode::current_config() const {
  SpikeConfig c = SpikeConfig::__getDefault__();
  const WorldPlannerOptions& w = planner_.options();
  c.robot_radius = w.robot_radius;
  c.safety_distance = w.safety_distance;
  c.obstacle_horizon = w.horizon;
  c.spacing = w.spacing;
  c.replan_rate = o_.replan_rate;
  return c;
}

// A new inflation or horizon rebuilds the planner (the moving obstacles
// kept) and re-plans the current goal; the rate restarts the timer. Values
// that cannot be applied are refused: `c` gets the current ones back.
void SpikeNode::on_reconfigure(SpikeConfig& c) {
  const std::lock_guard<std::mutex> lock(mutex_);
  WorldPlannerOptions w = planner_.options();
  w.robot_radius = c.robot_radius;
  w.safety_distance = c.safety_distance;
  w.horizon = c.obstacle_horizon;
  w.spacing = c.spacing;
  try {
    if (planner_.reconfigure(w)) {
      ROS_INFO("spike_node: reconfigured: inflation %.3f m (robot radius %.3f + safety %.3f), horizon %.2f s",
               w.robot_radius + w.safety_distance, w.robot_radius, w.safety_distance, w.horizon);
      marker_pub_.publish(static_markers(planner_, o_.frame_id));
      marker_pub_.publish(obstacle_markers(planner_, o_.frame_id));
      if (has_goal_) replan("reconfigured");
    }
  } catch (const std::exception& e) {
    ROS_WARN("spike_node: reconfiguration refused: %s", e.what());
    c = current_config();
    return;
  }
  o_.planner = planner_.options();
  if (c.replan_rate != o_.replan_rate && c.replan_rate > 0.0) {
    o_.replan_rate = c.replan_rate;
    timer_.setPeriod(ros::Duration(1.0 / o_.replan_rate));
  }
  c = current_config();
}

bool SpikeNode::to_map(const std::string& frame, mrt::common::Pose2D& pose) {
  try {
    const auto t = tf_.lookupTransform(o_.frame_id, frame, ros::Time(0), ros::Duration(0.1)).transform;
    pose = mrt::common::Pose2D(t.translation.x, t.translation.y, mrt::ros_common::quaternion_to_yaw(t.rotation));
    return true;
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5, "spike_node: obstacles in %s dropped: %s", frame.c_str(), e.what());
    ++dropped_;
    return false;
  }
}

// The objects the ontology accepts (the others counted), moved into the map
// frame through tf; the tracker keeps those of the obstacle classes.
void SpikeNode::on_percept(const mrt_msgs::Percept& p) {
  const std::lock_guard<std::mutex> lock(mutex_);
  mrt::common::Pose2D t;
  if (!to_map(p.header.frame_id, t)) return;
  const size_t refused = percept_drops_.total();
  const auto objects = mrt::ros_common::accepted_objects(p, percept_drops_);
  if (percept_drops_.total() > refused)
    ROS_WARN_THROTTLE(5, "spike_node: %zu percept objects of %s refused by the ontology (unknown class, "
                      "attribute missing or of the wrong kind)", percept_drops_.total() - refused, p.robot.c_str());
  const ros::Time stamp = p.header.stamp.isZero() ? ros::Time::now() : p.header.stamp;
  if (tracker_.add_percept(p.robot, objects, t, stamp.toSec()) > 0)
    ROS_WARN_THROTTLE(5, "spike_node: percept objects of %s without a finite position dropped", p.robot.c_str());
}

// MAP's anchors, in the model's frame; the tracker keeps those of the
// obstacle classes (README, world_model).
void SpikeNode::on_world_model(const mrt_msgs::WorldModel& m) {
  const std::lock_guard<std::mutex> lock(mutex_);
  mrt::common::Pose2D t;
  if (!to_map(m.header.frame_id, t)) return;
  const ros::Time stamp = m.header.stamp.isZero() ? ros::Time::now() : m.header.stamp;
  std::vector<WorldModelAnchor> anchors;
  anchors.reserve(m.anchors.size());
  for (const auto& a : m.anchors)
    anchors.push_back({a.id, a.membership_class, a.status == mrt_msgs::Anchor::TENTATIVE, a.x, a.y, a.vx, a.vy,
                       a.covariance[0], a.covariance[5]});
  tracker_.add_world_model(m.robot, anchors, t, stamp.toSec());
}

NodeOptions read_options(ros::NodeHandle& pnh) {
  mrt::ros_common::ParamReader p(pnh);
  NodeOptions o;
  auto& w = o.planner;
  p.get("use_map_topic", o.use_map_topic);
  if (!o.use_map_topic) p.require("map", o.map, "a map file: world YAML or map_server YAML");
  p.get_positive("resolution", o.resolution)
      .get_non_negative("robot_radius", w.robot_radius)
      .get_non_negative("safety_distance", w.safety_distance)
      .get_non_negative("spacing", w.spacing)
      .get_non_negative("obstacle_horizon", w.horizon)
      .get_positive("replan_rate", o.replan_rate)
      .get_positive("obstacle_timeout", o.tracker.timeout)
      .get_non_negative("default_obstacle_radius", o.tracker.default_radius)
      .get("obstacle_classes", o.tracker.classes)
      .get("use_world_model", o.use_world_model)
      .get_non_negative("anchor_sigmas", o.tracker.anchor_sigmas)
      .get("frame_id", o.frame_id)
      .get("base_frame", o.base_frame)
      .get("planner", w.planner)
      .get("smoothing", o.smoothing)
      .get_positive("turning_radius", o.smoothing_options.turning_radius);
  try {  // at start-up, before the map is loaded
    check_dynamic_planner(w.planner);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("~planner: " + std::string(e.what()));
  }
  try {
    o.smoothing_options.model = smoothing_model(o.smoothing);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("~smoothing: " + std::string(e.what()));
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "spike_node");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    NodeOptions o = read_options(pnh);
    WorldGrid map;
    if (o.use_map_topic) {  // as amcl: the first map on the topic (a map server's, latched)
      ROS_INFO("spike_node: waiting for the map on %s", nh.resolveName("map").c_str());
      const auto msg = ros::topic::waitForMessage<nav_msgs::OccupancyGrid>("map", nh);
      if (!msg) return 1;  // shut down while waiting
      o.map = nh.resolveName("map");
      map = to_world_grid(mrt::world::from_msg(*msg, o.map));
    } else {
      map = load_any_map(o.map, o.resolution);
    }
    SpikeNode node(nh, pnh, o, map);
    ros::spin();
    return 0;
  });
}
