// scare_node: the generic SCARE sequencer node (see
// include/mrt_scare/ros/sequencer_node.h). Applications that feed the active
// path point to their behaviours run their own node around SequencerNode
// (Roby: mrt_roby's roby_scare_node).
#include <ros/ros.h>

#include "mrt_common_ros/params.h"
#include "mrt_scare/ros/sequencer_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "scare");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    mrt::ros_common::ParamReader params(pnh);
    mrt::scare::SequencerNode node(nh, mrt::scare::SequencerNodeOptions::read(params));
    ros::spin();
    return 0;
  });
}
