// The referee box over DCDT (MSG_FROM_REFBOX, 28): mrt_msgs/RefereeCommand
// <-> MRT XML, lossless through the wire text; the documented file decodes
// to the values written in it; wrong shapes are refused with the reason.
#include <gtest/gtest.h>

#include <fstream>
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

mrt_msgs::RefereeCommand through_xml(const mrt_msgs::RefereeCommand& r) {
  return node::to_referee(decode_xml(encode_xml(node::from_referee(r))));
}

TEST(RefereeConversions, RoundTripThroughXmlTextIsExact) {
  mrt_msgs::RefereeCommand r;
  r.header.stamp.sec = 1763776000;
  r.header.stamp.nsec = 999999999;
  r.header.frame_id = "world";
  r.command = mrt_msgs::RefereeCommand::THROW_IN;
  r.name = "throw_in";
  r.team = "magenta";
  r.x = 1.0 / 3.0;     // not a short decimal: bit-exact or not at all
  r.y = -6.0;
  r.teams = {"cyan", "magenta"};
  r.score = {0, 4294967295u};
  r.reason = "ball over the touch line <&>";
  EXPECT_EQ(through_xml(r), r);
  // A stop for both teams, no score yet, no reason: the optional parts stay empty.
  mrt_msgs::RefereeCommand s;
  s.command = mrt_msgs::RefereeCommand::STOP;
  s.name = "stop";
  const auto t = through_xml(s);
  EXPECT_EQ(t, s);
  EXPECT_TRUE(t.team.empty());
  EXPECT_TRUE(t.teams.empty());
}

TEST(RefereeConversions, DocumentedGoalDecodesToTheValuesWritten) {
  const auto r = node::to_referee(decode_xml(read("referee_goal.xml")));
  EXPECT_EQ(r.header.stamp.sec, 1763776012u);
  EXPECT_EQ(r.header.stamp.nsec, 500000000u);
  EXPECT_EQ(r.header.frame_id, "world");
  EXPECT_EQ(r.command, 3);  // GOAL
  EXPECT_EQ(r.name, "goal");
  EXPECT_EQ(r.team, "cyan");
  EXPECT_EQ(r.x, 0.0);
  EXPECT_EQ(r.y, 0.0);
  EXPECT_EQ(r.reason, "ball over the goal line");
  EXPECT_EQ(r.teams, (std::vector<std::string>{"cyan", "magenta"}));
  EXPECT_EQ(r.score, (std::vector<uint32_t>{2, 1}));
}

void expect_refused(const std::string& doc, const char* what) {
  const XmlMessage x = decode_xml(doc);  // valid MRT XML: the shape is wrong
  try {
    node::to_referee(x);
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

TEST(RefereeConversions, WrongShapesAreRefused) {
  const std::string g = read("referee_goal.xml");
  expect_refused(replace(g, R"(name="command" value="3")", R"(name="command" value="256")"), "in [0, 255]");
  expect_refused(replace(g, R"(name="command" value="3")", R"(name="command" value="2.5")"), "integer");
  expect_refused(replace(g, R"(<attribute name="y" value="0"/>)", ""), "no numeric attribute 'y'");
  expect_refused(replace(g, R"(symbol="cyan")", R"(value="0")"), "must be a symbol");
  expect_refused(replace(g, R"(name="goals" value="2")", R"(name="goals" value="-2")"), "integer");
  expect_refused(replace(g, R"(class="Score")", R"(class="Penalty")"), "class 'Penalty'");
  expect_refused(replace(g, R"(<attribute name="goals" value="1"/>)",
                         R"(<attribute name="goals" value="1"/><attribute name="own_goals" value="0"/>)"),
                 "unknown or repeated attribute 'own_goals'");
  const auto from = g.find(R"(<object name="goal" class="RefereeCommand">)");
  const auto to = g.find("</object>", from) + 9;
  expect_refused(std::string(g).erase(from, to - from), "needs one RefereeCommand object");
  expect_refused(replace(g, R"(class="Score")", R"(class="RefereeCommand")"), "more than one RefereeCommand");
}

TEST(RefereeConversions, RosMessagesXmlCannotCarryAreRefused) {
  mrt_msgs::RefereeCommand r;
  r.command = mrt_msgs::RefereeCommand::GOAL;
  EXPECT_THROW(node::from_referee(r), XmlError);  // no name
  r.name = "goal";
  r.teams = {"cyan", "magenta"};
  r.score = {1};
  EXPECT_THROW(node::from_referee(r), XmlError);  // a score short of a team
  r.score = {1, 0};
  r.teams[1] = "";
  EXPECT_THROW(node::from_referee(r), XmlError);  // a team without a name
}

}  // namespace
