// The node's conversions: teammates' anchors through mrt_msgs/WorldModel and
// through the DCDT form (mrt_msgs/Percept, what the DCDT bridge carries).
#include <gtest/gtest.h>

#include "ros/conversions.h"

using namespace mrt::map;

namespace {
const char* kModel =
    "classes:\n"
    "  Ball: {motion: constant_velocity, accel_noise: 1, attributes: {color: {symbols: {orange: 1}}}}\n"
    "tracker: {confirm_hits: 2}\n";

PerceptObject ball(double x, double y) {
  PerceptObject o;
  o.membership_class = "Ball";
  o.attributes.push_back({"color", 0.0, "orange", 0.0, 1.0});
  o.set("x", x, 0.1, 1.0);
  o.set("y", y, 0.2, 1.0);
  return o;
}
}  // namespace

TEST(Conversions, OwnTracksRoundTrip) {
  const ConceptualModel m = ConceptualModel::parse(kModel, "t.yaml");
  WorldModel w(m, {"r1", 0.5});
  RobotPose pose;
  pose.x = 1.0;  // robot at (1, 0) facing +x: the ball at world (3, 1)
  for (double t : {10.0, 10.1}) {
    w.add_percept({ball(2, 1)}, pose, t, t, "cam");
    w.update(t);
  }
  const auto own = w.local_tracks();
  ASSERT_EQ(own.size(), 1u);
  const ros::Time stamp(10.1);
  // Through the team topic: every field back, full covariance.
  const mrt_msgs::WorldModel msg = node::to_msg(w, own, "map", stamp);
  ASSERT_EQ(msg.anchors.size(), 1u);
  EXPECT_TRUE(msg.local_only);
  EXPECT_EQ(msg.robot, "r1");
  RemoteTrack back;
  ASSERT_TRUE(node::from_msg(msg.anchors[0], m, stamp, back));
  EXPECT_EQ(back.id, own[0].id);
  EXPECT_NEAR(back.estimate.x(0), 3.0, 1e-12);
  EXPECT_NEAR(back.estimate.x(1), 1.0, 1e-12);
  EXPECT_TRUE(back.estimate.P.isApprox(own[0].estimate.P, 1e-12));
  EXPECT_NEAR(back.last_seen, 10.1, 1e-6);
  EXPECT_EQ(back.sensors, (std::set<std::string>{"r1/cam"}));
  // A non-positive covariance or an unknown class is refused.
  mrt_msgs::Anchor bad = msg.anchors[0];
  bad.covariance[0] = -1.0;
  EXPECT_FALSE(node::from_msg(bad, m, stamp, back));
  bad = msg.anchors[0];
  bad.membership_class = "Cat";
  EXPECT_FALSE(node::from_msg(bad, m, stamp, back));
}
