// rostest of the match plugin in sim_node (match.test): the referee's
// commands arrive on /referee (mrt_msgs/RefereeCommand) -- the automatic
// kick-off and start, then the operator's stop, start and goal -- and the
// ball's ground truth on /ball/ground_truth.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mrt_msgs/RefereeCommand.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::ros_common::wait_for;
using mrt_msgs::RefereeCommand;

struct Referee {
  std::vector<RefereeCommand> seen;
  void on(const RefereeCommand::ConstPtr& m) { seen.push_back(*m); }
  // Index of the first command `name` at or after `from`, -1 if none.
  int find(const std::string& name, std::size_t from = 0) const {
    for (std::size_t i = from; i < seen.size(); ++i)
      if (seen[i].name == name) return static_cast<int>(i);
    return -1;
  }
};

RefereeCommand op(const std::string& name, const std::string& team = "") {
  RefereeCommand m;
  m.name = name;
  m.team = team;
  return m;
}

TEST(MatchPlugin, RefereeCommandsOnTheTopic) {
  ros::NodeHandle nh;
  Referee ref;
  nav_msgs::Odometry ball;
  int balls = 0;
  ros::Subscriber s = nh.subscribe("/referee", 50, &Referee::on, &ref);
  ros::Subscriber b = nh.subscribe<nav_msgs::Odometry>("/ball/ground_truth", 10,
                                                       [&](const nav_msgs::Odometry::ConstPtr& m) {
                                                         ball = *m;
                                                         ++balls;
                                                       });
  ros::Publisher pub = nh.advertise<RefereeCommand>("/referee/operator", 10);

  // Kick-off for cyan at the centre at t = 0, start 2 simulated seconds
  // later (restart_delay; 0.5 s of wall time at factor 4).
  wait_for([&] { return ref.find("start") >= 0 && pub.getNumSubscribers() > 0 && balls > 0; }, 30.0);
  const int kickoff = ref.find("kick_off");
  ASSERT_GE(kickoff, 0) << "no kick_off on /referee";
  const RefereeCommand& k = ref.seen[static_cast<std::size_t>(kickoff)];
  EXPECT_EQ(k.command, RefereeCommand::KICK_OFF);
  EXPECT_EQ(k.team, "cyan");
  EXPECT_EQ(k.x, 0.0);
  ASSERT_EQ(k.teams.size(), 2u);
  EXPECT_EQ(k.teams[1], "magenta");
  ASSERT_GE(ref.find("start"), kickoff + 1);
  EXPECT_GT(balls, 0) << "no /ball/ground_truth";
  EXPECT_EQ(ball.header.frame_id, "world");

  // The operator stops, then starts, play.
  std::size_t from = ref.seen.size();
  pub.publish(op("stop"));
  wait_for([&] { return ref.find("stop", from) >= 0; }, 10.0);
  ASSERT_GE(ref.find("stop", from), 0) << "the operator's stop was not published";
  EXPECT_EQ(ref.seen[static_cast<std::size_t>(ref.find("stop", from))].command, RefereeCommand::STOP);
  from = ref.seen.size();
  pub.publish(op("start"));
  wait_for([&] { return ref.find("start", from) >= 0; }, 10.0);
  ASSERT_GE(ref.find("start", from), 0) << "the operator's start was not published";

  // A malformed command is dropped; then a goal for magenta: 0-1 and a
  // kick-off for cyan.
  from = ref.seen.size();
  pub.publish(op("penalty"));
  pub.publish(op("goal", "magenta"));
  wait_for([&] { return ref.find("kick_off", from) >= 0; }, 15.0);
  const int goal = ref.find("goal", from);
  ASSERT_GE(goal, 0);
  const RefereeCommand& g = ref.seen[static_cast<std::size_t>(goal)];
  EXPECT_EQ(g.team, "magenta");
  ASSERT_EQ(g.score.size(), 2u);
  EXPECT_EQ(g.score[0], 0u);
  EXPECT_EQ(g.score[1], 1u);
  const int k2 = ref.find("kick_off", from);
  ASSERT_GT(k2, goal);
  EXPECT_EQ(ref.seen[static_cast<std::size_t>(k2)].team, "cyan");
  EXPECT_EQ(ref.find("penalty", from), -1);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mrt_robocup_match_rostest");
  return RUN_ALL_TESTS();
}
