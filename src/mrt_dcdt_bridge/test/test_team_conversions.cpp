// Team data over DCDT: mrt_msgs/WorldModel and CoordinationParameters <->
// MRT XML, lossless through the wire text; the documented documents (the
// files a legacy Agora would produce) decode to the values written in them.
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "ros/team_conversions.h"

using namespace mrt::dcdt;

namespace {

std::string read(const std::string& name) {
  std::ifstream f(std::string(DCDT_TEST_DATA) + "/" + name);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

mrt_msgs::WorldModel SampleModel() {
  mrt_msgs::WorldModel w;
  w.header.stamp.sec = 1763776000;
  w.header.stamp.nsec = 999999999;
  w.header.frame_id = "map";
  w.robot = "robot1";
  w.local_only = true;
  w.robot_x = -3.25;
  w.robot_y = 1.0 / 3.0;
  w.robot_theta = -3.141592653589793;
  w.robot_covariance = {4e-4, -1e-5, -1e-5, 9e-4};
  for (uint32_t i = 0; i < 3; ++i) {
    mrt_msgs::Anchor a;
    a.id = i == 2 ? 4294967295u : 17 + i;
    a.membership_class = i == 1 ? "" : "Ball";  // "" (no class) travels too
    a.matching_degree = 0.1 * (i + 1);
    a.status = static_cast<uint8_t>(i);
    a.x = 1.0 / (i + 7);
    a.y = -2.5e-17 * i;
    // The smallest normal number (mrt_dcdt's decoder refuses subnormal ones,
    // which its encoder writes: reported, not the bridge's to change).
    a.vx = std::numeric_limits<double>::min();
    a.vy = std::numeric_limits<double>::max();
    for (int k = 0; k < 16; ++k) a.covariance[static_cast<std::size_t>(k)] = (k % 5 == 0 ? 1.0 : -0.01) / (k + 3);
    a.reliability = 0.7;
    a.last_seen.sec = 1763775999;
    a.last_seen.nsec = 123456789 * i;
    if (i != 1) a.sources = {"robot1/omnivision", "robot1/frontal <&>"};
    w.anchors.push_back(a);
  }
  mrt_msgs::CrispData d;
  d.name = "ScareRole_PassageToMate_passer";
  d.value = 1.0;
  d.reliability = 0.5;
  w.parameters.push_back(d);
  return w;
}

mrt_msgs::CoordinationParameters SampleCoordination() {
  mrt_msgs::CoordinationParameters c;
  c.header.stamp.sec = 1763776000;
  c.header.stamp.nsec = 1;
  c.header.frame_id = "world";
  c.robot_id = "robot3";
  c.seq = 4294967295u;
  c.x = 2.5;
  c.y = -2.0;
  c.intention = "PassageToMate.receiver";
  c.intention_since = 1763775990.125;
  c.slots = {"Defense", "PassageToMate.passer", "PassageToMate.receiver"};
  c.attitude = {0.5, 0.0, 1.0};
  c.time = {7.566, -1.0, 0.41666666666666669};
  c.activities = {"Defense", "PassageToMate"};
  c.opportunity = {0.6, 0.9};
  c.heard_ids = {"robot1", "robot2"};
  c.heard_stamps = {1763776000.05, 1763775999.95};
  return c;
}

TEST(TeamConversions, WorldModelRoundTripThroughXmlTextIsExact) {
  const auto w = SampleModel();
  const auto v = node::to_world_model(decode_xml(encode_xml(node::from_world_model(w))));
  // The generated messages compare member by member (header included):
  // stamp, every covariance entry, ids, sources, parameters bit-exact.
  EXPECT_TRUE(v == w);
  EXPECT_EQ(v.anchors[2].id, 4294967295u);
  EXPECT_EQ(v.anchors[1].membership_class, "");
  EXPECT_EQ(v.anchors[0].covariance[1], -0.01 / 4);
}

TEST(TeamConversions, CoordinationRoundTripThroughXmlTextIsExact) {
  auto c = SampleCoordination();
  auto d = node::to_coordination(decode_xml(encode_xml(node::from_coordination(c))));
  EXPECT_TRUE(d == c);
  // A leaving message (no intention, no vectors) too.
  c = mrt_msgs::CoordinationParameters();
  c.robot_id = "robot2";
  c.leaving = true;
  d = node::to_coordination(decode_xml(encode_xml(node::from_coordination(c))));
  EXPECT_TRUE(d == c);
  EXPECT_TRUE(d.leaving);
  EXPECT_EQ(d.intention, "");
  EXPECT_EQ(d.intention_since, 0.0);  // absent in the XML: unknown
}

TEST(TeamConversions, DocumentedWorldModelDecodesToTheValuesWritten) {
  const auto w = node::to_world_model(decode_xml(read("world_model_robot2.xml")));
  EXPECT_EQ(w.header.stamp.sec, 1763776000u);
  EXPECT_EQ(w.header.stamp.nsec, 250000000u);
  EXPECT_EQ(w.header.frame_id, "map");
  EXPECT_EQ(w.robot, "robot2");
  EXPECT_TRUE(w.local_only);
  EXPECT_EQ(w.robot_theta, -1.5);
  EXPECT_EQ(w.robot_covariance[3], 0.0004);
  ASSERT_EQ(w.anchors.size(), 1u);
  const auto& a = w.anchors[0];
  EXPECT_EQ(a.id, 7u);
  EXPECT_EQ(a.membership_class, "Ball");
  EXPECT_EQ(a.status, mrt_msgs::Anchor::CONFIRMED);
  EXPECT_EQ(a.x, 2.0);
  EXPECT_EQ(a.vy, -0.25);
  EXPECT_EQ(a.covariance[1], -0.002);
  EXPECT_EQ(a.covariance[4], -0.002);
  EXPECT_EQ(a.covariance[15], 0.1);
  EXPECT_EQ(a.last_seen.nsec, 200000000u);
  ASSERT_EQ(a.sources.size(), 1u);
  EXPECT_EQ(a.sources[0], "robot2/omnivision");
  ASSERT_EQ(w.parameters.size(), 1u);
  EXPECT_EQ(w.parameters[0].name, "ScareJob_BringBall");
}

TEST(TeamConversions, DocumentedCoordinationDecodesToTheValuesWritten) {
  const auto c = node::to_coordination(decode_xml(read("coordination_robot2.xml")));
  EXPECT_EQ(c.robot_id, "robot2");
  EXPECT_EQ(c.header.stamp.nsec, 100000000u);
  EXPECT_EQ(c.seq, 42u);
  EXPECT_FALSE(c.leaving);
  EXPECT_EQ(c.intention, "BringBall");
  EXPECT_EQ(c.slots, (std::vector<std::string>{"BringBall", "Defense"}));
  EXPECT_EQ(c.attitude, (std::vector<double>{0.9, 0.5}));
  EXPECT_EQ(c.time, (std::vector<double>{0.75, -1.0}));
  EXPECT_EQ(c.activities, (std::vector<std::string>{"BringBall", "Defense"}));
  EXPECT_EQ(c.opportunity, (std::vector<double>{0.9, 0.5}));
  EXPECT_EQ(c.heard_ids, (std::vector<std::string>{"robot1"}));
  EXPECT_EQ(c.heard_stamps, (std::vector<double>{1763776000.05}));
}

// Documents of the wrong shape are refused with the reason.
void expect_refused(const std::string& doc, const char* what, bool world) {
  const XmlMessage x = decode_xml(doc);  // valid MRT XML: the shape is wrong
  try {
    if (world) node::to_world_model(x);
    else node::to_coordination(x);
    ADD_FAILURE() << "accepted: " << doc;
  } catch (const XmlError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(TeamConversions, WrongShapesAreRefused) {
  const std::string w = read("world_model_robot2.xml");
  expect_refused(replace(w, R"(<attribute name="cov_33" value="0.1"/>)", ""), "no numeric attribute 'cov_33'", true);
  expect_refused(replace(w, R"(name="vx")", R"(name="speed")"), "no numeric attribute 'vx'", true);
  expect_refused(replace(w, R"(<attribute name="reliability" value="0.85"/>)",
                         R"(<attribute name="reliability" value="0.85"/><attribute name="speed" value="1"/>)"),
                 "unknown or repeated attribute 'speed'", true);
  expect_refused(replace(w, R"(<attribute name="x" value="2"/>)", R"(<attribute name="x" value="2"/><attribute name="x" value="3"/>)"),
                 "unknown or repeated attribute 'x'", true);
  expect_refused(replace(w, R"(name="status" value="1")", R"(name="status" value="3")"), "'status' must be 0, 1 or 2", true);
  expect_refused(replace(w, R"(name="7")", R"(name="-7")"), "the name must be the anchor id", true);
  expect_refused(replace(w, R"(class="Anchor")", R"(class="Ball")"), "class 'Ball' in a world model", true);
  expect_refused(replace(w, R"(name="robot2" class="WorldModel")", R"(name="robot2" class="Anchor")"),
                 "the name must be the anchor id", true);
  const auto wfrom = w.find(R"(<object name="robot2" class="WorldModel">)");
  const auto wto = w.find("</object>", wfrom) + 9;
  expect_refused(std::string(w).erase(wfrom, wto - wfrom), "needs one WorldModel object", true);
  expect_refused(replace(w, R"(name="local_only" value="1")", R"(name="local_only" value="0.5")"), "must be 0 or 1", true);
  expect_refused(replace(w, R"(name="robot2" class="WorldModel")", R"(name="robot9" class="WorldModel")"),
                 "named after the message's robot", true);
  const std::string c = read("coordination_robot2.xml");
  expect_refused(replace(c, R"(<attribute name="time" value="0.75"/>)", ""), "no numeric attribute 'time'", false);
  expect_refused(replace(c, R"(name="seq" value="42")", R"(name="seq" value="4.5")"), "integer", false);
  expect_refused(replace(c, R"(symbol="BringBall")", R"(value="3")"), "must be a symbol", false);
  expect_refused(replace(c, R"(class="Coordination")", R"(class="Heard")"), "no numeric attribute 'stamp'", false);
  const auto from = c.find(R"(<object name="robot2" class="Coordination">)");
  const auto to = c.find("</object>", from) + 9;
  expect_refused(std::string(c).erase(from, to - from), "needs one Coordination object", false);
  expect_refused(replace(c, R"(class="Heard")", R"(class="Gossip")"), "class 'Gossip'", false);
}

TEST(TeamConversions, RosMessagesXmlCannotCarryAreRefused) {
  auto w = SampleModel();
  w.anchors[0].sources.push_back("");
  EXPECT_THROW(node::from_world_model(w), XmlError);
  w = SampleModel();
  w.anchors[0].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(encode_xml(node::from_world_model(w)), XmlError);
  auto c = SampleCoordination();
  c.time.pop_back();  // a malformed message: vectors of different lengths
  EXPECT_THROW(node::from_coordination(c), XmlError);
}

}  // namespace
