// spike_node: SPIKE as a ROS planner. make_plan (nav_msgs/GetPlan, as navfn),
// goal -> plan from the robot's pose in tf, moving obstacles from percepts
// and (optionally) MAP's world model, re-planning when the plan becomes
// blocked, rviz markers, diagnostics.
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseStamped.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WorldModel.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <cmath>
#include <map>
#include <set>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_spike/world_planner.h"
#include "spike_markers.h"

namespace {

using namespace mrt::spike;

struct NodeOptions {
  std::string map;
  double resolution = 0.1;
  std::string frame_id = "map";
  std::string base_frame = "base_link";
  double replan_rate = 10.0;
  double obstacle_timeout = 1.0;
  std::vector<std::string> obstacle_classes{"Person", "Robot", "Teammate", "Opponent", "Obstacle"};
  double default_obstacle_radius = 0.25;
  bool use_world_model = false;  ///< also take the anchors of MAP's world model
  double anchor_sigmas = 1.0;    ///< an anchor's radius grows by this many position std devs
  WorldPlannerOptions planner;
};

class SpikeNode {
 public:
  SpikeNode(ros::NodeHandle& nh, const NodeOptions& o)
      : o_(o), planner_(load_any_map(o.map, o.resolution), o.planner), listener_(tf_) {
    plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, true);
    marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
    service_ = nh.advertiseService("make_plan", &SpikeNode::make_plan, this);
    goal_sub_ = nh.subscribe("goal", 1, &SpikeNode::on_goal, this);
    percept_sub_ = nh.subscribe("percepts", 20, &SpikeNode::on_percept, this);
    if (o.use_world_model) model_sub_ = nh.subscribe("world_model", 5, &SpikeNode::on_world_model, this);
    diag_.setHardwareID("spike " + o.map);
    diag_.add("planner", this, &SpikeNode::diagnose);
    timer_ = nh.createTimer(ros::Duration(1.0 / o.replan_rate), &SpikeNode::on_timer, this);
    marker_pub_.publish(static_markers(planner_, o_.frame_id));
    ROS_INFO("spike_node: map %s, %d x %d cells of %.3f m, %zu quadtree leaves", o.map.c_str(),
             planner_.map().grid.width(), planner_.map().grid.height(), planner_.map().frame.resolution,
             planner_.quadtree().leaves().size());
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

  bool make_plan(nav_msgs::GetPlan::Request& req, nav_msgs::GetPlan::Response& res) {
    const auto& s = req.start.pose.position;
    const auto& g = req.goal.pose.position;
    const WorldPlan p = timed_plan(s.x, s.y, g.x, g.y);
    if (!p.solved) {
      ROS_WARN("make_plan: no path: %s; nearest reachable point (%.2f, %.2f)", p.reason.c_str(), p.nearest_x, p.nearest_y);
      res.plan.header.frame_id = o_.frame_id;
      res.plan.header.stamp = ros::Time::now();
      return true;  // an empty plan, as navfn
    }
    res.plan = to_path(p, mrt::ros_common::quaternion_to_yaw(req.goal.pose.orientation));
    return true;
  }

  bool current_pose(double& x, double& y) {
    try {
      const auto t = tf_.lookupTransform(o_.frame_id, o_.base_frame, ros::Time(0), ros::Duration(0.2));
      x = t.transform.translation.x, y = t.transform.translation.y;
      return true;
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5, "spike_node: no pose of %s in %s: %s", o_.base_frame.c_str(), o_.frame_id.c_str(), e.what());
      return false;
    }
  }

  void replan(const char* why) {
    double x = 0, y = 0;
    if (!has_goal_ || !current_pose(x, y)) return;
    const auto& g = goal_.pose.position;
    plan_ = timed_plan(x, y, g.x, g.y);
    ++replans_;
    if (!plan_.solved)
      ROS_WARN("spike_node (%s): no path: %s; nearest reachable point (%.2f, %.2f)", why, plan_.reason.c_str(),
               plan_.nearest_x, plan_.nearest_y);
    else
      ROS_INFO("spike_node (%s): plan of %.2f m, %zu poses", why, plan_.length, plan_.poses.size());
    plan_pub_.publish(to_path(plan_, mrt::ros_common::quaternion_to_yaw(goal_.pose.orientation)));
  }

  void on_goal(const geometry_msgs::PoseStamped& g) {
    if (!std::isfinite(g.pose.position.x) || !std::isfinite(g.pose.position.y)) {
      ROS_WARN_THROTTLE(5, "spike_node: dropped a non-finite goal");
      return;
    }
    goal_ = g;
    has_goal_ = true;
    replan("new goal");
  }

  void on_percept(const mrt_msgs::Percept& p);
  void on_world_model(const mrt_msgs::WorldModel& m);
  bool to_map(const std::string& frame, geometry_msgs::TransformStamped& t);
  void update_track(const std::string& key, double x, double y, double r, double vx, double vy, bool has_v,
                    const ros::Time& stamp);

  // every plan goes through here: its time and its failure for the diagnostics
  WorldPlan timed_plan(double x0, double y0, double x1, double y1) {
    const auto t0 = std::chrono::steady_clock::now();
    WorldPlan p = planner_.plan(x0, y0, x1, y1);
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

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    if (plans_ > 0 && !last_solved_)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "last plan failed: " + last_failure_);
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
    st.add("map", o_.map);
    st.add("map loaded", true);
    st.add("map cells", std::to_string(planner_.map().grid.width()) + " x " + std::to_string(planner_.map().grid.height()));
    st.add("resolution (m)", planner_.map().frame.resolution);
    st.add("quadtree leaves", planner_.quadtree().leaves().size());
    st.add("obstacles", tracks_.size());
    st.add("plans", plans_);
    st.add("re-plans", replans_);
    st.add("failures", failures_);
    st.add("last plan time (ms)", last_plan_ms_);
    st.add("max plan time (ms)", max_plan_ms_);
    st.add("last failure", last_failure_.empty() ? std::string("none") : last_failure_);
    st.add("dropped messages", dropped_);
    st.add("world model", o_.use_world_model);
  }

  void on_timer(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    bool changed = false;
    for (auto it = tracks_.begin(); it != tracks_.end();) {
      if ((now - it->second.seen).toSec() > o_.obstacle_timeout) {
        planner_.remove_obstacle(it->second.id);
        it = tracks_.erase(it);
        changed = true;
      } else {
        ++it;
      }
    }
    if (changed || obstacles_dirty_) marker_pub_.publish(obstacle_markers(planner_, o_.frame_id));
    obstacles_dirty_ = false;
    if (has_goal_ && plan_.solved && !planner_.still_valid(plan_)) replan("plan blocked");
    diag_.update();
  }

  struct Track {
    int id = 0;
    double x = 0, y = 0;
    ros::Time seen;
  };

  NodeOptions o_;
  WorldPlanner planner_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  ros::Publisher plan_pub_, marker_pub_;
  ros::ServiceServer service_;
  ros::Subscriber goal_sub_, percept_sub_, model_sub_;
  diagnostic_updater::Updater diag_;
  ros::Timer timer_;
  geometry_msgs::PoseStamped goal_;
  bool has_goal_ = false;
  WorldPlan plan_;
  std::map<std::string, Track> tracks_;
  int next_id_ = 0;
  bool obstacles_dirty_ = false;
  int replans_ = 0;
  int plans_ = 0, failures_ = 0, dropped_ = 0;
  bool last_solved_ = true;
  double last_plan_ms_ = 0.0, max_plan_ms_ = 0.0;
  std::string last_failure_;
};

double attribute(const mrt_msgs::PerceptObject& o, const std::string& name, double def, bool* found = nullptr) {
  for (const auto& a : o.attributes)
    if (a.name == name && a.symbol.empty() && std::isfinite(a.value)) {
      if (found) *found = true;
      return a.value;
    }
  return def;
}

bool SpikeNode::to_map(const std::string& frame, geometry_msgs::TransformStamped& t) {
  try {
    t = tf_.lookupTransform(o_.frame_id, frame, ros::Time(0), ros::Duration(0.1));
    return true;
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5, "spike_node: obstacles in %s dropped: %s", frame.c_str(), e.what());
    ++dropped_;
    return false;
  }
}

// One obstacle (map frame): a new track or a move; without a velocity, the
// velocity from the last sighting.
void SpikeNode::update_track(const std::string& key, double x, double y, double r, double vx, double vy, bool has_v,
                             const ros::Time& stamp) {
  auto [it, fresh] = tracks_.try_emplace(key);
  Track& tr = it->second;
  if (fresh) tr.id = next_id_++;
  const double dt = (stamp - tr.seen).toSec();
  if (!has_v && !fresh && dt > 1e-3) vx = (x - tr.x) / dt, vy = (y - tr.y) / dt;
  planner_.set_obstacle(tr.id, x, y, r, vx, vy);
  tr.x = x, tr.y = y, tr.seen = stamp;
  obstacles_dirty_ = true;
}

bool is_obstacle_class(const std::vector<std::string>& classes, const std::string& c) {
  return std::find(classes.begin(), classes.end(), c) != classes.end();
}

// Objects of the obstacle classes, at attributes x, y in the percept's frame
// (radius, vx, vy when given; else the default radius and the velocity from
// the last sighting), moved into the map frame through tf.
void SpikeNode::on_percept(const mrt_msgs::Percept& p) {
  geometry_msgs::TransformStamped t;
  if (!to_map(p.header.frame_id, t)) return;
  const double yaw = mrt::ros_common::quaternion_to_yaw(t.transform.rotation);
  const double c = std::cos(yaw), s = std::sin(yaw);
  const ros::Time stamp = p.header.stamp.isZero() ? ros::Time::now() : p.header.stamp;
  for (const auto& ob : p.objects) {
    if (!is_obstacle_class(o_.obstacle_classes, ob.membership_class)) continue;
    bool has_x = false, has_y = false, has_vx = false, has_vy = false;
    const double lx = attribute(ob, "x", 0, &has_x), ly = attribute(ob, "y", 0, &has_y);
    if (!has_x || !has_y) {
      ROS_WARN_THROTTLE(5, "spike_node: %s without x, y dropped", ob.name.c_str());
      ++dropped_;
      continue;
    }
    const double x = t.transform.translation.x + c * lx - s * ly, y = t.transform.translation.y + s * lx + c * ly;
    const double vx = attribute(ob, "vx", 0, &has_vx), vy = attribute(ob, "vy", 0, &has_vy);
    update_track(p.robot + "/" + ob.name, x, y, attribute(ob, "radius", o_.default_obstacle_radius), vx, vy,
                 has_vx && has_vy, stamp);
  }
}

// The anchors of MAP's world model of the obstacle classes (tentative ones
// skipped) become moving obstacles: radius ~default_obstacle_radius plus
// ~anchor_sigmas position standard deviations (the larger of x and y), the
// footprint swept along the anchor's velocity (both rotated into the map
// frame). The model is complete: a producer's anchors missing from its new
// model are removed.
void SpikeNode::on_world_model(const mrt_msgs::WorldModel& m) {
  geometry_msgs::TransformStamped t;
  if (!to_map(m.header.frame_id, t)) return;
  const double yaw = mrt::ros_common::quaternion_to_yaw(t.transform.rotation);
  const double c = std::cos(yaw), s = std::sin(yaw);
  const ros::Time stamp = m.header.stamp.isZero() ? ros::Time::now() : m.header.stamp;
  const std::string prefix = "world_model:" + m.robot + "/";
  std::set<std::string> seen;
  for (const auto& a : m.anchors) {
    if (a.status == mrt_msgs::Anchor::TENTATIVE || !is_obstacle_class(o_.obstacle_classes, a.membership_class))
      continue;
    if (!std::isfinite(a.x) || !std::isfinite(a.y)) {
      ++dropped_;
      continue;
    }
    const double x = t.transform.translation.x + c * a.x - s * a.y, y = t.transform.translation.y + s * a.x + c * a.y;
    const double vx = std::isfinite(a.vx) ? c * a.vx - s * a.vy : 0.0, vy = std::isfinite(a.vy) ? s * a.vx + c * a.vy : 0.0;
    const double var = std::max(a.covariance[0], a.covariance[5]);
    const double r = o_.default_obstacle_radius + o_.anchor_sigmas * (std::isfinite(var) && var > 0 ? std::sqrt(var) : 0.0);
    const std::string key = prefix + std::to_string(a.id);
    update_track(key, x, y, r, vx, vy, true, stamp);
    seen.insert(key);
  }
  for (auto it = tracks_.lower_bound(prefix); it != tracks_.end() && it->first.compare(0, prefix.size(), prefix) == 0;) {
    if (seen.count(it->first)) {
      ++it;
      continue;
    }
    planner_.remove_obstacle(it->second.id);
    it = tracks_.erase(it);
    obstacles_dirty_ = true;
  }
}

NodeOptions read_options(ros::NodeHandle& pnh) {
  mrt::ros_common::ParamReader p(pnh);
  NodeOptions o;
  auto& w = o.planner;
  p.require("map", o.map, "a map file: world YAML or map_server YAML")
      .get_positive("resolution", o.resolution)
      .get_non_negative("robot_radius", w.robot_radius)
      .get_non_negative("safety_distance", w.safety_distance)
      .get_non_negative("spacing", w.spacing)
      .get_non_negative("obstacle_horizon", w.horizon)
      .get_positive("replan_rate", o.replan_rate)
      .get_positive("obstacle_timeout", o.obstacle_timeout)
      .get_non_negative("default_obstacle_radius", o.default_obstacle_radius)
      .get("obstacle_classes", o.obstacle_classes)
      .get("use_world_model", o.use_world_model)
      .get_non_negative("anchor_sigmas", o.anchor_sigmas)
      .get("frame_id", o.frame_id)
      .get("base_frame", o.base_frame);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "spike_node");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    const NodeOptions o = read_options(pnh);
    SpikeNode node(nh, o);
    ros::spin();
    return 0;
  });
}
