// player_node: one robot of the RoboCup team (README "Node player_node").
// Wiring only: parameters -> PlayerOptions, messages -> PlayerInput, one
// Player::cycle per ~rate, the output -> cmd_vel, kick, dribble, crisp debug
// and diagnostics. A referee stop zeroes cmd_vel at once, in its callback.
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/CoordinationParameters.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/RefereeCommand.h>
#include <mrt_msgs/WorldModel.h>
#include <nav_msgs/Odometry.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/params.h"
#include "mrt_robocup/coordination.h"
#include "mrt_robocup/player.h"

namespace mrt::robocup::node {
namespace {

struct NodeOptions {
  PlayerOptions player;
  std::string robot_id, team_topic = "/scare/team", referee_topic = "/referee";
  double rate = 10.0, pose_timeout = 0.5, world_timeout = 1.0, coordination_timeout = 1.0,
         possession_timeout = 0.5;

  static NodeOptions read(ros_common::ParamReader& p, const std::string& ns) {
    NodeOptions o;
    PlayerOptions& pl = o.player;
    SituationOptions& s = pl.situation;
    o.robot_id = ns;
    p.require("kinematics", pl.kinematics, "differential or omni")
        .get("rule_base", pl.rule_base)
        .get("robot_id", o.robot_id)
        .get("team_topic", o.team_topic)
        .get("referee_topic", o.referee_topic)
        .get_positive("rate", o.rate)
        .get_positive("pose_timeout", o.pose_timeout)
        .get_positive("world_model_timeout", o.world_timeout)
        .get_positive("coordination_timeout", o.coordination_timeout)
        .get_positive("possession_timeout", o.possession_timeout)
        .get_positive("max_speed", pl.max_speed)
        .get_positive("max_omega", pl.max_omega)
        .get_positive("carry_max_speed", pl.carry_max_speed)
        .get_positive("carry_max_omega", pl.carry_max_omega)
        .get_non_negative("dribble_distance", pl.dribble_distance)
        .get_non_negative("kick_cooldown", pl.kick_cooldown)
        .get_positive("kick_max_omega", pl.kick_max_omega)
        .get_non_negative("job_hold", pl.job_hold)
        .get("play_without_referee", pl.play_without_referee)
        .get_positive("body_radius", s.body_radius)
        .get_positive("goal_x", s.field.goal_x)
        .get_positive("keeper_clearance", s.keeper_clearance)
        .get_positive("spot_depth", s.spot_depth)
        .get_non_negative("spot_offset", s.spot_offset)
        .get("home_x", s.home.x)
        .get("home_y", s.home.y);
    ros_common::ParamReader::check(pl.kinematics == "differential" || pl.kinematics == "omni", "kinematics",
                                   "differential or omni");
    ros_common::ParamReader::check(!o.robot_id.empty(), "robot_id", "a non-empty robot id (or a namespace)");
    if (pl.rule_base.empty())
      pl.rule_base = ros::package::getPath("mrt_robocup") + "/config/brian/" + pl.kinematics + "/BrianConfigs.ini";
    return o;
  }
};

class PlayerNode {
 public:
  PlayerNode(ros::NodeHandle& nh, NodeOptions o) : o_(std::move(o)), player_(o_.player) {
    cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    kick_pub_ = nh.advertise<std_msgs::Float64>("kick", 10);
    dribble_pub_ = nh.advertise<std_msgs::Bool>("dribble", 10, true);
    crisp_pub_ = nh.advertise<mrt_msgs::CrispDataArray>("player/crisp", 5);
    job_pub_ = nh.advertise<std_msgs::String>("player/job", 5, true);
    pose_sub_ = nh.subscribe("pose", 10, &PlayerNode::on_pose, this);
    world_sub_ = nh.subscribe("world_model", 5, &PlayerNode::on_world, this);
    crisp_sub_ = nh.subscribe("scare/crisp", 5, &PlayerNode::on_scare_crisp, this);
    team_sub_ = nh.subscribe(o_.team_topic, 50, &PlayerNode::on_team, this);
    referee_sub_ = nh.subscribe(o_.referee_topic, 20, &PlayerNode::on_referee, this);
    possession_sub_ = nh.subscribe("ball_possession", 10, &PlayerNode::on_possession, this);
    turn_sub_ = nh.subscribe("odom", 10, &PlayerNode::on_turn, this);
    diag_.setHardwareID(o_.robot_id);
    diag_.add("RoboCup player", this, &PlayerNode::diagnose);
    timer_ = nh.createTimer(ros::Duration(1.0 / o_.rate), &PlayerNode::cycle, this);
    ROS_INFO("player_node %s: %s rule base %s", o_.robot_id.c_str(), o_.player.kinematics.c_str(),
             o_.player.rule_base.c_str());
  }

 private:
  static double now() { return ros::Time::now().toSec(); }

  // MUREA's estimate.
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
    const common::Pose2D q = ros_common::to_pose2d(m->pose.pose);
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.theta)) return drop("pose");
    in_.pose = q;
    pose_stamp_ = now();
  }

  void on_world(const mrt_msgs::WorldModel::ConstPtr& m) {
    in_.anchors.clear();
    for (const mrt_msgs::Anchor& a : m->anchors) {
      if (!std::isfinite(a.x) || !std::isfinite(a.y)) {
        drop("anchor");
        continue;
      }
      in_.anchors.push_back({a.membership_class, a.x, a.y, a.vx, a.vy, a.reliability});
    }
    // MAP holds SCARE's crisp output as parameters: a fallback source.
    model_parameters_.clear();
    for (const mrt_msgs::CrispData& c : m->parameters) model_parameters_[c.name] = {c.value, c.reliability};
    world_stamp_ = now();
  }

  void on_scare_crisp(const mrt_msgs::CrispDataArray::ConstPtr& m) {
    scare_crisp_.clear();
    for (const mrt_msgs::CrispData& c : m->data) scare_crisp_[c.name] = {c.value, c.reliability};
    scare_stamp_ = now();
  }

  void on_team(const mrt_msgs::CoordinationParameters::ConstPtr& m) {
    if (m->leaving) {
      team_.erase(m->robot_id);
      return;
    }
    team_[m->robot_id] = {m->intention, m->x, m->y, now()};
  }

  void on_referee(const mrt_msgs::RefereeCommand::ConstPtr& m) {
    if (m->command > static_cast<std::uint8_t>(Referee::kDropBall)) return drop("referee");
    in_.referee = static_cast<Referee>(m->command);
    referee_name_ = m->name;
    if (!Player::playing(in_.referee, o_.player.play_without_referee)) halt();  // at once, not next cycle
  }

  // The turn rate that gates the kick (PlayerOptions::kick_max_omega).
  void on_turn(const nav_msgs::Odometry::ConstPtr& m) {
    if (!std::isfinite(m->twist.twist.angular.z)) return drop("odometry");
    in_.omega = m->twist.twist.angular.z;
    turn_stamp_ = now();
  }

  void on_possession(const std_msgs::Bool::ConstPtr& m) {
    in_.possession = m->data;
    possession_stamp_ = now();
  }

  void halt() {
    cmd_pub_.publish(geometry_msgs::Twist());
    if (dribbling_) {
      std_msgs::Bool b;
      dribble_pub_.publish(b);
      dribbling_ = false;
    }
  }

  void drop(const char* what) {
    ++dropped_;
    ROS_WARN_THROTTLE(1.0, "player_node: dropped a malformed %s", what);
  }

  void cycle(const ros::TimerEvent&) {
    const double t = now();
    in_.time = t;
    in_.pose_valid = t - pose_stamp_ <= o_.pose_timeout;
    if (t - turn_stamp_ > o_.pose_timeout) in_.omega = std::numeric_limits<double>::quiet_NaN();
    if (t - world_stamp_ > o_.world_timeout) in_.anchors.clear();
    in_.possession_known = t - possession_stamp_ <= o_.possession_timeout;
    if (t - scare_stamp_ <= o_.coordination_timeout) in_.coordination = scare_crisp_;
    else if (t - world_stamp_ <= o_.world_timeout && !model_parameters_.empty()) in_.coordination = model_parameters_;
    else in_.coordination = coordination_from_team(o_.robot_id, team_, t, o_.coordination_timeout);
    PlayerOutput out = player_.cycle(in_);
    geometry_msgs::Twist tw;
    tw.linear.x = out.twist.vx;
    tw.linear.y = out.twist.vy;
    tw.angular.z = out.twist.omega;
    cmd_pub_.publish(tw);
    if (out.kick) {
      std_msgs::Float64 k;
      k.data = out.kick_strength;
      kick_pub_.publish(k);
      ++kicks_;
    }
    if (out.kick_held) ++kicks_held_;
    // Repeated every cycle while on: mrt_sim's ball handler lets the ball go
    // without it for ~dribble_timeout (so does a robot whose player died).
    if (out.dribble || out.dribble != dribbling_) {
      std_msgs::Bool b;
      b.data = out.dribble;
      dribble_pub_.publish(b);
      dribbling_ = out.dribble;
    }
    mrt_msgs::CrispDataArray c;
    c.header.stamp = ros::Time::now();
    for (const brian::CrispDatum& d : out.crisp) {
      mrt_msgs::CrispData x;
      x.name = d.name;
      x.value = d.value;
      x.reliability = d.reliability;
      c.data.push_back(x);
    }
    crisp_pub_.publish(c);
    if (out.job != job_ || cycles_ == 0) {
      std_msgs::String j;
      j.data = out.job;
      job_pub_.publish(j);
      if (cycles_ > 0) ++job_changes_;
      job_ = out.job;
    }
    last_ = out;
    ++cycles_;
    diag_.update();
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    const bool stale = !in_.pose_valid;
    s.summary(stale ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK,
              stale ? "no recent pose: halted" : (last_.halted ? "halted by the referee" : "playing"));
    s.add("job", job_);
    s.add("referee", referee_name_);
    s.add("ball owned", last_.situation.owned);
    s.add("cycles", cycles_);
    s.add("kicks", kicks_);
    s.add("kicks held while turning", kicks_held_);
    s.add("job changes", job_changes_);
    s.add("dropped messages", dropped_);
  }

  NodeOptions o_;
  Player player_;
  PlayerInput in_;
  PlayerOutput last_;
  Parameters scare_crisp_, model_parameters_;
  std::map<std::string, TeamEntry> team_;
  double pose_stamp_ = -1e9, turn_stamp_ = -1e9, world_stamp_ = -1e9, scare_stamp_ = -1e9, possession_stamp_ = -1e9;
  bool dribbling_ = false;
  std::string job_, referee_name_;
  std::uint64_t cycles_ = 0, kicks_ = 0, kicks_held_ = 0, job_changes_ = 0, dropped_ = 0;
  ros::Publisher cmd_pub_, kick_pub_, dribble_pub_, crisp_pub_, job_pub_;
  ros::Subscriber turn_sub_, pose_sub_, world_sub_, crisp_sub_, team_sub_, referee_sub_, possession_sub_;
  ros::Timer timer_;
  diagnostic_updater::Updater diag_;
};

}  // namespace
}  // namespace mrt::robocup::node

int main(int argc, char** argv) {
  ros::init(argc, argv, "player_node");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader params(pnh);
    std::string ns = ros::this_node::getNamespace();
    while (!ns.empty() && ns.front() == '/') ns.erase(0, 1);
    mrt::robocup::node::PlayerNode node(nh, mrt::robocup::node::NodeOptions::read(params, ns));
    ros::spin();
    return 0;
  });
}
