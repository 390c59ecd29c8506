// The bridge mapping file: the shipped examples parse; errors name file:line:col.
#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"
#include "mrt_dcdt_bridge/bridge_mapping.h"
#include "mrt_dcdt/config.h"

using namespace mrt::dcdt;
using mrt::common::ParseError;

namespace {

TEST(BridgeMapping, TestMappingParses) {
  auto m = load_bridge_mapping(std::string(DCDT_TEST_DATA) + "/bridge_mapping.yaml");
  ASSERT_EQ(m.to_ros.size(), 3u);
  EXPECT_EQ(m.to_ros[0].type, MSG_FROM_VISION);
  EXPECT_EQ(m.to_ros[0].topic, "vision/percepts");
  EXPECT_EQ(m.to_ros[0].kind, PayloadKind::PERCEPT);
  EXPECT_EQ(m.to_ros[0].scope, DCDT_ALL_MSG);
  EXPECT_EQ(m.to_ros[1].kind, PayloadKind::COMMANDS);
  ASSERT_EQ(m.to_dcdt.size(), 2u);
  EXPECT_EQ(m.to_dcdt[0].type, MSG_TO_MOTION);
  EXPECT_EQ(m.to_dcdt[0].warranty, DCDT_DW_GUARANTEED);
}

TEST(BridgeMapping, Errors) {
  struct Case {
    const char* text;
    int line;
    const char* expect;
  } cases[] = {
      {"to_ros:\n  - {type: MSG_FROM_NOTHING, topic: a}\n", 2, "unknown DCDT message type"},
      {"to_ros:\n  - type: 18\n    kind: percept\n", 2, "missing 'topic'"},
      {"to_ros:\n  - {type: 18, topic: a, kind: jpeg}\n", 2, "kind must be"},
      {"to_ros:\n  - {type: 18, topic: a, scope: near}\n", 2, "scope must be"},
      {"to_dcdt:\n  - {type: 18, topic: a, warranty: maybe}\n", 2, "warranty must be"},
      {"to_ros:\n  - {type: 18, topic: a}\n  - {type: 18, topic: b}\n", 3, "mapped twice"},
      {"to_ros:\n  - {type: 18, topic: a, colour: red}\n", 2, "unknown key 'colour'"},
      {"from_ros: []\n", 1, "unknown key 'from_ros'"},
      {"to_ros: [\n", 2, ""},
      {"to_ros: []\n", 1, "nothing mapped"},
  };
  for (const auto& c : cases) {
    try {
      parse_bridge_mapping(c.text, "map.yaml");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.file(), "map.yaml");
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
    }
  }
}

}  // namespace

namespace {

TEST(BridgeMapping, ShippedApplicationConfigurationParses) {
  auto m = load_bridge_mapping(std::string(DCDT_CONFIG_DIR) + "/bridge_mapping.yaml");
  EXPECT_FALSE(m.to_ros.empty());
  EXPECT_FALSE(m.to_dcdt.empty());
  auto c = load_agora_config(std::string(DCDT_CONFIG_DIR) + "/agora.cfg");
  EXPECT_EQ(c.local_addr, "127.0.0.1");
}

}  // namespace

namespace {

// The team configuration (README "Team data"): MAP and SCARE both ways, as
// the legacy types 23 and 24, without retransmission; the robot's Agora is
// NETWORK with the Finder and no static channel; the tests' Agoras use
// Finder ports of their own.
TEST(BridgeMapping, ShippedTeamConfigurationParses) {
  auto m = load_bridge_mapping(std::string(DCDT_CONFIG_DIR) + "/team_mapping.yaml");
  ASSERT_EQ(m.to_ros.size(), 2u);
  ASSERT_EQ(m.to_dcdt.size(), 2u);
  EXPECT_EQ(m.to_ros[0].type, 23);
  EXPECT_EQ(m.to_ros[0].kind, PayloadKind::WORLD_MODEL);
  EXPECT_EQ(m.to_ros[0].topic, "team/world_models");
  EXPECT_EQ(m.to_ros[1].type, 24);
  EXPECT_EQ(m.to_ros[1].kind, PayloadKind::COORDINATION);
  EXPECT_EQ(m.to_ros[1].topic, "scare/team");
  EXPECT_EQ(m.to_dcdt[0].kind, PayloadKind::WORLD_MODEL);
  EXPECT_EQ(m.to_dcdt[1].kind, PayloadKind::COORDINATION);
  EXPECT_EQ(m.to_dcdt[1].warranty, DCDT_DW_NONE);
  EXPECT_STREQ(kind_name(PayloadKind::WORLD_MODEL), "world_model");
  EXPECT_STREQ(kind_name(PayloadKind::COORDINATION), "coordination");
  auto c = load_agora_config(std::string(DCDT_CONFIG_DIR) + "/robot_agora.cfg");
  EXPECT_TRUE(c.channels.empty());
  auto t = load_agora_config(std::string(DCDT_TEST_DATA) + "/team_agora_map.cfg");
  EXPECT_EQ(t.port, 7419);
  EXPECT_EQ(t.multicast_addr, "239.255.0.19");
}

}  // namespace

namespace {

// The RoboCup configuration (README "Team data"): a robot's bridge carries the
// team data of team_mapping.yaml plus the referee box's commands from DCDT
// (type 28, MSG_FROM_REFBOX, in mrt_dcdt's types.h) on its own `referee`
// topic; the referee-box station shares /referee as type 28, guaranteed.
TEST(BridgeMapping, ShippedRoboCupConfigurationParses) {
  auto m = load_bridge_mapping(std::string(DCDT_CONFIG_DIR) + "/robocup_mapping.yaml");
  ASSERT_EQ(m.to_ros.size(), 3u);
  ASSERT_EQ(m.to_dcdt.size(), 2u);
  EXPECT_EQ(m.to_ros[2].type, 28);
  EXPECT_EQ(m.to_ros[2].kind, PayloadKind::REFEREE);
  EXPECT_EQ(m.to_ros[2].topic, "referee");
  EXPECT_STREQ(kind_name(PayloadKind::REFEREE), "referee");
  auto r = load_bridge_mapping(std::string(DCDT_CONFIG_DIR) + "/refbox_mapping.yaml");
  EXPECT_TRUE(r.to_ros.empty());
  ASSERT_EQ(r.to_dcdt.size(), 1u);
  EXPECT_EQ(r.to_dcdt[0].type, 28);
  EXPECT_EQ(r.to_dcdt[0].kind, PayloadKind::REFEREE);
  EXPECT_EQ(r.to_dcdt[0].warranty, DCDT_DW_GUARANTEED);
}

}  // namespace
