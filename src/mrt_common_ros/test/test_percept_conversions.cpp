// Percepts to and from mrt_msgs: a round trip keeps every field; a
// received percept's objects checked against the ontology, the bad ones
// counted.
#include <gtest/gtest.h>

#include "mrt_common_ros/percept_conversions.h"

using namespace mrt::common;
using namespace mrt::ros_common;

TEST(PerceptConversions, RoundTrip) {
  Percept p;
  p.stamp = 12.25;
  p.frame = "robot1/base_link";
  p.sensor = "omnivision";
  p.robot = "robot1";
  PerceptObject b("ball", percept_class::kBall);
  b.set_polar({2.0, -0.5, 0.05, 0.01, 0.9}).set_symbol("color", "orange", 0.7);
  p.objects.push_back(b);
  const mrt_msgs::Percept m = to_msg(p);
  EXPECT_DOUBLE_EQ(m.header.stamp.toSec(), 12.25);
  EXPECT_EQ(m.header.frame_id, "robot1/base_link");
  ASSERT_EQ(m.objects.size(), 1u);
  ASSERT_EQ(m.objects[0].attributes.size(), 5u);
  EXPECT_EQ(m.objects[0].attributes[4].symbol, "orange");
  EXPECT_DOUBLE_EQ(m.objects[0].attributes[4].reliability, 0.7);
  const Percept back = from_msg(m);
  EXPECT_EQ(back.sensor, "omnivision");
  EXPECT_EQ(back.robot, "robot1");
  ASSERT_EQ(back.objects.size(), 1u);
  EXPECT_DOUBLE_EQ(*back.objects[0].number("distance"), 2.0);
  EXPECT_DOUBLE_EQ(back.objects[0].find("bearing")->variability, 0.01);
  EXPECT_EQ(back.objects[0].symbol("color"), "orange");
}

TEST(PerceptConversions, AcceptedObjectsDropAndCount) {
  mrt_msgs::Percept m;
  PerceptObject ok("b", "Ball"), unknown("u", "Ghost"), nopos("l", "Landmark");
  ok.set_polar({1.0, 0.0});
  unknown.set_polar({1.0, 0.0});
  nopos.set_symbol("color", "red");
  for (const auto& o : {ok, unknown, nopos}) m.objects.push_back(to_msg(o));
  PerceptDrops d;
  const auto kept = accepted_objects(m, d);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].name, "b");
  EXPECT_EQ(d.unknown_class, 1u);
  EXPECT_EQ(d.missing_attribute, 1u);
}
