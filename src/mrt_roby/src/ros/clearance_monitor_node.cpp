// clearance_monitor_node (simulation only): the robot's clearance to every
// wall, post (cars, trees) and walking person, from ground truth: footprint
// circle to obstacle surface. For the demo summary and rviz. Diagnostics
// "clearance monitor": ground_truth expected every second (100 Hz), the
// movers' dynamic_markers every 2 s, the checks made; WARN closer than
// 0.3 m, ERROR in contact; the current and smallest clearance.
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <visualization_msgs/MarkerArray.h>

#include <cmath>
#include <limits>

#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_roby/roby_loop.h"
#include "mrt_sim/world.h"

namespace {

class Monitor {
 public:
  Monitor(ros::NodeHandle& nh, mrt::sim::World world, const std::string& robot)
      : world_(std::move(world)),
        diag_(nh, "clearance monitor", "simulation", [this](diagnostic_updater::DiagnosticStatusWrapper& st) {
          diagnose(st);
        }) {
    diag_.input("ground_truth", 1.0);
    diag_.input("dynamic_markers", 2.0);
    for (const auto& r : world_.robots)
      if (r.name == robot) radius_ = r.base.body_radius;
    world_.movers.clear();  // their live positions come from the markers
    clearance_pub_ = nh.advertise<std_msgs::Float64>(robot + "/clearance", 10);
    min_pub_ = nh.advertise<std_msgs::Float64>(robot + "/min_clearance", 10, true);
    gt_sub_ = nh.subscribe(robot + "/ground_truth", 50, &Monitor::on_truth, this);
    marker_sub_ = nh.subscribe("dynamic_markers", 5, &Monitor::on_markers, this);
  }

 private:
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) const {
    st.add("clearance (m)", last_);
    st.add("closest", what_);
    st.add("min clearance (m)", min_);
    if (last_ < 0.0)
      st.mergeSummary(diagnostic_msgs::DiagnosticStatus::ERROR, "in contact with " + what_);
    else if (last_ < 0.3)
      st.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, "closer than 0.3 m to " + what_);
  }

  void on_markers(const visualization_msgs::MarkerArray& a) {
    diag_.received("dynamic_markers");
    world_.movers.clear();
    for (const auto& m : a.markers) {
      if (m.ns != "movers" || m.action != visualization_msgs::Marker::ADD) continue;
      mrt::sim::Mover mv;
      mv.name = "person";
      mv.radius = m.scale.x / 2.0;
      mv.position = {m.pose.position.x, m.pose.position.y};
      world_.movers.push_back(mv);
    }
  }

  void on_truth(const nav_msgs::Odometry& o) {
    diag_.received("ground_truth");
    if (++count_ % 5 != 0) return;  // 20 Hz of 100
    std::string what;
    const double c = mrt::roby::world_clearance(&world_, o.pose.pose.position.x, o.pose.pose.position.y,
                                                 radius_, &what);
    diag_.count("clearance checks");
    last_ = c;
    what_ = what;
    if (c < min_) {
      min_ = c;
      if (c < 0.3) ROS_WARN("clearance %.3f m to %s", c, what.c_str());
    }
    std_msgs::Float64 f;
    f.data = c;
    clearance_pub_.publish(f);
    f.data = min_;
    min_pub_.publish(f);
  }

  mrt::sim::World world_;
  double radius_ = 0.25;
  double min_ = std::numeric_limits<double>::infinity();
  double last_ = std::numeric_limits<double>::infinity();
  std::string what_;
  unsigned count_ = 0;
  ros::Publisher clearance_pub_, min_pub_;
  ros::Subscriber gt_sub_, marker_sub_;
  mrt::ros_common::NodeDiagnostics diag_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "clearance_monitor");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader p(pnh);
    std::string world, robot = "robot1";
    p.require("world", world, "the mrt_sim world file").get("robot", robot);
    Monitor m(nh, mrt::sim::load_world(world), robot);
    ros::spin();
    return 0;
  });
}
