// rostest team_world_model.test: two robots' map_nodes exchange their
// world models only over DCDT (each through its own bridge and Agora).
// 1. Every model of robot1 that reaches robot2's team topic arrives from
//    robot2's bridge and equals, field by field (stamp, anchors' 4x4
//    covariance, sources ...), the one robot1's map_node published.
// 2. mrt_map's team-ball scenario over that path: robot1 at (0, 0) and
//    robot2 at (4, 0) see a ball at world (2, 1), fuse it into one anchor
//    supported by both cameras, lose it (coasting), and robot1 gets it back,
//    same id, from robot2 alone.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WorldModel.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <algorithm>
#include <map>
#include <mutex>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::wait_for;

namespace {

struct Fixture {
  ros::NodeHandle nh;
  tf2_ros::StaticTransformBroadcaster tf;
  ros::Publisher p1 = nh.advertise<mrt_msgs::Percept>("/robot1/percepts", 10);
  ros::Publisher p2 = nh.advertise<mrt_msgs::Percept>("/robot2/percepts", 10);
  bool sees1 = true, sees2 = true;
  mrt_msgs::WorldModel model1;  // robot1's fused team model
  // What robot1's map_node sent, by stamp, and what reached robot2.
  std::map<ros::Time, mrt_msgs::WorldModel> sent;
  // matched: arrived with the stamp of a model we saw robot1 send (the first
  // ones may precede our subscription to robot1's topic).
  int matched = 0, matched_with_anchors = 0, equal = 0, wrong_publisher = 0, direct = 0;
  ros::Subscriber s1 = nh.subscribe("/robot1/world_model", 5, &Fixture::on_model, this);
  ros::Subscriber out1, in2;
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
    const boost::function<void(const ros::MessageEvent<mrt_msgs::WorldModel const>&)> on_out =
        [this](const ros::MessageEvent<mrt_msgs::WorldModel const>& ev) {
          if (ev.getPublisherName() != "/robot1/map") return;  // robot2's, from robot1's bridge
          auto m = *ev.getConstMessage();
          m.header.seq = 0;  // not carried (README)
          sent[m.header.stamp] = m;
        };
    const boost::function<void(const ros::MessageEvent<mrt_msgs::WorldModel const>&)> on_in =
        [this](const ros::MessageEvent<mrt_msgs::WorldModel const>& ev) {
          const auto& m = *ev.getConstMessage();
          if (m.robot != "robot1") return;
          if (ev.getPublisherName() == "/robot1/map") ++direct;  // must not happen: not on ROS
          if (ev.getPublisherName() != "/robot2/dcdt_bridge") ++wrong_publisher;
          auto it = sent.find(m.header.stamp);
          if (it == sent.end()) return;
          ++matched;
          if (!m.anchors.empty()) ++matched_with_anchors;
          auto copy = m;
          copy.header.seq = 0;
          if (copy == it->second) ++equal;
        };
    out1 = nh.subscribe<mrt_msgs::WorldModel, const ros::MessageEvent<mrt_msgs::WorldModel const>&>(
        "/robot1/team/world_models", 50, on_out);
    in2 = nh.subscribe<mrt_msgs::WorldModel, const ros::MessageEvent<mrt_msgs::WorldModel const>&>(
        "/robot2/team/world_models", 50, on_in);
  }
  void on_model(const mrt_msgs::WorldModel& m) { model1 = m; }
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
  static bool has(const mrt_msgs::Anchor& a, const std::string& source) {
    return std::find(a.sources.begin(), a.sources.end(), source) != a.sources.end();
  }
};

}  // namespace

TEST(TeamWorldModelOverDcdt, ModelsArriveIntactAndTheTeamBallIsFused) {
  Fixture f;
  // 1. Both see it: one anchor on robot1, supported by robot2's camera too,
  //    which robot1 can only know from robot2's model through DCDT.
  ASSERT_TRUE(wait_for([&] {
    const auto b = f.balls();
    return b.size() == 1 && b[0].status == mrt_msgs::Anchor::CONFIRMED && f.has(b[0], "robot1/omnivision") &&
           f.has(b[0], "robot2/omnivision");
  }, 25.0)) << "no single fused ball anchor on /robot1/world_model";
  const auto fused = f.balls().at(0);
  EXPECT_NEAR(fused.x, 2.0, 0.05);
  EXPECT_NEAR(fused.y, 1.0, 0.05);
  // robot1's models on robot2's team topic: at 10 Hz, 10 within ~1 s, each
  // from robot2's bridge and equal to what robot1 sent (same stamp).
  ASSERT_TRUE(wait_for([&] { return f.matched_with_anchors >= 10; }, 5.0)) << f.matched_with_anchors;
  EXPECT_EQ(f.direct, 0);
  EXPECT_EQ(f.wrong_publisher, 0);
  EXPECT_EQ(f.equal, f.matched);
  // 2. Both lose it: robot1's anchor coasts (unseen > coast_after 0.3 s).
  f.sees1 = f.sees2 = false;
  ASSERT_TRUE(wait_for([&] {
    const auto b = f.balls();
    return b.size() == 1 && b[0].status == mrt_msgs::Anchor::COASTING;
  }, 5.0)) << "robot1's ball anchor did not coast";
  EXPECT_EQ(f.balls().at(0).id, fused.id);
  // 3. robot2 sees it again, robot1 does not: back from the teammate over
  //    DCDT, same id, confirmed.
  f.sees2 = true;
  ASSERT_TRUE(wait_for([&] {
    const auto b = f.balls();
    return b.size() == 1 && b[0].status == mrt_msgs::Anchor::CONFIRMED && f.has(b[0], "robot2/omnivision");
  }, 5.0)) << "robot1 did not get the ball back from robot2";
  const auto back = f.balls().at(0);
  EXPECT_EQ(back.id, fused.id);
  EXPECT_NEAR(back.x, 2.0, 0.1);
  EXPECT_NEAR(back.y, 1.0, 0.1);
  EXPECT_EQ(f.direct, 0);
  EXPECT_EQ(f.wrong_publisher, 0);
  EXPECT_EQ(f.equal, f.matched);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "team_world_model_rostest");
  return RUN_ALL_TESTS();
}
