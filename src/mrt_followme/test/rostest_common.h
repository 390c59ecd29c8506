// What the FollowMe rostests read from followme_node: the tour's status
// lines, the plans and the summary (parsed back into numbers).
#pragma once

#include <gtest/gtest.h>
#include <mrt_followme/SetTour.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <mrt_msgs/TourStatus.h>
#include <std_msgs/String.h>

#include <cstdio>
#include <string>
#include <vector>

struct Summary {
  bool received = false;
  std::string text;
  int visited = -1;
  std::string names;
  int wanders = -1;
  bool completed = false;
  double time = -1, unseen = -1, pose_error = -1, person_gap = -1;
};

class FollowMeObserver {
 public:
  explicit FollowMeObserver(ros::NodeHandle& nh) {
    status_ = nh.subscribe<mrt_msgs::TourStatus>("/robot1/tour_status", 100, [this](const mrt_msgs::TourStatus::ConstPtr& m) {
      // "Job | next X | visited N | wanders W" (the fields but the time)
      const std::string s = m->job + " | next " + (m->next.empty() ? "-" : m->next) + " | visited " +
                            std::to_string(m->visited.size()) + " | wanders " + std::to_string(m->wanders);
      if (statuses.empty() || statuses.back() != s) statuses.push_back(s);
    });
    summary_ = nh.subscribe<std_msgs::String>("/robot1/tour_summary", 1, [this](const std_msgs::String::ConstPtr& m) {
      parse(m->data);
    });
    plan_ = nh.subscribe<nav_msgs::Path>("/robot1/plan", 20, [this](const nav_msgs::Path::ConstPtr& m) {
      plans.push_back(*m);
    });
  }

  bool wait(double seconds) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && !summary.received && ros::WallTime::now() < end) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
    return summary.received;
  }

  bool saw(const std::string& prefix) const {
    for (const auto& s : statuses)
      if (s.compare(0, prefix.size(), prefix) == 0) return true;
    return false;
  }

  Summary summary;
  std::vector<std::string> statuses;
  std::vector<nav_msgs::Path> plans;

 private:
  void parse(const std::string& t) {
    summary.received = true;
    summary.text = t;
    char names[256] = {0}, done[8] = {0};
    const char* p = t.c_str();
    std::sscanf(p, "exhibits visited: %d (%255[^)])", &summary.visited, names);
    summary.names = names;
    auto field = [&](const char* key, const char* fmt, void* out) {
      const auto at = t.find(key);
      if (at != std::string::npos) std::sscanf(t.c_str() + at + std::string(key).size(), fmt, out);
    };
    field("wanders handled: ", "%d", &summary.wanders);
    field("completed: ", "%7s", done);
    summary.completed = std::string(done) == "yes";
    field("time: ", "%lf", &summary.time);
    field("out of sight: ", "%lf", &summary.unseen);
    field("ground truth): ", "%lf", &summary.pose_error);
    field("closest to a person: ", "%lf", &summary.person_gap);
  }

  ros::Subscriber status_, summary_, plan_;
};

/// Does the path cross the vertical line x = x_line between y0 and y1?
inline bool crosses(const nav_msgs::Path& path, double x_line, double y0, double y1) {
  for (std::size_t i = 1; i < path.poses.size(); ++i) {
    const auto& a = path.poses[i - 1].pose.position;
    const auto& b = path.poses[i].pose.position;
    if ((a.x - x_line) * (b.x - x_line) > 0 || a.x == b.x) continue;
    const double y = a.y + (b.y - a.y) * (x_line - a.x) / (b.x - a.x);
    if (y >= y0 && y <= y1) return true;
  }
  return false;
}

// The dialogue (`service`) refuses a tour naming an exhibit twice.
inline void expect_twice_refused(const std::string& service, double wait_s) {
  ASSERT_TRUE(ros::service::waitForService(service, ros::Duration(wait_s)));
  mrt_followme::SetTour srv;
  srv.request.exhibits = {"statue", "statue"};
  ASSERT_TRUE(ros::service::call(service, srv));
  EXPECT_FALSE(srv.response.accepted);
  EXPECT_EQ(srv.response.message, "exhibit 'statue' twice in the tour");
}

// The bounds on the 4-exhibit tour with one wander: every exhibit
// in order, the wander, the visitor never out of sight > 10 s, nobody
// closer than 0.3 m, MUREA's error < 10 cm, a WaitVisitor at each exhibit.
inline void expect_tour_with_one_wander(const FollowMeObserver& obs) {
  const Summary& s = obs.summary;
  EXPECT_TRUE(s.completed) << s.text;
  EXPECT_EQ(s.visited, 4) << s.text;
  EXPECT_EQ(s.names, "statue, pedestal, sculpture, vase");
  EXPECT_EQ(s.wanders, 1);
  EXPECT_LE(s.unseen, 10.0);
  EXPECT_GE(s.person_gap, 0.3);
  EXPECT_GE(s.pose_error, 0.0);
  EXPECT_LT(s.pose_error, 0.10);
  for (const char* e : {"statue", "pedestal", "sculpture", "vase"})
    EXPECT_TRUE(obs.saw(std::string("WaitVisitor | next ") + e)) << e;
}
