// followme_monitor_node: the measures of the distributed FollowMe in
// simulation, from ground truth (sim_node) and what the robot published:
// MUREA's error (against the truth at the pose's stamp), the closest a person came to the robot (footprints), the
// longest time the visitor was out of the camera's sight (no Person
// percept of its colour). When the guide node reports the tour over
// (tour_result) it publishes the summary (tour_summary, latched) in the
// format of the in-process followme_node, which ./scripts/demo.sh prints.
// Percept objects the ontology does not accept are dropped and counted
// (diagnostics).
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <mrt_msgs/TourMeasures.h>
#include <mrt_msgs/TourResult.h>
#include <std_msgs/String.h>

#include <cmath>
#include <deque>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "markers.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common/percept.h"
#include "mrt_common_ros/params.h"
#include "mrt_common_ros/percept_conversions.h"
#include "mrt_msgs/Percept.h"

namespace {

using mrt::common::Pose2D;

class Monitor {
 public:
  Monitor(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    mrt::ros_common::ParamReader p(pnh);
    std::string robot = "robot1";
    std::vector<std::string> people{"guest", "visitor1", "visitor2"};
    p.get("robot", robot)
        .get("people", people)
        .get("visitor_color", color_)
        .get_positive("robot_radius", robot_radius_)
        .get_positive("person_radius", person_radius_);
    // ground_truth comes at 100 Hz simulated (400 /s at factor 4): a queue
    // of 2.5 s at that rate, so that a busy moment does not drop the truth.
    truth_sub_ = nh.subscribe(robot + "/ground_truth", 1000, &Monitor::on_truth, this);
    pose_sub_ = nh.subscribe(robot + "/pose", 20, &Monitor::on_pose, this);
    percept_sub_ = nh.subscribe(robot + "/percepts", 20, &Monitor::on_percepts, this);
    result_sub_ = nh.subscribe(robot + "/tour_result", 1, &Monitor::on_result, this);
    for (const auto& n : people)
      people_subs_.push_back(nh.subscribe<nav_msgs::Odometry>(
          n + "/ground_truth", 5, [this, n](const nav_msgs::Odometry::ConstPtr& m) { on_person(n, *m); }));
    summary_pub_ = nh.advertise<std_msgs::String>(robot + "/tour_summary", 1, true);
    measures_pub_ = nh.advertise<mrt_msgs::TourMeasures>(robot + "/tour_measures", 5);
    timer_ = nh.createTimer(ros::Duration(1.0), &Monitor::report, this);
    diag_.setHardwareID("none");
    diag_.add("FollowMe monitor", this, &Monitor::diagnose);
  }

 private:
  void on_truth(const nav_msgs::Odometry& m) {
    truth_ = mrt::ros_common::to_pose2d(m.pose.pose);
    history_.push_back({m.header.stamp.toSec(), *truth_});
    while (history_.size() > 1 && history_.back().first - history_.front().first > 2.0) history_.pop_front();
    while (!poses_.empty() && poses_.front().first <= history_.back().first) {
      score(poses_.front().first, poses_.front().second);
      poses_.pop_front();
    }
  }

  /// MUREA's pose against the truth at its own stamp: a pose is held until
  /// the truth of its moment has arrived (a pose may come before the truth
  /// of its camera frame's moment), then compared with the truth
  /// interpolated at its stamp.
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    poses_.emplace_back(m.header.stamp.toSec(), mrt::ros_common::to_pose2d(m.pose.pose));
    while (poses_.size() > 1 && poses_.back().first - poses_.front().first > 2.0) poses_.pop_front();
  }

  void score(double t, const Pose2D& e) {
    if (history_.empty() || t < history_.front().first) return;  // older than the truth kept
    auto after = history_.begin();
    while (after->first < t) ++after;  // the first truth at or after t (exists: t <= the newest)
    const auto& [t1, p1] = *after;
    const auto& [t0, p0] = after == history_.begin() ? *after : *std::prev(after);
    const double w = t1 > t0 ? (t - t0) / (t1 - t0) : 1.0;
    const double x = p0.x + w * (p1.x - p0.x), y = p0.y + w * (p1.y - p0.y);
    const double err = std::hypot(e.x - x, e.y - y);
    if (err > r_.max_pose_error && err > 0.05)
      ROS_INFO("monitor: MUREA's error %.3f m at %.3f s (estimate %.3f %.3f %.3f, truth %.3f %.3f %.3f)", err, t, e.x, e.y,
               e.theta, x, y, p1.theta);
    r_.max_pose_error = std::max(r_.max_pose_error, err);
  }

  void on_person(const std::string& name, const nav_msgs::Odometry& m) {
    if (!truth_) return;
    const double gap = std::hypot(m.pose.pose.position.x - truth_->x, m.pose.pose.position.y - truth_->y) -
                       robot_radius_ - person_radius_;
    if (gap < r_.min_person_gap) {
      r_.min_person_gap = gap;
      r_.nearest_person = name;
    }
  }

  void on_percepts(const mrt_msgs::Percept& m) {
    const double t = m.header.stamp.toSec();
    bool seen = false;
    const std::size_t dropped = drops_.total();
    for (const auto& o : mrt::ros_common::accepted_objects(m, drops_))
      seen = seen || (o.membership_class == mrt::common::percept_class::kPerson && o.symbol("color") == color_);
    if (drops_.total() > dropped)
      ROS_WARN_THROTTLE(5.0, "followme_monitor: %zu percept objects the ontology does not accept dropped so far",
                        drops_.total());
    if (first_ < 0) first_ = last_seen_ = t;
    if (seen) last_seen_ = t;
    r_.max_unseen = std::max(r_.max_unseen, t - last_seen_);
  }

  void on_result(const mrt_msgs::TourResult& m) {
    r_.completed = m.completed;
    r_.time = m.time;
    r_.wanders = m.wanders;
    r_.visited = m.visited;
    std_msgs::String s;
    s.data = mrt::followme::node::summary(r_);
    summary_pub_.publish(s);
    ROS_INFO("tour %s:\n%s", r_.completed ? "completed" : "ended", s.data.c_str());
  }

  void report(const ros::TimerEvent&) {
    mrt_msgs::TourMeasures m;
    m.header.stamp = ros::Time::now();
    m.max_unseen = r_.max_unseen;
    m.max_pose_error = r_.max_pose_error;
    m.min_person_gap = r_.min_person_gap;
    measures_pub_.publish(m);
    diag_.update();
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st) {
    if (drops_.total() > 0)
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "percept objects dropped (not in the ontology)");
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "measuring");
    mrt::ros_common::report(st, drops_);
  }

  std::string color_ = "purple";
  mrt::common::PerceptDrops drops_;
  diagnostic_updater::Updater diag_;
  double robot_radius_ = 0.25, person_radius_ = 0.25, first_ = -1.0, last_seen_ = 0.0;
  std::optional<Pose2D> truth_;
  std::deque<std::pair<double, Pose2D>> history_;  // the last 2 s of ground truth
  std::deque<std::pair<double, Pose2D>> poses_;    // MUREA's poses waiting for their truth
  mrt::followme::FollowMeResult r_;
  ros::Subscriber truth_sub_, pose_sub_, percept_sub_, result_sub_;
  std::vector<ros::Subscriber> people_subs_;
  ros::Publisher summary_pub_, measures_pub_;
  ros::Timer timer_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "followme_monitor");
  ros::NodeHandle nh, pnh("~");
  return mrt::ros_common::run_node([&] {
    Monitor m(nh, pnh);
    ros::spin();
    return 0;
  });
}
