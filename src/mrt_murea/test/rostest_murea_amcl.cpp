// rostest of murea_node's amcl interface (test/murea_amcl.test): amcl's
// parameter names take effect over MUREA's older aliases; amcl_pose, pose
// and particlecloud are published; request_nomotion_update gives a new
// amcl_pose while the robot stands still; set_map replaces the map and
// starts from the request's initial pose; tf_broadcast false publishes no
// map -> odom. The robot stands at (8.7, 3, pi/2) in the museum's
// south-west room; the estimates must be within 7 cm and 1.5 deg of the
// truth (the tolerance of rostest_murea_laser.cpp, worked out there).
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/SetMap.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "laser_sim.h"
#include "mrt_common/angle.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::common::Pose2D;
using namespace mrt::murea::test;
namespace rc = mrt::ros_common;

const double kMaxXy = 0.07, kMaxTheta = mrt::common::deg_to_rad(1.5);

struct Recorder {
  std::vector<geometry_msgs::PoseWithCovarianceStamped> amcl, pose;
  std::vector<geometry_msgs::PoseArray> clouds;
  std::vector<std::string> tf_children;  // child frames of every /tf transform from the world frame
  std::map<std::string, std::string> diag;
  nav_msgs::OccupancyGrid::ConstPtr map;
  void on_amcl(const geometry_msgs::PoseWithCovarianceStamped& m) { amcl.push_back(m); }
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) { pose.push_back(m); }
  void on_cloud(const geometry_msgs::PoseArray& m) { clouds.push_back(m); }
  void on_map(const nav_msgs::OccupancyGrid::ConstPtr& m) { map = m; }
  void on_tf(const tf2_msgs::TFMessage& m) {
    for (const auto& t : m.transforms)
      if (t.header.frame_id == "world" || t.header.frame_id == "wrong_map") tf_children.push_back(t.child_frame_id);
  }
  void on_diag(const diagnostic_msgs::DiagnosticArray& m) {
    for (const auto& st : m.status)
      if (st.name.find("murea") != std::string::npos)
        for (const auto& kv : st.values) diag[kv.key] = kv.value;
  }
};

void expect_near(const geometry_msgs::Pose& m, const Pose2D& truth, const char* what) {
  const Pose2D p = rc::to_pose2d(m);
  EXPECT_LT(std::hypot(p.x - truth.x, p.y - truth.y), kMaxXy) << what << " at (" << p.x << ", " << p.y << ")";
  EXPECT_LT(std::abs(mrt::common::angle_diff(p.theta, truth.theta)), kMaxTheta) << what << " heading " << p.theta;
}

// 4. set_map: the museum's grid moved 1 m along x, tracking from the
// truth's place in it; the scans of the same place give (9.7, 3, pi/2).
template <class ScanUntil>
void check_set_map(Recorder& rec, ScanUntil& scan_until, const Pose2D& truth) {
  ASSERT_TRUE(rec.map) << "no map on `map`";
  nav_msgs::SetMap sm;
  sm.request.map = *rec.map;
  sm.request.map.info.origin.position.x += 1.0;
  sm.request.initial_pose.header.frame_id = "world";
  sm.request.initial_pose.pose.pose = rc::to_pose(Pose2D(truth.x + 1.0, truth.y, truth.theta));
  sm.request.initial_pose.pose.covariance[0] = sm.request.initial_pose.pose.covariance[7] = 0.01;
  sm.request.initial_pose.pose.covariance[35] = 0.01;
  ASSERT_TRUE(ros::service::call("set_map", sm));
  EXPECT_TRUE(sm.response.success);
  const std::size_t before_map = rec.amcl.size();
  ASSERT_TRUE(scan_until([&] { return rec.amcl.size() > before_map + 3; }, 10.0));
  expect_near(rec.amcl.back().pose.pose, Pose2D(truth.x + 1.0, truth.y, truth.theta), "amcl_pose after set_map");
  // An empty map is refused.
  nav_msgs::SetMap bad;
  bad.request.initial_pose.pose.pose.orientation.w = 1.0;
  ASSERT_TRUE(ros::service::call("set_map", bad));
  EXPECT_FALSE(bad.response.success);

}

}  // namespace

TEST(MureaAmcl, AmclInterface) {
  ros::NodeHandle nh, pnh("~");
  std::string world;
  ASSERT_TRUE(pnh.getParam("world", world));
  Recorder rec;
  ros::Subscriber s1 = nh.subscribe("amcl_pose", 50, &Recorder::on_amcl, &rec);
  ros::Subscriber s2 = nh.subscribe("pose", 50, &Recorder::on_pose, &rec);
  ros::Subscriber s3 = nh.subscribe("particlecloud", 50, &Recorder::on_cloud, &rec);
  ros::Subscriber s4 = nh.subscribe("/tf", 200, &Recorder::on_tf, &rec);
  ros::Subscriber s5 = nh.subscribe("/diagnostics", 10, &Recorder::on_diag, &rec);
  ros::Subscriber s6 = nh.subscribe("map", 1, &Recorder::on_map, &rec);
  LaserSim sim(world, Pose2D(0.1, 0.0, 0.0));
  const Pose2D truth(8.7, 3.0, M_PI / 2);
  DriftingOdometry odom(truth, 0.0, 0.0);
  // Frames by amcl's names: the node must look up odom2 -> base2.
  LaserRobot robot(sim, odom, "odom2", "base2", "laser");
  ASSERT_TRUE(rc::wait_for([&] { return robot.connected(); }, 20.0));

  // 1. Standing still, scanning at 10 Hz: amcl_pose and pose, the same
  // message, in the frame global_frame_id names; particlecloud there too.
  ros::Time last_scan;
  auto scan_until = [&](auto pred, double seconds) {
    return rc::wait_for(
        [&] {
          last_scan = ros::Time::now();
          robot.step(truth, last_scan);
          return pred();
        },
        seconds, 0.1);
  };
  ASSERT_TRUE(scan_until([&] { return rec.amcl.size() >= 5 && rec.pose.size() >= 5 && !rec.clouds.empty(); }, 30.0))
      << "amcl_pose " << rec.amcl.size() << ", pose " << rec.pose.size() << ", particlecloud " << rec.clouds.size();
  const auto& a = rec.amcl.back();
  EXPECT_EQ(a.header.frame_id, "world");
  expect_near(a.pose.pose, truth, "amcl_pose");
  const auto& p = rec.pose.back();  // the amcl_pose of its stamp carries the same pose
  bool same = false;
  for (const auto& m : rec.amcl)
    same = same || (m.header.stamp == p.header.stamp && m.pose.pose.position.x == p.pose.pose.position.x &&
                    m.pose.pose.position.y == p.pose.pose.position.y && m.pose.covariance == p.pose.covariance);
  EXPECT_TRUE(same) << "no amcl_pose equal to the last pose";
  const auto& c = rec.clouds.back();
  EXPECT_EQ(c.header.frame_id, "world");
  ASSERT_FALSE(c.poses.empty());
  for (const auto& q : c.poses) {  // the plateau: within its box (0.3 m, 10 deg) of the truth
    const Pose2D qq = rc::to_pose2d(q);
    EXPECT_LT(std::hypot(qq.x - truth.x, qq.y - truth.y), 0.3 * std::sqrt(2.0) + kMaxXy);
  }

  // 2. laser_max_beams (20) wins over scan_max_beams (40): 20 wall points per scan.
  EXPECT_TRUE(scan_until([&] { return rec.diag["laser beams used, last scan"] == "20"; }, 5.0))
      << "beams used: " << rec.diag["laser beams used, last scan"];

  // 3. request_nomotion_update: no scan, no motion; a new amcl_pose for the
  // last scan's stamp.
  rc::spin_for(0.5);
  const std::size_t before = rec.amcl.size();
  std_srvs::Empty empty;
  ASSERT_TRUE(ros::service::call("request_nomotion_update", empty));
  ASSERT_TRUE(rc::wait_for([&] { return rec.amcl.size() > before; }, 3.0)) << "no amcl_pose after the no-motion update";
  EXPECT_EQ(rec.amcl.back().header.stamp, last_scan);
  expect_near(rec.amcl.back().pose.pose, truth, "no-motion amcl_pose");

  check_set_map(rec, scan_until, truth);
  if (HasFatalFailure()) return;

  // 5. tf_broadcast false (over publish_tf true): no map -> odom at all.
  EXPECT_TRUE(rec.tf_children.empty()) << "a transform from the map frame to " << rec.tf_children.front();
  EXPECT_TRUE(ros::service::exists("global_localization", false));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "murea_amcl_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
