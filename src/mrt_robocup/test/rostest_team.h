// What the RoboCup rostests watch of a running team (robocup.launch in the
// test's .test file): the referee, the true ball, every robot's true pose
// and twist (mrt_sim's ground truth), its SCARE job and the coordination
// messages its teammates hear over DCDT. Sim time throughout.
#pragma once

#include <mrt_msgs/CoordinationParameters.h>
#include <mrt_msgs/RefereeCommand.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace mrt::robocup::test {

struct Sample {
  double t, x, y, speed, omega;
};

class TeamWatch {
 public:
  explicit TeamWatch(const std::vector<std::string>& robots) : robots_(robots) {
    subs_.push_back(nh_.subscribe<mrt_msgs::RefereeCommand>(
        "/referee", 20, [this](const mrt_msgs::RefereeCommand::ConstPtr& m) { referee.push_back(*m); }));
    subs_.push_back(nh_.subscribe<nav_msgs::Odometry>("/ball/ground_truth", 20, [this](const nav_msgs::Odometry::ConstPtr& m) {
      ball.push_back({m->header.stamp.toSec(), m->pose.pose.position.x, m->pose.pose.position.y,
                      std::hypot(m->twist.twist.linear.x, m->twist.twist.linear.y), 0.0});
    }));
    for (const std::string& r : robots_) {
      subs_.push_back(nh_.subscribe<nav_msgs::Odometry>("/" + r + "/ground_truth", 200,
                                                        [this, r](const nav_msgs::Odometry::ConstPtr& m) {
        truth[r].push_back({m->header.stamp.toSec(), m->pose.pose.position.x, m->pose.pose.position.y,
                            std::hypot(m->twist.twist.linear.x, m->twist.twist.linear.y),
                            m->twist.twist.angular.z});
      }));
      subs_.push_back(nh_.subscribe<std_msgs::String>("/" + r + "/scare/job", 10, [this, r](const std_msgs::String::ConstPtr& m) {
        job[r] = m->data;
        job_changes[r].push_back({ros::Time::now().toSec(), m->data});
      }));
      // The team topic of each robot is fed by its own DCDT bridge: what it
      // hears of its teammates.
      subs_.push_back(nh_.subscribe<mrt_msgs::CoordinationParameters>(
          "/" + r + "/scare/team", 50, [this, r](const mrt_msgs::CoordinationParameters::ConstPtr& m) {
            if (m->robot_id == r) {  // its own: when it took its intention, on its own clock
              own.push_back(m);
              auto& v = intentions[r];
              if (v.empty() || v.back().second != m->intention) v.push_back({m->intention_since, m->intention});
              return;
            }
            double& last = last_heard[m->robot_id];
            last = std::max(last, m->header.stamp.toSec());
          }));
    }
  }

  /// The first referee command of that name at or after `since` (sim s), or nullptr.
  const mrt_msgs::RefereeCommand* command(const std::string& name, double since = 0.0) const {
    for (const auto& c : referee)
      if (c.name == name && c.header.stamp.toSec() >= since) return &c;
    return nullptr;
  }
  const Sample* latest(const std::string& robot) const {
    auto it = truth.find(robot);
    return it == truth.end() || it->second.empty() ? nullptr : &it->second.back();
  }
  /// The team's goals (score[0]) as the referee last announced them.
  unsigned goals() const {
    for (auto it = referee.rbegin(); it != referee.rend(); ++it)
      if (!it->score.empty()) return it->score[0];
    return 0;
  }

  std::vector<mrt_msgs::RefereeCommand> referee;
  std::vector<Sample> ball;
  std::map<std::string, std::vector<Sample>> truth;
  std::map<std::string, std::string> job;
  std::map<std::string, std::vector<std::pair<double, std::string>>> job_changes;
  std::map<std::string, double> last_heard;  // newest stamp of each robot's coordination message, heard by a teammate
  /// Each robot's intentions as it announced them: (taken at, slot), its
  /// coordinator's sim time of the cycle that took it (0: not carried).
  std::map<std::string, std::vector<std::pair<double, std::string>>> intentions;
  /// Every robot's own coordination messages, in arrival order (for a failure's timeline).
  std::vector<mrt_msgs::CoordinationParameters::ConstPtr> own;

 private:
  ros::NodeHandle nh_;
  std::vector<std::string> robots_;
  std::vector<ros::Subscriber> subs_;
};

}  // namespace mrt::robocup::test
