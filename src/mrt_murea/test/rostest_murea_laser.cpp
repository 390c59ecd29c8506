// rostest of murea_node on a laser robot (test/murea_laser.test): scans
// ray-cast in the museum from known poses along an ellipse, odometry that
// drifts (3 % scale, 0.03 rad per metre), the map from the `map` topic;
// the estimates on amcl_pose stay within the tolerance of the truth.
//
// The tolerance, worked out: MUREA localizes in world_node's occupancy
// grid (5 cm cells; a cell is occupied when its centre is within
// 5 cm / sqrt(2) of a wall), whose walls run through the occupied cells'
// centres. The museum's walls lie on cell edges, so each map wall stands
// 2.5 cm in front of the true one (posts: up to 3.5 cm): a bias of at most
// 2.5 cm per axis, 3.5 cm in the plane, where the walls seen do not
// balance. The range noise (1 cm sd) over 30 beams moves the least-squares
// fit by about 1 cm / sqrt(15) ~ 0.3 cm. Should the fit fall back to the
// plateau's mean, the lattice adds up to half a cell (2.5 cm, 0.5 deg).
// Hence every estimate within 3.5 + 2.5 + 3 x 0.3 ~ 7 cm, and the RMSE
// within the bias plus noise, 3.5 cm; headings within 0.5 deg (lattice)
// + 3 sd of the noise's (~0.05 deg each) + the walls' misalignment (none:
// the grid is aligned with the walls): 1.5 deg allows a margin of 0.85 deg.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "laser_sim.h"
#include "mrt_common/angle.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::common::Pose2D;
using namespace mrt::murea::test;
namespace rc = mrt::ros_common;

const double kMaxXy = 0.07, kRmseXy = 0.035, kMaxTheta = mrt::common::deg_to_rad(1.5);

struct Errors {
  std::map<ros::Time, Pose2D> truth;  // every scan's true pose, by stamp
  std::vector<std::pair<double, double>> errors;  // (m, rad) per estimate
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    const auto it = truth.find(m.header.stamp);
    if (it == truth.end()) return;
    const Pose2D p = rc::to_pose2d(m.pose.pose), t = it->second;
    errors.emplace_back(std::hypot(p.x - t.x, p.y - t.y), std::abs(mrt::common::angle_diff(p.theta, t.theta)));
  }
};

}  // namespace

TEST(MureaLaser, TracksAnEllipseFromScans) {
  ros::NodeHandle nh, pnh("~");
  std::string world;
  ASSERT_TRUE(pnh.getParam("world", world));
  LaserSim sim(world, Pose2D(0.1, 0.0, 0.0));
  DriftingOdometry odom(ellipse_pose(0.0), 0.03, 0.03);
  LaserRobot robot(sim, odom, "odom", "base_link", "laser");
  Errors e;
  ros::Subscriber sub = nh.subscribe("amcl_pose", 50, &Errors::on_pose, &e);
  ASSERT_TRUE(rc::wait_for([&] { return robot.connected() && sub.getNumPublishers() > 0; }, 20.0));
  // Standing at the start until the node has world_node's map and
  // answers (as a robot waits for its localization), then 25 s of the
  // path (a full turn, 14 m), a scan every 0.1 s.
  ASSERT_TRUE(rc::wait_for(
      [&] {
        const ros::Time stamp = ros::Time::now();
        e.truth[stamp] = ellipse_pose(0.0);
        robot.step(ellipse_pose(0.0), stamp);
        return !e.errors.empty();
      },
      30.0, 0.1))
      << "no amcl_pose while standing at the start";
  e.errors.clear();
  const int kScans = 250;
  for (int i = 0; i < kScans && ros::ok(); ++i) {
    const ros::Time stamp = ros::Time::now();
    const Pose2D truth = ellipse_pose(0.1 * i);
    e.truth[stamp] = truth;
    robot.step(truth, stamp);
    rc::spin_for(0.1);
  }
  rc::wait_for([&] { return false; }, 1.0);  // the last estimates
  ASSERT_GT(e.errors.size(), kScans * 8u / 10u) << "fewer than 80 % of the scans gave an estimate";
  double worst_d = 0, worst_a = 0, sum_d2 = 0;
  for (std::size_t i = 3; i < e.errors.size(); ++i) {  // after the initial pose's offset is corrected
    worst_d = std::max(worst_d, e.errors[i].first);
    worst_a = std::max(worst_a, e.errors[i].second);
    sum_d2 += e.errors[i].first * e.errors[i].first;
  }
  const double rmse = std::sqrt(sum_d2 / (e.errors.size() - 3));
  const Pose2D dead = ellipse_pose(0.0) * odom.odom(), end = ellipse_pose(0.1 * (kScans - 1));
  std::printf("laser tracking: %zu estimates of %d scans, RMSE %.4f m, worst %.4f m, %.3f deg; odometry alone ends "
              "%.2f m off\n",
              e.errors.size(), kScans, rmse, worst_d, mrt::common::rad_to_deg(worst_a),
              std::hypot(dead.x - end.x, dead.y - end.y));
  EXPECT_LT(worst_d, kMaxXy);
  EXPECT_LT(rmse, kRmseXy);
  EXPECT_LT(worst_a, kMaxTheta);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "murea_laser_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
