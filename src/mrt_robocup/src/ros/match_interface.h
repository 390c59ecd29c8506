// The ROS interface of the match simulation (match.h), for the match
// plugin of sim_node (match_plugin.cpp): the referee's commands on
// `referee`, the operator's on `referee/operator`, each robot's kicker
// (`<robot>/kick`) and ball handler (`<robot>/dribble`), and the ball's
// ground truth (`ball/ground_truth`).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <mrt_msgs/RefereeCommand.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>

#include "mrt_robocup/match.h"

namespace mrt::robocup::node {

/// The message of a referee event; `frame` is the world frame.
mrt_msgs::RefereeCommand to_msg(const RefereeEvent& e, const MatchConfig& cfg, const std::string& frame,
                                const ros::Time& stamp);

class MatchInterface {
 public:
  MatchInterface(ros::NodeHandle& nh, Match& match, std::string world_frame);

  /// Publishes the referee's commands issued since the last call (by the
  /// match's steps or an operator command), stamped `stamp`.
  void publish_events(const ros::Time& stamp);
  /// Publishes the ball's ground truth (with the robots' ground truth).
  void publish_ball(const ros::Time& stamp);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) const;

 private:
  void on_operator(const mrt_msgs::RefereeCommand::ConstPtr& msg);

  Match& match_;
  std::string frame_;
  ros::Publisher referee_pub_, ball_pub_;
  ros::Subscriber operator_sub_;
  std::vector<ros::Subscriber> robot_subs_;
  std::uint64_t published_ = 0, dropped_ = 0;
  mrt_msgs::RefereeCommand last_;
};

}  // namespace mrt::robocup::node
