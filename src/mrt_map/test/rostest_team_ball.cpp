// Two robots (map_node in /robot1 and /robot2, team topic shared) see the
// same ball at world (2, 1): robot1 at (0, 0), robot2 at (4, 0), both facing
// +x. They fuse it into one anchor; both lose it (robot1's anchor coasts);
// robot2 sees it again and robot1 gets it back, same id, from its teammate.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WorldModel.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <algorithm>
#include <cmath>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::wait_for;

namespace {

struct Fixture {
  ros::NodeHandle nh;
  tf2_ros::StaticTransformBroadcaster tf;
  ros::Publisher p1 = nh.advertise<mrt_msgs::Percept>("/robot1/percepts", 10);
  ros::Publisher p2 = nh.advertise<mrt_msgs::Percept>("/robot2/percepts", 10);
  bool sees1 = true, sees2 = true;
  mrt_msgs::WorldModel model1;
  mrt_msgs::CrispDataArray crisp1;
  bool have_model = false;
  ros::Subscriber s1 = nh.subscribe("/robot1/world_model", 5, &Fixture::on_model, this);
  ros::Subscriber s2 = nh.subscribe("/robot1/crisp_data", 5, &Fixture::on_crisp, this);
  ros::Timer timer = nh.createTimer(ros::Duration(1.0 / 30), &Fixture::on_timer, this);

  Fixture() {
    std::vector<geometry_msgs::TransformStamped> ts;
    for (int i = 1; i <= 2; ++i) {
      geometry_msgs::TransformStamped t;
      t.header.stamp = ros::Time::now();
      t.header.frame_id = "map";
      t.child_frame_id = "robot" + std::to_string(i) + "/base_link";
      t.transform.translation.x = i == 1 ? 0.0 : 4.0;
      t.transform.rotation.w = 1.0;
      ts.push_back(t);
    }
    tf.sendTransform(ts);
  }
  void on_model(const mrt_msgs::WorldModel& m) {
    model1 = m;
    have_model = true;
  }
  void on_crisp(const mrt_msgs::CrispDataArray& c) { crisp1 = c; }
  static mrt_msgs::Percept percept(const std::string& robot, double x, double y) {
    mrt_msgs::Percept p;
    p.header.stamp = ros::Time::now();
    p.header.frame_id = robot + "/base_link";
    p.sensor = "omnivision";
    p.robot = robot;
    mrt_msgs::PerceptObject o;
    o.name = "ball";
    o.membership_class = "Ball";
    mrt_msgs::Attribute a;
    a.name = "color";
    a.symbol = "orange";
    a.reliability = 1;
    o.attributes.push_back(a);
    a.symbol.clear();
    a.name = "x";
    a.value = x;
    a.variability = 0.03;
    o.attributes.push_back(a);
    a.name = "y";
    a.value = y;
    o.attributes.push_back(a);
    p.objects.push_back(o);
    return p;
  }
  void on_timer(const ros::TimerEvent&) {
    if (sees1) p1.publish(percept("robot1", 2.0, 1.0));   // world (2, 1)
    if (sees2) p2.publish(percept("robot2", -2.0, 1.0));  // world (4 - 2, 1)
  }
  std::vector<mrt_msgs::Anchor> balls() const {
    std::vector<mrt_msgs::Anchor> out;
    for (const auto& a : model1.anchors)
      if (a.membership_class == "Ball") out.push_back(a);
    return out;
  }
  bool has(const mrt_msgs::Anchor& a, const std::string& source) const {
    return std::find(a.sources.begin(), a.sources.end(), source) != a.sources.end();
  }
};

}  // namespace

TEST(MapTeam, FuseLoseAndGetBackFromTeammate) {
  Fixture f;
  // 1. Both see it: one anchor, supported by both robots' cameras.
  ASSERT_TRUE(wait_for([&] {
    const auto b = f.balls();
    return b.size() == 1 && b[0].status == mrt_msgs::Anchor::CONFIRMED && f.has(b[0], "robot1/omnivision") &&
           f.has(b[0], "robot2/omnivision");
  }, 15.0)) << "no single fused ball anchor on /robot1/world_model";
  const auto fused = f.balls().at(0);
  EXPECT_NEAR(fused.x, 2.0, 0.05);
  EXPECT_NEAR(fused.y, 1.0, 0.05);
  // BallDistance in mm from robot1 at (0, 0): 1000 * sqrt(2^2 + 1^2) = 2236.07.
  ASSERT_TRUE(wait_for([&] { return !f.crisp1.data.empty(); }, 5.0));
  EXPECT_EQ(f.crisp1.data[0].name, "BallDistance");
  EXPECT_NEAR(f.crisp1.data[0].value, 2236.07, 50.0);
  // 2. Both lose it: robot1's anchor coasts (unseen > coast_after 0.3 s).
  f.sees1 = f.sees2 = false;
  ASSERT_TRUE(wait_for([&] {
    const auto b = f.balls();
    return b.size() == 1 && b[0].status == mrt_msgs::Anchor::COASTING;
  }, 5.0)) << "robot1's ball anchor did not coast";
  EXPECT_EQ(f.balls().at(0).id, fused.id);
  // 3. robot2 sees it again, robot1 does not: robot1 gets it back from its
  // teammate, same id, confirmed.
  f.sees2 = true;
  ASSERT_TRUE(wait_for([&] {
    const auto b = f.balls();
    return b.size() == 1 && b[0].status == mrt_msgs::Anchor::CONFIRMED;
  }, 5.0)) << "robot1 did not get the ball back from robot2";
  const auto back = f.balls().at(0);
  EXPECT_EQ(back.id, fused.id);
  EXPECT_NEAR(back.x, 2.0, 0.1);
  EXPECT_NEAR(back.y, 1.0, 0.1);
  EXPECT_GT(back.reliability, 0.5);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mrt_map_team_rostest");
  return RUN_ALL_TESTS();
}
