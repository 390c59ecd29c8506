// rostest (sequencer_job.test): scare_node executes the job scare_coordinator
// publishes, reports a hand-back, and gets another job.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/TaskStatus.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <map>
#include <string>
#include <vector>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::wait_for;

TEST(SequencerJob, RunsTheJobAndHandsItBack) {
  ros::NodeHandle nh;
  std::vector<std::string> jobs, hand_backs, events;
  std::string task, status_frame;
  double blocked = 0.0;
  auto job_sub = nh.subscribe<std_msgs::String>("/robot1/scare/job", 5,
                                                [&](const std_msgs::String::ConstPtr& m) { jobs.push_back(m->data); });
  auto back_sub = nh.subscribe<std_msgs::String>(
      "/robot1/scare/hand_back", 5, [&](const std_msgs::String::ConstPtr& m) { hand_backs.push_back(m->data); });
  auto status_sub = nh.subscribe<mrt_msgs::TaskStatus>("/robot1/task_status", 50,
                                                       [&](const mrt_msgs::TaskStatus::ConstPtr& s) {
                                                         status_frame = s->header.frame_id;
                                                         if (s->event.empty()) return;
                                                         events.push_back(s->event);
                                                         if (s->event == "task_started") task = s->task;
                                                       });
  auto pose_pub = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("/robot1/pose", 5);
  auto world_pub = nh.advertise<mrt_msgs::CrispDataArray>("/robot1/world_crisp", 5);
  auto timer = nh.createTimer(ros::Duration(0.05), [&](const ros::TimerEvent&) {
    geometry_msgs::PoseWithCovarianceStamped o;
    o.header.frame_id = "map";
    o.header.stamp = ros::Time::now();
    o.pose.pose.orientation.w = 1.0;
    pose_pub.publish(o);
    // The worked example of test_coordinator.cpp (Defense opportune) and Blocked.
    mrt_msgs::CrispDataArray w;
    w.header.stamp = o.header.stamp;
    for (const auto& [name, value] : std::map<std::string, double>{
             {"BallX", 0.5}, {"BallY", 1.0}, {"BallSeen", 1.0}, {"BallOwned", 0.9}, {"ShotClear", 0.1},
             {"Threat", 0.6}, {"ReceiveX", 3.0}, {"ReceiveY", -2.0}, {"Blocked", blocked}}) {
      mrt_msgs::CrispData d;
      d.name = name;
      d.value = value;
      d.reliability = 1.0;
      w.data.push_back(d);
    }
    world_pub.publish(w);
  });
  // The coordinator's first real job reaches the sequencer, which starts Work.
  ASSERT_TRUE(wait_for([&] { return !jobs.empty() && !jobs.back().empty() && task == "Work"; }, 15.0));
  const std::string first = jobs.back();
  EXPECT_TRUE(hand_backs.empty());
  // Blocked: the task's failure hands the job back; the coordinator leaves it.
  blocked = 1.0;
  ASSERT_TRUE(wait_for([&] { return !hand_backs.empty(); }, 5.0));
  EXPECT_EQ(hand_backs.front(), first);
  ASSERT_TRUE(wait_for([&] { return jobs.back() != first; }, 5.0)) << "still " << first;
  bool handed = false;
  for (const auto& e : events) handed = handed || e == "handed_back";
  EXPECT_TRUE(handed);
  EXPECT_EQ(status_frame, "map");  // ~frame's default (REP-105)
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sequencer_job_test");
  ros::NodeHandle nh;  // callbacks run in wait_for's spinOnce
  return RUN_ALL_TESTS();
}
