// visitor_node: the simulated visitor of the distributed FollowMe. It runs
// the visitor's behaviour model (VisitorModel: follows the robot, looks at
// the tour's exhibits, wanders off once, comes back when called or after a
// while) and steers the world's `guest` mover in sim_node through
// <guest>/goal. Like a person it sees the robot (its true pose); the robot
// sees it only through its camera. Simulation only.
#include <geometry_msgs/PointStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <mrt_msgs/Tour.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_followme/museum.h"
#include "mrt_followme/visitor_model.h"

namespace {

using namespace mrt::followme;

class VisitorNode {
 public:
  VisitorNode(ros::NodeHandle& nh, ros::NodeHandle& pnh) : diag_(nh, "FollowMe visitor", "simulated visitor") {
    mrt::ros_common::ParamReader p(pnh);
    std::string config, robot = "robot1", frame = "world";
    double rate = 10.0;
    int wander_after = -1;
    p.require("config", config, "config/followme/followme.yaml")
        .get("robot", robot)
        .get("frame", frame)
        .get("wander_after", wander_after)
        .get_positive("rate", rate);
    cfg_ = load_followme_config(config);
    if (wander_after >= 0) cfg_.visitor.wander_after = wander_after;
    frame_ = frame;
    robot_sub_ = nh.subscribe(robot + "/ground_truth", 5, &VisitorNode::on_robot, this);
    self_sub_ = nh.subscribe(cfg_.visitor.name + "/ground_truth", 5, &VisitorNode::on_self, this);
    tour_sub_ = nh.subscribe(robot + "/tour", 1, &VisitorNode::on_tour, this);
    call_sub_ = nh.subscribe(robot + "/call_visitor", 5, &VisitorNode::on_call, this);
    goal_pub_ = nh.advertise<geometry_msgs::PointStamped>(cfg_.visitor.name + "/goal", 5);
    diag_.input("robot ground_truth", 1.0);
    diag_.input("visitor ground_truth", 1.0);
    start(cfg_.tour);
    timer_ = nh.createTimer(ros::Duration(1.0 / rate), &VisitorNode::cycle, this);
  }

 private:
  void start(const std::vector<std::string>& names) {
    std::vector<Exhibit> tour;
    for (const auto& n : names) tour.push_back(cfg_.exhibits[cfg_.exhibit_index(n)]);
    const Exhibit wander = cfg_.visitor.wander_to.empty()
                               ? Exhibit{}
                               : cfg_.exhibits[cfg_.exhibit_index(cfg_.visitor.wander_to)];
    model_ = std::make_unique<VisitorModel>(cfg_.visitor, tour, wander);
  }

  void on_tour(const mrt_msgs::Tour& m) {
    try {
      start(m.exhibits);
    } catch (const std::exception& e) {
      std::string names;
      for (const auto& n : m.exhibits) names += (names.empty() ? "" : ",") + n;
      ROS_WARN("visitor: tour %s: %s", names.c_str(), e.what());
    }
  }

  void on_robot(const nav_msgs::Odometry& m) {
    diag_.received("robot ground_truth");
    robot_ = mrt::ros_common::to_pose2d(m.pose.pose);
  }
  void on_self(const nav_msgs::Odometry& m) {
    diag_.received("visitor ground_truth");
    self_ = Point2D{m.pose.pose.position.x, m.pose.pose.position.y};
  }
  void on_call(const std_msgs::Empty&) {
    ROS_INFO("visitor: called back");
    model_->call();
  }

  void cycle(const ros::TimerEvent&) {
    if (!robot_ || !self_) return;
    const VisitorStep s = model_->update(ros::Time::now().toSec(), *self_, *robot_);
    geometry_msgs::PointStamped g;
    g.header.stamp = ros::Time::now();
    g.header.frame_id = frame_;
    g.point.x = s.target.x;
    g.point.y = s.target.y;
    g.point.z = s.speed;
    goal_pub_.publish(g);
    if (model_->state() != last_) ROS_INFO("visitor: %s", to_string(model_->state()));
    last_ = model_->state();
  }

  FollowMeConfig cfg_;
  std::string frame_;
  std::unique_ptr<VisitorModel> model_;
  std::optional<Pose2D> robot_;
  std::optional<Point2D> self_;
  VisitorState last_ = VisitorState::kFollow;
  ros::Subscriber robot_sub_, self_sub_, tour_sub_, call_sub_;
  ros::Publisher goal_pub_;
  ros::Timer timer_;
  mrt::ros_common::NodeDiagnostics diag_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "visitor");
  ros::NodeHandle nh, pnh("~");
  return mrt::ros_common::run_node([&] {
    VisitorNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
