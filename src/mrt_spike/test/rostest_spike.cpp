// spike_node on the Roby outdoor map (mrt_world.s roby_outdoor world at 0.1 m,
// robot radius 0.3 + safety 0.1): make_plan around the buildings, and a new
// plan when a person steps onto the current one.
#include <gtest/gtest.h>
#include <mrt_msgs/Percept.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <cmath>

#include "mrt_common_ros/rostest_helpers.h"
#include "mrt_world/world_loader.h"

using mrt::ros_common::wait_for;

namespace {

double clearance(const mrt::world::World& w, double x, double y) {
  double d = 1e9;
  for (const auto& s : mrt::world::solid_segments(w)) d = std::min(d, mrt::world::distance_to_segment({x, y}, s));
  for (const auto& p : w.posts) d = std::min(d, std::hypot(x - p.center.x, y - p.center.y) - p.radius);
  return d;
}

geometry_msgs::PoseStamped pose(double x, double y, const std::string& frame = "map") {
  geometry_msgs::PoseStamped p;
  p.header.frame_id = frame;
  p.pose.position.x = x, p.pose.position.y = y;
  p.pose.orientation.w = 1.0;
  return p;
}

}  // namespace

TEST(SpikeNode, MakePlanOnTheRobyMap) {
  ros::NodeHandle nh, pnh("~");
  std::string world_file;
  ASSERT_TRUE(pnh.getParam("world", world_file));
  const mrt::world::World w = mrt::world::load_world(world_file);
  ASSERT_TRUE(ros::service::waitForService("make_plan", ros::Duration(20)));
  nav_msgs::GetPlan srv;
  // Roby's route ends: (8, 0) to (36, 20), past buildings A, B and C.
  srv.request.start = pose(8, 0);
  srv.request.goal = pose(36, 20);
  ASSERT_TRUE(ros::service::call("make_plan", srv));
  const auto& ps = srv.response.plan.poses;
  ASSERT_GT(ps.size(), 10u);
  EXPECT_EQ(srv.response.plan.header.frame_id, "map");
  EXPECT_NEAR(ps.front().pose.position.x, 8, 0.051);
  EXPECT_NEAR(ps.front().pose.position.y, 0, 0.051);
  EXPECT_NEAR(ps.back().pose.position.x, 36, 0.051);
  EXPECT_NEAR(ps.back().pose.position.y, 20, 0.051);
  double length = 0.0;
  for (size_t i = 0; i < ps.size(); ++i) {
    const auto& p = ps[i].pose.position;
    // inflation 0.4 m on a 0.1 m grid whose cells block when within 0.0707
    // of a wall: poses keep at least 0.4 - 0.0707 from every object
    EXPECT_GE(clearance(w, p.x, p.y), 0.4 - 0.071) << i << " at " << p.x << ", " << p.y;
    if (i == 0) continue;
    const double step = std::hypot(p.x - ps[i - 1].pose.position.x, p.y - ps[i - 1].pose.position.y);
    EXPECT_LE(step, 0.25 + 1e-6);  // the spacing parameter
    length += step;
  }
  // at least the straight distance hypot(28, 20) = 34.41; any-angle round the
  // buildings adds little: well under the L1 distance 48
  EXPECT_GE(length, std::hypot(28.0, 20.0) - 0.15);
  EXPECT_LE(length, 40.0);
  // a goal inside building B: an empty plan
  srv.request.goal = pose(24, 5);
  ASSERT_TRUE(ros::service::call("make_plan", srv));
  EXPECT_TRUE(srv.response.plan.poses.empty());
}

// make_plan as navfn's: start and goal in another frame (`site`, at (10, 5)
// in map, static tf) come back in map; a goal 0.2 m inside building B's
// north wall (y = 8, x in [20, 28]) gives an empty plan without tolerance
// or with 0.3 m, and with 1.0 m a plan to the nearest reachable point: just
// north of the wall, beyond the inflation (0.4 m), within 1.0 m of the goal.
TEST(SpikeNode, MakePlanAcrossFramesAndWithinTolerance) {
  ASSERT_TRUE(ros::service::waitForService("make_plan", ros::Duration(20)));
  nav_msgs::GetPlan srv;
  srv.request.start = pose(8 - 10, 0 - 5, "site");
  srv.request.goal = pose(36 - 10, 20 - 5, "site");
  ASSERT_TRUE(ros::service::call("make_plan", srv));
  const auto& ps = srv.response.plan.poses;
  ASSERT_GT(ps.size(), 10u);
  EXPECT_EQ(srv.response.plan.header.frame_id, "map");
  EXPECT_NEAR(ps.front().pose.position.x, 8, 0.051);
  EXPECT_NEAR(ps.back().pose.position.x, 36, 0.051);
  EXPECT_NEAR(ps.back().pose.position.y, 20, 0.051);
  srv.request.start = pose(8, 0);
  srv.request.goal = pose(24, 7.8);
  ASSERT_TRUE(ros::service::call("make_plan", srv));
  EXPECT_TRUE(srv.response.plan.poses.empty());
  srv.request.tolerance = 0.3;
  ASSERT_TRUE(ros::service::call("make_plan", srv));
  EXPECT_TRUE(srv.response.plan.poses.empty());
  srv.request.tolerance = 1.0;
  ASSERT_TRUE(ros::service::call("make_plan", srv));
  ASSERT_FALSE(srv.response.plan.poses.empty());
  const auto& end = srv.response.plan.poses.back().pose.position;
  EXPECT_LE(std::hypot(end.x - 24, end.y - 7.8), 1.0);
  EXPECT_GE(end.y, 8 + 0.4 - 0.071);  // outside the building, clear of its wall
  srv.request.goal = pose(24, 7.8, "nowhere");  // a frame tf does not know: empty
  ASSERT_TRUE(ros::service::call("make_plan", srv));
  EXPECT_TRUE(srv.response.plan.poses.empty());
}

TEST(SpikeNode, ReplansWhenAPersonStepsOntoThePath) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::Path> plans;
  auto sub = nh.subscribe<nav_msgs::Path>("plan", 10, [&](const nav_msgs::PathConstPtr& p) { plans.push_back(*p); });
  auto goal_pub = nh.advertise<geometry_msgs::PoseStamped>("goal", 1, true);
  auto percept_pub = nh.advertise<mrt_msgs::Percept>("percepts", 5);
  ASSERT_TRUE(wait_for([&] { return goal_pub.getNumSubscribers() > 0 && percept_pub.getNumSubscribers() > 0; }, 20));
  // the robot stands at (18, 10.5) (static tf): the way to (28, 10.5) between
  // buildings B (y <= 8) and C (y >= 13) is the straight line
  goal_pub.publish(pose(28, 10.5));
  ASSERT_TRUE(wait_for([&] { return !plans.empty(); }, 10));
  const nav_msgs::Path first = plans.back();
  ASSERT_FALSE(first.poses.empty());
  for (const auto& p : first.poses) EXPECT_NEAR(p.pose.position.y, 10.5, 0.051);
  // a person steps onto it at (23, 10.5), in the map frame
  mrt_msgs::Percept pc;
  pc.header.frame_id = "map";
  pc.sensor = "camera";
  pc.robot = "robot1";
  mrt_msgs::PerceptObject o;
  o.name = "visitor";
  o.membership_class = "Person";
  mrt_msgs::Attribute a;
  a.name = "x", a.value = 23.0;
  o.attributes.push_back(a);
  a.name = "y", a.value = 10.5;
  o.attributes.push_back(a);
  pc.objects.push_back(o);
  const size_t before = plans.size();
  const ros::WallTime t0 = ros::WallTime::now();
  ASSERT_TRUE(wait_for([&] {
    pc.header.stamp = ros::Time::now();
    percept_pub.publish(pc);
    return plans.size() > before;
  }, 10, 0.1));
  const double dt = (ros::WallTime::now() - t0).toSec();
  EXPECT_LT(dt, 2.0);
  const nav_msgs::Path& second = plans.back();
  ASSERT_FALSE(second.poses.empty());
  // round the person: person 0.25 (default radius) + robot 0.3 + safety 0.1
  // = 0.65 m from its centre, less half a cell's diagonal (0.0707)
  double closest = 1e9;
  for (const auto& p : second.poses)
    closest = std::min(closest, std::hypot(p.pose.position.x - 23.0, p.pose.position.y - 10.5));
  EXPECT_GE(closest, 0.65 - 0.071);
  EXPECT_NEAR(second.poses.back().pose.position.x, 28, 0.051);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "spike_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  tf2_ros::StaticTransformBroadcaster tf;  // the robot stands at (18, 10.5)
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "map";
  t.child_frame_id = "base_link";
  t.transform.translation.x = 18.0, t.transform.translation.y = 10.5;
  t.transform.rotation.w = 1.0;
  geometry_msgs::TransformStamped site = t;  // another fixed frame, at (10, 5)
  site.child_frame_id = "site";
  site.transform.translation.x = 10.0, site.transform.translation.y = 5.0;
  tf.sendTransform(std::vector<geometry_msgs::TransformStamped>{t, site});
  return RUN_ALL_TESTS();
}
