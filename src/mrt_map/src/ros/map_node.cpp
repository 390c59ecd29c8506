// map_node: MAP for one robot of a team. Wiring only: parameters -> options,
// messages <-> the mrt_map core (see README for the API table).
// dynamic_reconfigure (cfg/Map.cfg): the gates and the noise; one mutex
// serializes every callback with the reconfiguration.
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WorldModel.h>
#include <ros/ros.h>
#include <tf2/utils.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

#include "mrt_common_ros/params.h"
#include "mrt_common_ros/percept_conversions.h"
#include "mrt_map/MapConfig.h"
#include "mrt_map/team_sender.h"
#include "mrt_map/world_model.h"
#include "ros/conversions.h"

namespace {

using mrt::ros_common::ParamReader;
using mrt_map::MapConfig;
namespace conv = mrt::map::node;

struct NodeOptions {
  std::string model;
  std::string world_frame = "map";
  std::string base_frame;  // default "<robot>/base_link"
  double rate = 30.0;
  double team_rate = 10.0;
  std::string team_topic = "/team/world_models";
  double pose_sigma = 0.02;
  double theta_sigma = 0.01;
  mrt::map::WorldModelOptions core;
};

NodeOptions read_options(ros::NodeHandle& pnh) {
  NodeOptions o;
  ParamReader p(pnh);
  p.require("model", o.model, "the path of the conceptual model YAML file");
  std::string ns = ros::this_node::getNamespace();
  while (!ns.empty() && ns.front() == '/') ns.erase(0, 1);
  o.core.robot = ns.empty() ? "robot" : ns;
  p.get("robot", o.core.robot);
  ParamReader::check(!o.core.robot.empty() && o.core.robot.find('/') == std::string::npos, "robot",
                     "a non-empty name without '/'");
  o.base_frame = o.core.robot + "/base_link";
  p.get("world_frame", o.world_frame).get("base_frame", o.base_frame);
  ParamReader::check(!o.world_frame.empty(), "world_frame", "a non-empty frame id");
  p.get_positive("rate", o.rate).get_positive("team_rate", o.team_rate);
  p.get("team_topic", o.team_topic);
  p.get_positive("max_percept_age", o.core.max_percept_age);
  p.get_non_negative("pose_sigma", o.pose_sigma).get_non_negative("theta_sigma", o.theta_sigma);
  return o;
}

class MapNode {
 public:
  MapNode(ros::NodeHandle& nh, ros::NodeHandle& pnh)
      : opt_(read_options(pnh)), model_(mrt::map::ConceptualModel::load(opt_.model)), world_(model_, opt_.core),
        sender_(model_, 1.0 / opt_.team_rate, std::min(0.5 / opt_.rate, 0.5 / opt_.team_rate)),
        tf_listener_(tf_buffer_) {
    percept_sub_ = nh.subscribe("percepts", 20, &MapNode::on_percept, this);
    coordination_sub_ = nh.subscribe("coordination", 10, &MapNode::on_coordination, this);
    model_pub_ = nh.advertise<mrt_msgs::WorldModel>("world_model", 5);
    crisp_pub_ = nh.advertise<mrt_msgs::CrispDataArray>("crisp_data", 5);
    marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("map_markers", 2);
    if (!opt_.team_topic.empty()) {
      team_pub_ = nh.advertise<mrt_msgs::WorldModel>(opt_.team_topic, 10);
      team_sub_ = nh.subscribe(opt_.team_topic, 20, &MapNode::on_team, this);
    }
    diagnostics_.setHardwareID(opt_.core.robot);
    diagnostics_.add("MAP world model", this, &MapNode::diagnose);
    cycle_timer_ = nh.createTimer(ros::Duration(1.0 / opt_.rate), &MapNode::on_cycle, this);
    // the gates start from the model file, the pose noise from the parameters
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<MapConfig>>(reconfigure_mutex_, pnh);
    reconfigure_->updateConfig(current_config());
    reconfigure_->setCallback([this](MapConfig& c, uint32_t) { on_reconfigure(c); });
  }

 private:
  MapConfig current_config() const {
    MapConfig c = MapConfig::__getDefault__();
    const mrt::map::ModelTuning t = model_.tuning();
    c.gate = t.gate;
    c.merge_gate = t.merge_gate;
    c.team_gate = t.team_gate;
    c.team_extra_sigma = t.team_extra_sigma;
    c.pose_sigma = opt_.pose_sigma;
    c.theta_sigma = opt_.theta_sigma;
    return c;
  }

  // The model's tuned values (the Merger and Tracker read them from their
  // next call) and the pose noise; refused values are logged and `c` gets
  // the current ones back.
  void on_reconfigure(MapConfig& c) {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      model_.set_tuning({c.gate, c.merge_gate, c.team_gate, c.team_extra_sigma});
    } catch (const std::invalid_argument& e) {
      ROS_WARN("map_node: reconfiguration refused: %s", e.what());
    }
    if (std::isfinite(c.pose_sigma) && c.pose_sigma >= 0.0) opt_.pose_sigma = c.pose_sigma;
    if (std::isfinite(c.theta_sigma) && c.theta_sigma >= 0.0) opt_.theta_sigma = c.theta_sigma;
    c = current_config();
    ROS_INFO("map_node: gate %g, merge gate %g, team gate %g, team extra sigma %g m, pose sigma %g m, %g rad", c.gate,
             c.merge_gate, c.team_gate, c.team_extra_sigma, c.pose_sigma, c.theta_sigma);
  }

  bool pose_at(const std::string& frame, const ros::Time& stamp, mrt::map::RobotPose& pose) {
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_.lookupTransform(opt_.world_frame, frame, stamp, ros::Duration(0.02));
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "map_node: no pose of %s in %s: %s", frame.c_str(), opt_.world_frame.c_str(), e.what());
      return false;
    }
    pose.x = t.transform.translation.x;
    pose.y = t.transform.translation.y;
    pose.theta = tf2::getYaw(t.transform.rotation);
    pose.cov = opt_.pose_sigma * opt_.pose_sigma * mrt::map::Mat2::Identity();
    pose.theta_sigma = opt_.theta_sigma;
    return true;
  }

  void on_percept(const mrt_msgs::Percept& p) {
    const std::lock_guard<std::mutex> lock(mutex_);
    ++percepts_;
    const std::string frame = p.header.frame_id.empty() ? opt_.base_frame : p.header.frame_id;
    mrt::map::RobotPose pose;
    const double now = ros::Time::now().toSec(), stamp = p.header.stamp.toSec();
    const bool stale = std::fabs(now - stamp) > opt_.core.max_percept_age;  // the core counts it
    if (!stale && !pose_at(frame, p.header.stamp, pose)) {
      no_pose_ += p.objects.size();
      return;
    }
    const auto before = world_.counters();
    world_.add_percept(mrt::ros_common::accepted_objects(p, ontology_drops_), pose, stamp, now,
                       p.sensor.empty() ? "sensor" : p.sensor);
    const auto& after = world_.counters();
    if (after.accepted - before.accepted < p.objects.size())
      ROS_WARN_THROTTLE(5.0, "map_node: dropped %zu of %zu objects of a percept from %s (not in the ontology, "
                        "unknown class, non-finite, stale, unmatched or outside the world; see diagnostics)",
                        p.objects.size() - static_cast<std::size_t>(after.accepted - before.accepted),
                        p.objects.size(), p.sensor.c_str());
  }

  void on_coordination(const mrt_msgs::CrispDataArray& a) {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& d : a.data) {
      if (!std::isfinite(d.value) || !(d.reliability >= 0.0 && d.reliability <= 1.0)) {
        ++bad_parameters_;
        continue;
      }
      world_.set_parameter(d.name, d.value, d.reliability, a.header.stamp.toSec());
    }
  }

  void on_team(const mrt_msgs::WorldModel& m) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (m.robot == opt_.core.robot || !m.local_only) return;
    std::vector<mrt::map::RemoteTrack> tracks;
    for (const auto& a : m.anchors) {
      mrt::map::RemoteTrack t;
      if (conv::from_msg(a, model_, m.header.stamp, t)) tracks.push_back(std::move(t));
      else ++bad_anchors_;
    }
    mrt::map::RobotPose pose;
    pose.x = m.robot_x;
    pose.y = m.robot_y;
    pose.theta = m.robot_theta;
    pose.cov << m.robot_covariance[0], m.robot_covariance[1], m.robot_covariance[2], m.robot_covariance[3];
    const bool pose_ok = std::isfinite(pose.x) && std::isfinite(pose.y) && pose.cov.allFinite();
    world_.add_teammate_model(m.robot, tracks, m.header.stamp.toSec(), pose_ok ? &pose : nullptr);
    ++team_models_;
  }

  void on_cycle(const ros::TimerEvent&) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time now = ros::Time::now();
    mrt::map::RobotPose pose;
    if (pose_at(opt_.base_frame, ros::Time(0), pose)) world_.set_robot_pose(pose, now.toSec());
    world_.update(now.toSec());
    model_pub_.publish(conv::to_msg(world_, opt_.world_frame, now));
    crisp_pub_.publish(conv::to_msg(world_.crisp(now.toSec()), now));
    if (marker_pub_.getNumSubscribers() > 0) marker_pub_.publish(conv::markers(world_, opt_.world_frame, now));
    // The team exchange: on the heartbeat (team_rate) or on a deviation
    // (the model's team.send_threshold).
    if (team_pub_) {
      const std::vector<mrt::map::RemoteTrack> tracks = world_.local_tracks();
      if (sender_.due(now.toSec(), tracks)) {
        team_pub_.publish(conv::to_msg(world_, tracks, opt_.world_frame, now));
        sender_.sent(now.toSec(), tracks);
      }
    }
    diagnostics_.update();
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    const auto& c = world_.counters();
    const std::uint64_t dropped =
        c.unknown_class + c.non_finite + c.no_position + c.unmatched + c.stale + c.stale_team + c.outside_world + no_pose_ +
        bad_anchors_ + ontology_drops_.total();
    s.summary(dropped > 0 ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK,
              dropped > 0 ? "input dropped (see counters)" : "ok");
    s.add("anchors", world_.tracker().anchors().size());
    s.add("anchors dropped", world_.tracker().dropped_count());
    s.add("percepts", percepts_);
    s.add("objects accepted", c.accepted);
    mrt::ros_common::report(s, ontology_drops_);
    s.add("dropped unknown class", c.unknown_class);
    s.add("dropped non-finite", c.non_finite);
    s.add("dropped no position", c.no_position);
    s.add("dropped below matching threshold", c.unmatched);
    s.add("dropped stale", c.stale);
    s.add("dropped outside the world", c.outside_world);
    s.add("dropped no robot pose", no_pose_);
    s.add("teammate models", team_models_);
    s.add("team messages sent on the heartbeat", sender_.periodic());
    s.add("team messages sent on a deviation", sender_.on_deviation());
    s.add("teammate anchors stale", c.stale_team);
    s.add("teammate anchors malformed", bad_anchors_);
    s.add("coordination parameters malformed", bad_parameters_);
  }

  std::mutex mutex_;  // every callback's: the reconfiguration changes model_ and opt_
  NodeOptions opt_;
  mrt::map::ConceptualModel model_;  // tuned at run time; world_ and sender_ hold it by reference
  mrt::map::WorldModel world_;
  mrt::map::TeamSender sender_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  ros::Subscriber percept_sub_, coordination_sub_, team_sub_;
  ros::Publisher model_pub_, crisp_pub_, marker_pub_, team_pub_;
  ros::Timer cycle_timer_;
  diagnostic_updater::Updater diagnostics_;
  std::uint64_t percepts_ = 0, no_pose_ = 0, bad_anchors_ = 0, bad_parameters_ = 0, team_models_ = 0;
  mrt::common::PerceptDrops ontology_drops_;  // objects the ontology refuses (percept_conversions.h)
  boost::recursive_mutex reconfigure_mutex_;  // the server's own, held around on_reconfigure
  std::unique_ptr<dynamic_reconfigure::Server<MapConfig>> reconfigure_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "map_node");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    MapNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
