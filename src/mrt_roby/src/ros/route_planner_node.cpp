// route_planner_node: Roby's external planner: publishes the route over the
// map of buildings, and on every re-plan request a new plan from the current
// pose, its legs round the buildings planned by SPIKE (mrt_spike).
#include <geometry_msgs/PoseStamped.h>
#include <mrt_msgs/PlanRequest.h>
#include <nav_msgs/Path.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <cmath>

#include "mrt_common_ros/params.h"
#include "mrt_roby/route_planner.h"

namespace {

using namespace mrt::roby;

class PlannerNode {
 public:
  PlannerNode(ros::NodeHandle& nh, RoutePlanner planner, Point2D start)
      : planner_(std::move(planner)) {
    path_pub_ = nh.advertise<nav_msgs::Path>("path", 5, true);
    marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("map_markers", 1, true);
    sub_ = nh.subscribe("replan_request", 5, &PlannerNode::on_request, this);
    diag_.setHardwareID("route planner");
    diag_.add("route planner", this, &PlannerNode::diagnose);
    diag_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diag_.update(); });
    route_ = planner_.plan(start);
    last_size_ = route_.size();
    publish_markers();
    publish(route_);
  }

 private:
  void on_request(const mrt_msgs::PlanRequest& r) {
    if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.failed_x) || !std::isfinite(r.failed_y)) {
      ++dropped_;
      ROS_WARN_THROTTLE(5, "dropped a non-finite plan request");
      return;
    }
    ++replans_;
    ROS_INFO("re-plan from (%.2f, %.2f): path point (%.2f, %.2f) unreachable (%s)", r.x, r.y, r.failed_x,
             r.failed_y, r.reason.c_str());
    std::vector<Point2D> plan;
    try {
      plan = planner_.replan({r.x, r.y}, {r.failed_x, r.failed_y});
    } catch (const std::runtime_error& e) {
      ROS_ERROR("no plan from (%.2f, %.2f): %s; sending an empty plan (stop)", r.x, r.y, e.what());
      ++failed_;
      last_error_ = e.what();
    }
    last_size_ = plan.size();
    publish(plan);
    publish_markers();
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    if (last_size_ == 0)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "empty plan: " + (last_error_.empty() ? std::string("route done") : last_error_));
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "plan of " + std::to_string(last_size_) + " path points");
    st.add("re-plans", replans_);
    st.add("re-plans without a plan", failed_);
    st.add("requests dropped", dropped_);
    st.add("path points in the last plan", last_size_);
  }

  void publish(const std::vector<Point2D>& pts) {
    nav_msgs::Path p;
    p.header.stamp = ros::Time::now();
    p.header.frame_id = planner_.map().frame;
    for (const auto& q : pts) {
      geometry_msgs::PoseStamped ps;
      ps.header = p.header;
      ps.pose.position.x = q.x;
      ps.pose.position.y = q.y;
      ps.pose.orientation.w = 1.0;
      p.poses.push_back(ps);
    }
    ROS_INFO("plan of %zu path points", pts.size());
    path_pub_.publish(p);
  }

  void publish_markers() {
    visualization_msgs::MarkerArray a;
    const auto& m = planner_.map();
    visualization_msgs::Marker mk;
    mk.header.frame_id = m.frame;
    mk.header.stamp = ros::Time::now();
    mk.action = visualization_msgs::Marker::DELETEALL;
    a.markers.push_back(mk);
    mk.action = visualization_msgs::Marker::ADD;
    mk.pose.orientation.w = 1.0;
    int id = 0;
    for (const auto& b : m.buildings) {
      mk.ns = "buildings";
      mk.id = id++;
      mk.type = visualization_msgs::Marker::CUBE;
      mk.pose.position.x = (b.xmin + b.xmax) / 2;
      mk.pose.position.y = (b.ymin + b.ymax) / 2;
      mk.pose.position.z = 1.0;
      mk.scale.x = b.xmax - b.xmin;
      mk.scale.y = b.ymax - b.ymin;
      mk.scale.z = 2.0;
      mk.color.r = mk.color.g = mk.color.b = 0.55f;
      mk.color.a = 0.5f;
      a.markers.push_back(mk);
      visualization_msgs::Marker t = mk;
      t.ns = "building_names";
      t.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
      t.text = b.name;
      t.pose.position.z = 2.5;
      t.scale.x = t.scale.y = t.scale.z = 1.0;
      t.color.r = t.color.g = t.color.b = t.color.a = 1.0f;
      a.markers.push_back(t);
    }
    id = 0;
    for (std::size_t i = 0; i < route_.size(); ++i) {
      mk.ns = "route_points";
      mk.id = id++;
      mk.type = visualization_msgs::Marker::CYLINDER;
      mk.pose.position.x = route_[i].x;
      mk.pose.position.y = route_[i].y;
      mk.pose.position.z = 0.02;
      mk.scale.x = mk.scale.y = 0.4;
      mk.scale.z = 0.04;
      const bool bad = i < planner_.unreachable().size() && planner_.unreachable()[i];
      mk.color.r = bad ? 1.0f : 0.1f;
      mk.color.g = bad ? 0.1f : 0.3f;
      mk.color.b = bad ? 0.1f : 1.0f;
      mk.color.a = 0.9f;
      a.markers.push_back(mk);
      visualization_msgs::Marker t = mk;
      t.ns = "route_labels";
      t.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
      t.text = "P" + std::to_string(i + 1);
      t.pose.position.x += 0.5;
      t.pose.position.y += 0.5;
      t.scale.x = t.scale.y = t.scale.z = 0.8;
      t.color.r = t.color.g = t.color.b = t.color.a = 1.0f;
      a.markers.push_back(t);
    }
    marker_pub_.publish(a);
  }

  RoutePlanner planner_;
  std::vector<Point2D> route_;
  ros::Publisher path_pub_, marker_pub_;
  ros::Subscriber sub_;
  diagnostic_updater::Updater diag_;
  ros::Timer diag_timer_;
  int replans_ = 0, failed_ = 0, dropped_ = 0;
  std::size_t last_size_ = 0;
  std::string last_error_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "route_planner");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader p(pnh);
    std::string map;
    std::vector<double> start{0.0, 0.0};
    p.require("map", map, "the road map YAML file").get("start", start);
    p.check(start.size() == 2, "start", "[x, y]");
    RoutePlanner planner(load_road_map(map));
    try {
      PlannerNode node(nh, std::move(planner), {start[0], start[1]});
      ros::spin();
    } catch (const std::invalid_argument& e) {  // a leg of the route too close to a building
      throw std::runtime_error(map + ": " + e.what());
    }
    return 0;
  });
}
