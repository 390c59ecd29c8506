// team_markers_node: each robot's SCARE job and role, drawn where it thinks
// it is. For every robot of ~robots (namespaces) it subscribes
// /<robot>/scare/job (std_msgs/String: "BringBall", "PassageToMate.passer",
// "" waiting) and /<robot>/pose (MUREA's PoseWithCovarianceStamped) and
// publishes `team_markers` (visualization_msgs/MarkerArray, ~frame) at
// ~rate Hz: a text "robotN: Job / role" above the estimated pose and a disc
// under it in the job's colour (grey while waiting). rviz: robocup.rviz.
// Diagnostics "team markers": each robot's pose expected every 2 s (MUREA),
// its job messages (on change only: counted, no timeout), the arrays
// published.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include <array>
#include <functional>
#include <map>

#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"

namespace {

// A stable colour per activity: one of eight, by the name's hash.
std::array<float, 3> job_color(const std::string& job) {
  static const std::array<std::array<float, 3>, 8> palette{{{1.0f, 0.3f, 0.3f}, {1.0f, 0.7f, 0.1f}, {0.9f, 1.0f, 0.2f},
                                                           {0.3f, 1.0f, 0.4f}, {0.2f, 0.9f, 1.0f}, {0.4f, 0.5f, 1.0f},
                                                           {0.9f, 0.4f, 1.0f}, {1.0f, 0.5f, 0.8f}}};
  if (job.empty()) return {0.6f, 0.6f, 0.6f};
  return palette[std::hash<std::string>{}(job) % palette.size()];
}

struct Robot {
  std::string job;
  bool have_pose = false;
  double x = 0.0, y = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "team_markers");
  return mrt::ros_common::run_node([]() -> int {
    ros::NodeHandle nh, pnh("~");
    std::vector<std::string> names{"robot1", "robot2", "robot3", "robot4"};
    std::string frame = "map";
    double rate = 5.0;
    mrt::ros_common::ParamReader(pnh).get("robots", names).get("frame", frame).get_positive("rate", rate);
    std::map<std::string, Robot> robots;
    std::vector<ros::Subscriber> subs;
    mrt::ros_common::NodeDiagnostics diag(nh, "team markers", "none", [&](auto& st) {
      st.add("robots", names.size());
      st.add("frame", frame);
    });
    for (const std::string& r : names) {
      robots[r];
      diag.input(r + " pose", 2.0);
      diag.count(r + " job messages", 0);
      subs.push_back(nh.subscribe<std_msgs::String>("/" + r + "/scare/job", 5, [&robots, &diag, r](const std_msgs::String::ConstPtr& m) {
        diag.count(r + " job messages");
        robots[r].job = m->data;
      }));
      subs.push_back(nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
          "/" + r + "/pose", 5, [&robots, &diag, r](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
            diag.received(r + " pose");
            robots[r].have_pose = true;
            robots[r].x = m->pose.pose.position.x;
            robots[r].y = m->pose.pose.position.y;
          }));
    }
    ros::Publisher pub = nh.advertise<visualization_msgs::MarkerArray>("team_markers", 2);
    ros::Timer timer = nh.createTimer(ros::Duration(1.0 / rate), [&](const ros::TimerEvent&) {
      visualization_msgs::MarkerArray out;
      int id = 0;
      for (const std::string& name : names) {
        const Robot& r = robots[name];
        ++id;
        if (!r.have_pose) continue;
        const std::string job = r.job.substr(0, r.job.find('.'));
        const std::string role = r.job.find('.') == std::string::npos ? "" : r.job.substr(r.job.find('.') + 1);
        const auto c = job_color(job);
        visualization_msgs::Marker text;
        text.header.frame_id = frame;
        text.header.stamp = ros::Time::now();
        text.ns = "job";
        text.id = id;
        text.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
        text.pose.position.x = r.x;
        text.pose.position.y = r.y + 0.6;
        text.pose.position.z = 1.0;
        text.pose.orientation.w = 1.0;
        text.scale.z = 0.35;
        text.color.r = c[0];
        text.color.g = c[1];
        text.color.b = c[2];
        text.color.a = 1.0f;
        text.text = name + ": " + (job.empty() ? "(waiting)" : job) + (role.empty() ? "" : " / " + role);
        visualization_msgs::Marker disc = text;
        disc.ns = "estimate";
        disc.type = visualization_msgs::Marker::CYLINDER;
        disc.text.clear();
        disc.pose.position.y = r.y;
        disc.pose.position.z = 0.02;
        disc.scale.x = disc.scale.y = 0.7;
        disc.scale.z = 0.03;
        disc.color.a = 0.6f;
        out.markers.push_back(text);
        out.markers.push_back(disc);
      }
      pub.publish(out);
      diag.count("marker arrays published");
    });
    ros::spin();
    return 0;
  });
}
