// mrt_msgs <-> XML conversions of the node: lossless through the wire text.
#include <gtest/gtest.h>

#include <limits>

#include "ros/conversions.h"

using namespace mrt::dcdt;

namespace {

mrt_msgs::Percept Sample() {
  mrt_msgs::Percept p;
  p.header.stamp.sec = 1763776000;
  p.header.stamp.nsec = 999999999;
  p.header.frame_id = "robot2/base_link";
  p.sensor = "omnivision";
  p.robot = "ianus3";
  for (int i = 0; i < 3; ++i) {
    mrt_msgs::PerceptObject o;
    o.name = "obj" + std::to_string(i) + " <&>";
    o.membership_class = i == 0 ? "Ball" : "Obstacle";
    mrt_msgs::Attribute a;
    a.name = "distance";
    a.value = 1.0 / (i + 3);
    a.variability = 1e-9 * i;
    a.reliability = 0.1 * i;
    o.attributes.push_back(a);
    a.name = "colour";
    a.value = 0;
    a.symbol = "orange";
    o.attributes.push_back(a);
    a.name = "big";
    a.symbol = "";
    a.value = std::numeric_limits<double>::max();
    o.attributes.push_back(a);
    p.objects.push_back(o);
  }
  return p;
}

TEST(Conversions, PerceptRoundTripThroughXmlTextIsExact) {
  const auto p = Sample();
  const auto q = node::to_percept(decode_xml(encode_xml(node::from_percept(p))));
  EXPECT_EQ(q.header.stamp, p.header.stamp);
  EXPECT_EQ(q.header.frame_id, p.header.frame_id);
  EXPECT_EQ(q.sensor, p.sensor);
  EXPECT_EQ(q.robot, p.robot);
  // Every field: the generated messages compare member by member.
  EXPECT_TRUE(q.objects == p.objects);
}

TEST(Conversions, CrispDataAndCommandsRoundTrip) {
  mrt_msgs::CrispDataArray c;
  c.header.stamp.sec = 5;
  c.header.stamp.nsec = 7;
  c.header.frame_id = "f";
  for (int i = 0; i < 4; ++i) {
    mrt_msgs::CrispData d;
    d.name = "BallDistance" + std::to_string(i);
    d.value = 123.456 * i;
    d.reliability = 0.25 * i;
    c.data.push_back(d);
  }
  const auto c2 = node::to_crisp_data(decode_xml(encode_xml(node::from_crisp_data(c))));
  EXPECT_EQ(c2.header.stamp, c.header.stamp);
  EXPECT_TRUE(c2.data == c.data);

  mrt_msgs::CommandArray k;
  k.header.stamp.sec = 9;
  mrt_msgs::Command cmd;
  cmd.name = "SpeedModule";
  cmd.value = 42.5;
  k.commands.push_back(cmd);
  cmd.name = "SpeedAngle";
  cmd.value = -17.25;
  k.commands.push_back(cmd);
  const auto k2 = node::to_commands(decode_xml(encode_xml(node::from_commands(k))));
  EXPECT_TRUE(k2.commands == k.commands);
}

TEST(Conversions, WrongShapeIsRejected) {
  XmlMessage x;
  x.objects.push_back({"ball", "Ball", {{"distance", 1, "", 0, 1}}});
  EXPECT_THROW(node::to_commands(x), XmlError);
  EXPECT_THROW(node::to_crisp_data(x), XmlError);
}

XmlMessage Stamped(const char* time) {
  return decode_xml(std::string("<?xml version=\"1.0\"?>\n<message time=\"") + time + "\"/>\n");
}

TEST(Conversions, TimesOutsideRosTimeAreRejectedNotWrapped) {
  // ROS time: uint32 seconds, so [0, 2^32 - 1] s.
  for (const char* t : {"-1", "-4294967296", "4294967296", "4294967296.5", "9999999999"}) {
    const XmlMessage x = Stamped(t);
    EXPECT_THROW(node::to_percept(x), XmlError) << t;
    EXPECT_THROW(node::to_crisp_data(x), XmlError) << t;
    EXPECT_THROW(node::to_commands(x), XmlError) << t;
  }
  try {
    node::to_percept(Stamped("-1"));
  } catch (const XmlError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the ROS time range"), std::string::npos) << e.what();
  }
  // The edges themselves convert exactly.
  auto lo = node::to_percept(Stamped("0"));
  EXPECT_EQ(lo.header.stamp.sec, 0u);
  EXPECT_EQ(lo.header.stamp.nsec, 0u);
  auto hi = node::to_percept(Stamped("4294967295.999999999"));
  EXPECT_EQ(hi.header.stamp.sec, 4294967295u);
  EXPECT_EQ(hi.header.stamp.nsec, 999999999u);
}

TEST(Conversions, RosValuesNoDecoderAcceptsAreRefused) {
  auto p = Sample();
  p.objects[0].attributes[0].reliability = 1.25;
  EXPECT_THROW(encode_xml(node::from_percept(p)), XmlError);
  p = Sample();
  p.objects[1].attributes[0].variability = -0.5;
  EXPECT_THROW(encode_xml(node::from_percept(p)), XmlError);
  mrt_msgs::CrispDataArray c;
  mrt_msgs::CrispData d;
  d.name = "x";
  d.reliability = 2;
  c.data.push_back(d);
  EXPECT_THROW(encode_xml(node::from_crisp_data(c)), XmlError);
}

}  // namespace
