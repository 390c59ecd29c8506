// rostest of the vision bringup (test/murea_camera.test): simulator camera
// -> recvision_node -> murea_node (mice odometry, no prior). After the
// first pose and 2 s (sim time) of convergence, the poses of the next 8 s
// of sim time are compared with the ground truth at their stamps.
//
// Bounds (issue 15, tracking: "RMSE at most 3 cm and 1 deg, worst error
// under 10 cm"): RMSE < 3 cm, heading RMSE < 1 deg, worst < 10 cm. The
// bringup measured RMSE 0.8 cm, worst 5.1 cm, median heading error 0.12
// deg on 60 s at 0.6 m/s (README): the bounds leave room for a loaded
// machine (fewer frames, longer odometry gaps) but fail on a pose off by
// a line spacing or on the field's mirror (18 m away). Sim time throughout;
// no wall-clock speed is asserted (only a wall-time limit on waiting).
#include <gtest/gtest.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <vector>

#include "mrt_common/angle.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::common::Pose2D;
namespace rc = mrt::ros_common;

struct Recorder {
  std::deque<nav_msgs::Odometry> truth;  // the last 10 s of ground truth (100 Hz)
  struct Sample {
    double stamp, d, a;  // sim time (s), position error (m), heading error (rad); d < 0: no truth
    Pose2D pose, truth;
    bool on_mirror = false;  // within 0.3 m / 10 deg of the field's half-turn mirror of the truth
  };
  std::vector<Sample> samples;
  void on_truth(const nav_msgs::Odometry& m) {
    truth.push_back(m);
    while (truth.size() > 1000) truth.pop_front();
  }
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    const Pose2D p = rc::to_pose2d(m.pose.pose);
    const nav_msgs::Odometry* best = nullptr;
    for (const auto& t : truth)
      if (!best || std::abs((t.header.stamp - m.header.stamp).toSec()) <
                       std::abs((best->header.stamp - m.header.stamp).toSec()))
        best = &t;
    Sample s{m.header.stamp.toSec(), -1.0, -1.0, p, Pose2D()};
    if (best && std::abs((best->header.stamp - m.header.stamp).toSec()) <= 0.02) {
      const Pose2D t = rc::to_pose2d(best->pose.pose);
      s.truth = t;
      s.d = std::hypot(p.x - t.x, p.y - t.y);
      s.a = std::abs(mrt::common::angle_diff(p.theta, t.theta));
      s.on_mirror = std::hypot(p.x + t.x, p.y + t.y) < 0.3 &&
                    std::abs(mrt::common::angle_diff(p.theta, t.theta + M_PI)) < mrt::common::deg_to_rad(10);
    }
    samples.push_back(s);
  }
};

}  // namespace

TEST(MureaCamera, LocalizesFromTheRenderedCamera) {
  ros::NodeHandle nh;
  Recorder rec;
  ros::Subscriber st = nh.subscribe("/robot1/ground_truth", 1000, &Recorder::on_truth, &rec);
  ros::Subscriber sp = nh.subscribe("/robot1/pose", 100, &Recorder::on_pose, &rec);

  // No prior: the first pose comes once a coloured goal or post is in view.
  ASSERT_TRUE(rc::wait_for([&] { return !rec.samples.empty(); }, 40.0)) << "no /robot1/pose within 40 s";
  const double first = rec.samples.front().stamp;
  const double from = first + 2.0, to = from + 8.0;  // convergence, then 8 s of sim time compared
  // Wall time is only a limit: a loaded machine covers less sim time.
  rc::wait_for([&] { return rec.samples.back().stamp >= to; }, 35.0);

  const auto& f = rec.samples.front();
  std::printf("camera bringup: first pose (%.2f, %.2f, %.1f deg), truth (%.2f, %.2f, %.1f deg)\n", f.pose.x, f.pose.y,
              f.pose.theta * 180 / M_PI, f.truth.x, f.truth.y, f.truth.theta * 180 / M_PI);
  int compared = 0, mirrored = 0;
  double sum_d2 = 0, sum_a2 = 0, worst_d = 0, worst_a = 0;
  for (const auto& s : rec.samples) {
    if (s.stamp < from || s.stamp > to || s.d < 0.0) continue;
    ++compared;
    mirrored += s.on_mirror ? 1 : 0;
    sum_d2 += s.d * s.d;
    sum_a2 += s.a * s.a;
    worst_d = std::max(worst_d, s.d);
    worst_a = std::max(worst_a, s.a);
  }
  std::printf("camera bringup: first pose at %.2f s (sim), %zu poses, %d compared over %.1f s of sim time\n",
              first, rec.samples.size(), compared, rec.samples.back().stamp - from);
  // At least 3 s of sim time at 10 poses/s (the camera runs at 30 Hz; a
  // loaded machine drops images).
  ASSERT_GE(compared, 30) << "too few poses with ground truth after convergence";
  const double rmse = std::sqrt(sum_d2 / compared), rmse_a = std::sqrt(sum_a2 / compared);
  std::printf("camera bringup: %d of the compared poses on the field's mirror of the truth\n", mirrored);
  std::printf("camera bringup: RMSE %.2f cm, %.3f deg, worst %.2f cm, %.2f deg\n", 100 * rmse,
              rmse_a * 180 / M_PI, 100 * worst_d, worst_a * 180 / M_PI);
  EXPECT_LT(rmse, 0.03);
  EXPECT_LT(rmse_a, mrt::common::deg_to_rad(1.0));
  EXPECT_LT(worst_d, 0.10);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "murea_camera_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
