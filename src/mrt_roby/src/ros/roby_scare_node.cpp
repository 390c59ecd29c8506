// roby_scare_node: mrt_scare's sequencer node with Roby's outputs added to
// its cycle: the active path point as the rule base's crisp data, and the
// remote controller (tele-operation). Wiring only. Diagnostics: the
// sequencer's ("sequencer", SequencerNode) with the remote commands
// counted (tele-operation only: no timeout), the dropped ones too.
#include <geometry_msgs/Twist.h>
#include <mrt_msgs/CrispDataArray.h>
#include <ros/ros.h>

#include <cmath>
#include <optional>

#include "crisp_msg.h"
#include "mrt_common_ros/node_diagnostics.h"
#include "mrt_common_ros/params.h"
#include "mrt_roby/crisp_builder.h"
#include "mrt_scare/ros/sequencer_node.h"

namespace {

using namespace mrt::roby;
using namespace mrt::roby::node;

/// The remote controller's last command, until ~remote_timeout old.
class RemoteInput {
 public:
  RemoteInput(ros::NodeHandle& nh, double timeout, mrt::ros_common::NodeDiagnostics& diag)
      : timeout_(timeout), diag_(diag) {
    sub_ = nh.subscribe("remote_cmd", 10, &RemoteInput::on_remote, this);
    diag_.count("remote commands", 0);  // shown from the start
    diag_.count("remote commands dropped (non-finite)", 0);
  }
  std::optional<RemoteCommand> fresh(const ros::Time& now) const {
    if (remote_ && (now - time_).toSec() < timeout_) return remote_;
    return std::nullopt;
  }

 private:
  void on_remote(const geometry_msgs::Twist& t) {
    diag_.count("remote commands");
    if (!std::isfinite(t.linear.x) || !std::isfinite(t.angular.z)) {
      diag_.count("remote commands dropped (non-finite)");
      ROS_WARN_THROTTLE(5, "dropped a non-finite remote command");
      return;
    }
    remote_ = RemoteCommand{t.linear.x, t.angular.z};
    time_ = ros::Time::now();
  }

  double timeout_;
  mrt::ros_common::NodeDiagnostics& diag_;
  std::optional<RemoteCommand> remote_;
  ros::Time time_;
  ros::Subscriber sub_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "scare");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader params(pnh);
    const auto options = mrt::scare::SequencerNodeOptions::read(params);
    double remote_timeout = 0.5;
    params.get_positive("remote_timeout", remote_timeout);
    std::optional<RemoteInput> remote;  // after the node: it counts in the node's diagnostics
    ros::Publisher crisp_pub = nh.advertise<mrt_msgs::CrispDataArray>("goal_crisp", 10);
    mrt::scare::SequencerNode node(
        nh, options,
        [&](const ros::Time& now, const mrt::scare::Sequencer& seq, const std::optional<mrt::common::Pose2D>& pose) {
          std::optional<GoalCrisp> goal;
          if (pose && seq.active()) goal = mrt::scare::goal_crisp(*pose, seq.active()->goal());
          CrispDataList data;
          goal_crisp_data(seq.mode(), goal, data);
          remote_crisp_data(remote ? remote->fresh(now) : std::nullopt, data);
          crisp_pub.publish(to_msg(data, now));
        });
    remote.emplace(nh, remote_timeout, node.diagnostics());
    ros::spin();
    return 0;
  });
}
