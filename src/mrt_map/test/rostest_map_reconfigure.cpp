// map_node's dynamic_reconfigure (robocup.yaml, robot1 at (0, 0) facing +x,
// pose noise 0): every 1/30 s the omnivision sees an Obstacle at (2.0, 1.0)
// and the front camera one at (2.4, 1.0), each with sigma 0.1 m (R = 0.01 I).
// The Merger's distance of the two is (0.4^2) / (0.01 + 0.01) = 8: one object
// under the model's merge gate 9.21, one anchor at about (2.2, 1.0). With
// merge_gate 4 the two observations stay apart; the anchor keeps one of them
// (its steady covariance is well under R, so the other, 0.4 m from it, is
// outside its gate 9.21: 0.16 / (P + 0.01) > 9.21 for P < 0.0074 m^2) and
// the other becomes a second anchor: two confirmed Obstacles, at (2.0, 1.0)
// and (2.4, 1.0).
#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <mrt_msgs/Percept.h>
#include <mrt_msgs/WorldModel.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <algorithm>
#include <cmath>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::spin_for;
using mrt::ros_common::wait_for;

namespace {

mrt_msgs::Percept percept(const std::string& sensor, double x, double y) {
  mrt_msgs::Percept p;
  p.header.stamp = ros::Time::now();
  p.header.frame_id = "robot1/base_link";
  p.sensor = sensor;
  p.robot = "robot1";
  mrt_msgs::PerceptObject o;
  o.name = "obstacle";
  o.membership_class = "Obstacle";
  mrt_msgs::Attribute a;
  a.name = "x";
  a.value = x;
  a.variability = 0.1;
  o.attributes.push_back(a);
  a.name = "y";
  a.value = y;
  o.attributes.push_back(a);
  p.objects.push_back(o);
  return p;
}

struct Fixture {
  ros::NodeHandle nh;
  tf2_ros::StaticTransformBroadcaster tf;
  ros::Publisher pub = nh.advertise<mrt_msgs::Percept>("/robot1/percepts", 20);
  std::vector<mrt_msgs::Anchor> obstacles;  // the confirmed ones of the last model
  ros::Subscriber sub = nh.subscribe("/robot1/world_model", 5, &Fixture::on_model, this);
  ros::Timer timer = nh.createTimer(ros::Duration(1.0 / 30), &Fixture::on_timer, this);

  Fixture() {
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time::now();
    t.header.frame_id = "map";
    t.child_frame_id = "robot1/base_link";
    t.transform.rotation.w = 1.0;
    tf.sendTransform(t);
  }
  void on_model(const mrt_msgs::WorldModel& w) {
    obstacles.clear();
    for (const auto& a : w.anchors)
      if (a.membership_class == "Obstacle" && a.status == mrt_msgs::Anchor::CONFIRMED) obstacles.push_back(a);
  }
  void on_timer(const ros::TimerEvent&) {
    pub.publish(percept("omnivision", 2.0, 1.0));
    pub.publish(percept("front_camera", 2.4, 1.0));
  }
  std::vector<mrt_msgs::Anchor> confirmed() const { return obstacles; }
};

bool set_merge_gate(double value, double* applied) {
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::DoubleParameter p;
  p.name = "merge_gate";
  p.value = value;
  srv.request.config.doubles.push_back(p);
  if (!ros::service::call("/robot1/map/set_parameters", srv)) return false;
  for (const auto& d : srv.response.config.doubles)
    if (d.name == "merge_gate") *applied = d.value;
  return true;
}

}  // namespace

TEST(MapReconfigure, ATighterMergeGateSplitsWhatWasMerged) {
  Fixture f;
  ASSERT_TRUE(ros::service::waitForService("/robot1/map/set_parameters", ros::Duration(20)));
  // 1. merge gate 9.21 (the model's): one anchor between the two sightings
  ASSERT_TRUE(wait_for([&] { return f.confirmed().size() == 1; }, 15.0)) << "no single obstacle anchor";
  spin_for(1.0);  // the percepts go on
  auto one = f.confirmed();
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0].x, 2.2, 0.1);
  EXPECT_NEAR(one[0].y, 1.0, 0.05);

  // 2. merge gate 4 < 8: two anchors, one at each sighting
  double applied = 0;
  ASSERT_TRUE(set_merge_gate(4.0, &applied));
  EXPECT_DOUBLE_EQ(applied, 4.0);
  ASSERT_TRUE(wait_for([&] { return f.confirmed().size() == 2; }, 10.0)) << "the anchor was not split";
  spin_for(1.0);  // the percepts go on
  auto two = f.confirmed();
  ASSERT_EQ(two.size(), 2u);
  std::sort(two.begin(), two.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  EXPECT_NEAR(two[0].x, 2.0, 0.05);
  EXPECT_NEAR(two[1].x, 2.4, 0.05);
  for (const auto& a : two) EXPECT_NEAR(a.y, 1.0, 0.05);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mrt_map_reconfigure_rostest");
  return RUN_ALL_TESTS();
}
