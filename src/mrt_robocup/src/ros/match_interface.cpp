#include "match_interface.h"

#include <nav_msgs/Odometry.h>

namespace mrt::robocup::node {

mrt_msgs::RefereeCommand to_msg(const RefereeEvent& e, const MatchConfig& cfg, const std::string& frame,
                                const ros::Time& stamp) {
  mrt_msgs::RefereeCommand m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.command = static_cast<std::uint8_t>(e.command);
  m.name = to_string(e.command);
  m.team = e.team == 0 || e.team == 1 ? cfg.teams[static_cast<std::size_t>(e.team)] : "";
  m.x = e.position.x;
  m.y = e.position.y;
  m.teams = {cfg.teams[0], cfg.teams[1]};
  m.score = {static_cast<std::uint32_t>(e.score[0]), static_cast<std::uint32_t>(e.score[1])};
  m.reason = e.reason;
  return m;
}

MatchInterface::MatchInterface(ros::NodeHandle& nh, Match& match, std::string world_frame)
    : match_(match), frame_(std::move(world_frame)) {
  // Latched: a robot that starts late still learns the current command.
  referee_pub_ = nh.advertise<mrt_msgs::RefereeCommand>("referee", 20, true);
  ball_pub_ = nh.advertise<nav_msgs::Odometry>("ball/ground_truth", 20);
  operator_sub_ = nh.subscribe("referee/operator", 10, &MatchInterface::on_operator, this);
  sim::Simulator& sim = match_.simulator();
  for (std::size_t i = 0; i < sim.robots().size(); ++i) {
    ros::NodeHandle rnh(nh, sim.robots()[i].config.name);
    robot_subs_.push_back(rnh.subscribe<std_msgs::Float64>(
        "kick", 10, [this, i](const std_msgs::Float64::ConstPtr& m) { match_.kick(i, m->data); }));
    robot_subs_.push_back(rnh.subscribe<std_msgs::Bool>(
        "dribble", 10, [this, i](const std_msgs::Bool::ConstPtr& m) { match_.set_dribbler(i, m->data); }));
  }
}

void MatchInterface::on_operator(const mrt_msgs::RefereeCommand::ConstPtr& msg) {
  // The command by name when given, else by number; the team by name.
  RefereeCommand c;
  try {
    if (!msg->name.empty()) {
      c = referee_command_from_string(msg->name);
    } else if (msg->command <= static_cast<std::uint8_t>(RefereeCommand::kDropBall)) {
      c = static_cast<RefereeCommand>(msg->command);
    } else {
      throw std::invalid_argument("unknown command number " + std::to_string(msg->command));
    }
    int team = -1;
    const MatchConfig& cfg = match_.config();
    if (msg->team == cfg.teams[0]) team = 0;
    else if (msg->team == cfg.teams[1]) team = 1;
    else if (!msg->team.empty()) throw std::invalid_argument("unknown team '" + msg->team + "'");
    match_.command(c, team);
  } catch (const std::exception& e) {
    ++dropped_;
    ROS_WARN_THROTTLE(1.0, "referee/operator: dropped a command: %s", e.what());
  }
}

void MatchInterface::publish_events(const ros::Time& stamp) {
  const std::vector<RefereeEvent> events = match_.take_events();
  for (const RefereeEvent& e : events) {
    last_ = to_msg(e, match_.config(), frame_, stamp);
    referee_pub_.publish(last_);
    ++published_;
    ROS_INFO("referee: %s%s%s (%s) score %d-%d", last_.name.c_str(), last_.team.empty() ? "" : " for ",
             last_.team.c_str(), e.reason.c_str(), e.score[0], e.score[1]);
  }
}

void MatchInterface::publish_ball(const ros::Time& stamp) {
  if (ball_pub_.getNumSubscribers() == 0) return;
  const sim::Ball& b = match_.simulator().world().ball;
  nav_msgs::Odometry o;
  o.header.stamp = stamp;
  o.header.frame_id = frame_;
  o.child_frame_id = "ball";
  o.pose.pose.position.x = b.position.x;
  o.pose.pose.position.y = b.position.y;
  o.pose.pose.position.z = b.radius;
  o.pose.pose.orientation.w = 1.0;
  o.twist.twist.linear.x = b.velocity.x;
  o.twist.twist.linear.y = b.velocity.y;
  ball_pub_.publish(o);
}

void MatchInterface::diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) const {
  const MatchConfig& cfg = match_.config();
  s.summary(diagnostic_msgs::DiagnosticStatus::OK,
            match_.state() == Match::State::kPlaying ? "playing" : "stopped");
  s.add("score", cfg.teams[0] + " " + std::to_string(match_.score()[0]) + " - " +
                     std::to_string(match_.score()[1]) + " " + cfg.teams[1]);
  s.add("last command", last_.name);
  s.add("referee commands published", published_);
  s.add("operator commands dropped", dropped_);
  s.add("kicks", match_.kicks());
  s.add("ball holder (robot index, -1 none)", match_.holder());
  s.add("ball handlers off by their watchdog (~dribble_timeout)", match_.dribble_timeouts());
}

}  // namespace mrt::robocup::node
