// Roby on a 6-point route with two unmapped obstacles on it: every path
// point is reached, the robot never comes closer than 0.3 m to any obstacle
// (ground truth), within a time bound.
#include "roby_observer.h"

TEST(RobyRoute, ReachesEveryPathPointWithClearance) {
  ros::NodeHandle pnh("~");
  std::string world;
  int points = 6;
  double limit = 220.0, min_clearance = 0.3;
  ASSERT_TRUE(pnh.getParam("world", world));
  pnh.getParam("route_points", points);
  pnh.getParam("sim_time_limit", limit);
  pnh.getParam("min_clearance", min_clearance);
  roby_test::Observer obs(world);
  ASSERT_TRUE(obs.wait([&] { return obs.truths_ > 0 && !obs.statuses_.empty(); }, 20.0, 60.0))
      << "no ground truth or task status";
  const double t0 = ros::Time::now().toSec();
  const bool done = obs.wait([&] { return obs.last_.state == mrt_msgs::TaskStatus::DONE; }, limit, 140.0);
  const double took = ros::Time::now().toSec() - t0;
  EXPECT_TRUE(done) << "state " << int(obs.last_.state) << ", reached " << obs.last_.reached;
  EXPECT_EQ(obs.last_.reached, static_cast<uint32_t>(points));
  EXPECT_EQ(obs.last_.failed, 0u);
  EXPECT_EQ(obs.last_.replans, 0u);
  EXPECT_LT(took, limit);
  EXPECT_GE(obs.min_clearance_, min_clearance) << "nearest: " << obs.nearest_;
  EXPECT_GT(obs.truths_, 1000u);
  RecordProperty("sim_seconds", std::to_string(took));
  RecordProperty("min_clearance_m", std::to_string(obs.min_clearance_));
  std::printf("route: %u path points in %.1f s of sim time, min clearance %.3f m (%s)\n", obs.last_.reached,
              took, obs.min_clearance_, obs.nearest_.c_str());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "roby_route_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
