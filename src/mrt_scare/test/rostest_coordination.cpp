// rostest: three scare_coordinator nodes (coordination.test). This node
// plays MAP and the robots' localisation: it publishes the robots' poses
// and the shared world model, and checks the jobs they publish.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <mrt_msgs/CoordinationParameters.h>
#include <mrt_msgs/CrispDataArray.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>

#include <array>
#include <map>
#include <set>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

struct Harness {
  ros::NodeHandle nh;
  std::array<ros::Publisher, 3> pose_pub, enable_pub;
  std::array<ros::Subscriber, 3> job_sub;
  std::array<std::string, 3> job;
  std::array<bool, 3> have{false, false, false};
  ros::Publisher world_pub = nh.advertise<mrt_msgs::CrispDataArray>("/world_crisp", 5);
  std::map<std::string, double> world;
  const std::array<std::array<double, 2>, 3> poses{{{0.0, 1.0}, {1.0, 0.5}, {2.5, -2.0}}};
  ros::Timer timer;
  // robot2 on the team topic: the stamp of its first message as passer, and
  // the intention_since of its first and latest such messages.
  double passer_first_stamp = -1.0, passer_first_since = -1.0, passer_last_since = -1.0;
  ros::Subscriber team_sub = nh.subscribe<mrt_msgs::CoordinationParameters>(
      "/scare/team", 50, [this](const mrt_msgs::CoordinationParameters::ConstPtr& m) {
        if (m->robot_id != "robot2" || m->intention != "PassageToMate.passer") return;
        if (passer_first_stamp < 0.0) {
          passer_first_stamp = m->header.stamp.toSec();
          passer_first_since = m->intention_since;
        }
        passer_last_since = m->intention_since;
      });

  Harness() {
    for (int i = 0; i < 3; ++i) {
      const std::string ns = "/robot" + std::to_string(i + 1) + "/";
      pose_pub[i] = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>(ns + "pose", 5);
      enable_pub[i] = nh.advertise<std_msgs::Bool>(ns + "scare/enable", 5, true);
      job_sub[i] = nh.subscribe<std_msgs::String>(ns + "scare/job", 5, [this, i](const std_msgs::String::ConstPtr& m) {
        job[i] = m->data;
        have[i] = true;
      });
    }
    timer = nh.createTimer(ros::Duration(0.05), [this](const ros::TimerEvent&) { publish(); });
  }

  void publish() {
    for (int i = 0; i < 3; ++i) {
      geometry_msgs::PoseWithCovarianceStamped o;
      o.header.frame_id = "map";
      o.header.stamp = ros::Time::now();
      o.pose.pose.position.x = poses[i][0];
      o.pose.pose.position.y = poses[i][1];
      o.pose.pose.orientation.w = 1.0;
      pose_pub[i].publish(o);
    }
    mrt_msgs::CrispDataArray w;
    w.header.stamp = ros::Time::now();
    for (const auto& [name, value] : world) {
      mrt_msgs::CrispData d;
      d.name = name;
      d.value = value;
      d.reliability = 1.0;
      w.data.push_back(d);
    }
    world_pub.publish(w);
  }

  void set_world(double ball_x, double threat, double shot_clear) {
    world = {{"BallX", ball_x},         {"BallY", 1.0},     {"BallSeen", 1.0},  {"BallOwned", 0.9},
             {"ShotClear", shot_clear}, {"Threat", threat}, {"ReceiveX", 3.0}, {"ReceiveY", -2.0}};
  }

  std::multiset<std::string> jobs(int n = 3) const { return {job.begin(), job.begin() + n}; }
};

bool stable_for(const std::function<bool()>& pred, double seconds) {
  // pred must hold continuously for `seconds` (1 s of allocations at 10 Hz).
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::WallTime::now() < end) {
    if (!pred()) return false;
    mrt::ros_common::spin_for(0.05);
  }
  return true;
}

}  // namespace

TEST(Coordination, AllocateThenReallocateWhenARobotStops) {
  Harness h;
  // Ball at (2, 1), shot clear: BringBall 0.9, Defense 0.5, the passage 0.1.
  // Hand-worked (README): robot2 brings the ball (0.59), robot1 defends
  // (1.2 * 0.5 * 0.188 = 0.113), robot3 positions itself (0.05).
  h.set_world(2.0, 0.5, 0.9);
  const std::multiset<std::string> attack{"BringBall", "Defense", "Positioning"};
  ASSERT_TRUE(mrt::ros_common::wait_for([&] { return h.have[0] && h.have[1] && h.have[2] && h.jobs() == attack; }, 20))
      << h.job[0] << " " << h.job[1] << " " << h.job[2];
  EXPECT_EQ(h.job[0], "Defense");
  EXPECT_EQ(h.job[1], "BringBall");

  // Ball at (0.5, 1), shot blocked: the passage (0.9) heads the agenda
  // (test/data/passing.yaml: 0.6555 + 0.6703 + 0.1355).
  h.set_world(0.5, 0.6, 0.1);
  const std::multiset<std::string> pass{"Defense", "PassageToMate.passer", "PassageToMate.receiver"};
  ASSERT_TRUE(mrt::ros_common::wait_for([&] { return h.jobs() == pass; }, 10))
      << h.job[0] << " " << h.job[1] << " " << h.job[2];
  EXPECT_EQ(h.job[0], "Defense");
  EXPECT_EQ(h.job[1], "PassageToMate.passer");
  EXPECT_EQ(h.job[2], "PassageToMate.receiver");
  EXPECT_TRUE(stable_for([&] { return h.jobs() == pass; }, 1.0));  // no flip-flop
  // The dwell's clock on the wire: robot2 took the passer role in the step
  // of the cycle before it first announced it (a 0.1 s cycle earlier, same
  // clock), and the time stays the same while it holds the role.
  ASSERT_GT(h.passer_first_stamp, 0.0);
  EXPECT_LT(h.passer_first_since, h.passer_first_stamp);
  EXPECT_GT(h.passer_first_since, h.passer_first_stamp - 0.25);
  EXPECT_DOUBLE_EQ(h.passer_last_since, h.passer_first_since);

  // robot3 stops: silent, it is dropped after 1 s and its role filled again.
  std_msgs::Bool off;
  off.data = false;
  h.enable_pub[2].publish(off);
  const std::multiset<std::string> two{"PassageToMate.passer", "PassageToMate.receiver"};
  const ros::WallTime stopped = ros::WallTime::now();
  ASSERT_TRUE(mrt::ros_common::wait_for([&] { return h.jobs(2) == two; }, 5)) << h.job[0] << " " << h.job[1];
  EXPECT_LT((ros::WallTime::now() - stopped).toSec(), 1.0 + 0.5);  // drop_timeout + a few cycles
  EXPECT_EQ(h.job[0], "PassageToMate.receiver");
  EXPECT_TRUE(stable_for([&] { return h.jobs(2) == two; }, 1.0));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "coordination_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
