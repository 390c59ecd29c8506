// The bridge's mapping file (YAML): which DCDT message types become which ROS
// topics and back, and as what kind of ROS message. ROS-free.
//
//   to_ros:                        # DCDT -> ROS
//     - type: MSG_FROM_VISION      # legacy name or number
//       topic: vision/percepts
//       kind: percept              # percept | crisp_data | commands | world_model | coordination | referee | raw
//       scope: all                 # local | remote | all (default all)
//   to_dcdt:                       # ROS -> DCDT
//     - topic: motion/commands
//       type: MSG_TO_MOTION
//       kind: commands
//       warranty: guaranteed       # none | retransmit | guaranteed (default)
#pragma once

#include <string>
#include <vector>

#include "mrt_dcdt/types.h"

namespace mrt::dcdt {

/// WORLD_MODEL: mrt_msgs/WorldModel (MAP's team exchange); COORDINATION:
/// mrt_msgs/CoordinationParameters (SCARE's team topic); REFEREE:
/// mrt_msgs/RefereeCommand (the referee box). README "Team data".
enum class PayloadKind { PERCEPT, CRISP_DATA, COMMANDS, WORLD_MODEL, COORDINATION, REFEREE, RAW };
const char* kind_name(PayloadKind k);

struct TopicMapping {
  int type = 0;
  std::string topic;
  PayloadKind kind = PayloadKind::PERCEPT;
  RequestType scope = DCDT_ALL_MSG;     ///< to_ros only
  int warranty = DCDT_DW_GUARANTEED;    ///< to_dcdt only
  int line = 0;
};

struct BridgeMapping {
  std::vector<TopicMapping> to_ros;
  std::vector<TopicMapping> to_dcdt;
};

/// Parses the YAML text; errors throw mrt::common::ParseError (file:line:col).
BridgeMapping parse_bridge_mapping(const std::string& text, const std::string& file);
BridgeMapping load_bridge_mapping(const std::string& path);

}  // namespace mrt::dcdt
