// The SCARE sequencer as a ROS node (library mrt_scare_ros; the only ROS
// header of the package). Plans and poses in; task status, re-plan requests
// and the active path point out. An application adds what its behaviours
// need from the sequencer (Roby: the goal as Mr. BRIAN crisp data) through
// the cycle hook, in the same node and cycle. Diagnostics "sequencer"
// (mrt_common_ros's NodeDiagnostics): the pose expected within
// ~pose_timeout (2 s when 0), the messages of the sporadic inputs counted;
// an application adds its own through diagnostics().
#pragma once

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/PlanRequest.h>
#include <mrt_msgs/TaskStatus.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_scare/sequencer.h"

namespace mrt::scare {

/// The node's parameters, read once.
struct SequencerNodeOptions {
  std::string tasks;           // ~tasks: the task file (required)
  double rate = 10.0;          // ~rate: Hz of monitoring, in (0, 1000]
  double pose_timeout = 2.0;   // ~pose_timeout: s without a pose before monitoring stops (0 = never)
  std::string frame = "map";   // ~frame: frame of the plan and the pose (REP-105)
  Mode mode = Mode::kAuto;     // ~mode: auto or manual at start-up

  /// Reads and validates the parameters above; throws ros_common::ParamError.
  static SequencerNodeOptions read(ros_common::ParamReader& p);
};

/// "auto" / "manual".
std::optional<Mode> parse_mode(const std::string& s);

class SequencerNode {
 public:
  /// Called every cycle (1 / ~rate), after the sequencer has seen the pose;
  /// `pose` is the current pose when it is fresh.
  using CycleHook =
      std::function<void(const ros::Time& now, const Sequencer& seq, const std::optional<Pose2D>& pose)>;

  /// Loads the task file (throws common::ParseError) and starts the topics.
  SequencerNode(ros::NodeHandle& nh, const SequencerNodeOptions& o, CycleHook hook = {});

  /// The node's diagnostics, for an application's own inputs and counters.
  ros_common::NodeDiagnostics& diagnostics() { return diag_; }

 private:
  void on_path(const nav_msgs::Path& p);
  void apply_plan();
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m);
  void on_mode(const std_msgs::String& m);
  void on_job(const std_msgs::String& j);
  void apply_job();
  void on_world(const mrt_msgs::CrispDataArray& w);
  void on_timer(const ros::TimerEvent&);
  void handle(const std::vector<SequencerEvent>& events);
  void publish_goal();
  void publish_status(const std::string& event, const SequencerEvent* e = nullptr);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& st);

  Sequencer seq_;
  double pose_timeout_;
  std::string frame_;
  CycleHook hook_;
  std::optional<Pose2D> pose_;
  ros::Time pose_time_;
  std::vector<Point2D> pending_;
  bool have_pending_ = false;
  std::string pending_job_;
  bool have_pending_job_ = false;
  std::size_t dropped_ = 0;
  unsigned ticks_ = 0;
  ros::Publisher status_pub_, replan_pub_, goal_pub_, hand_back_pub_;
  ros::Subscriber path_sub_, pose_sub_, mode_sub_, job_sub_, world_sub_;
  ros::Timer timer_;
  ros_common::NodeDiagnostics diag_;
};

}  // namespace mrt::scare
