// rostest: the distributed FollowMe, pedestal then sculpture; the north door
// (x = 10, y 8.5-9.6) closes as the leg to the sculpture starts. SPIKE
// re-plans: the leg's first plan went through the north door, every plan
// after the closure avoids it (the first of them through the south door,
// x = 10, y 2.5-3.5), the robot (ground truth) never crosses it and still
// reaches the sculpture, through the south door.
#include <nav_msgs/Odometry.h>

#include "rostest_common.h"

TEST(FollowMeChain, ClosedDoorReplansThroughAnotherDoor) {
  ros::NodeHandle nh;
  FollowMeObserver obs(nh);
  ros::Publisher close = nh.advertise<std_msgs::String>("/robot1/close_door", 1, true);
  double last_x = -1, last_y = -1;
  int north = 0, south = 0;
  auto on_truth = [&](const nav_msgs::Odometry::ConstPtr& m) {
    const double x = m->pose.pose.position.x, y = m->pose.pose.position.y;
    if (last_x >= 0 && (last_x - 10.0) * (x - 10.0) <= 0 && last_x != x) {
      const double yc = last_y + (y - last_y) * (10.0 - last_x) / (x - last_x);
      if (yc >= 8.5 && yc <= 9.6) ++north;
      if (yc >= 2.5 && yc <= 3.5) ++south;
    }
    last_x = x;
    last_y = y;
  };
  auto truth = nh.subscribe<nav_msgs::Odometry>("/robot1/ground_truth", 100, on_truth);
  std::size_t plans_at_close = 0;
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(200.0);
  while (ros::ok() && !obs.summary.received && ros::WallTime::now() < end) {
    ros::spinOnce();
    if (plans_at_close == 0 && obs.saw("Guide | next sculpture")) {
      plans_at_close = obs.plans.size();
      std_msgs::String d;
      d.data = "north_door";
      close.publish(d);
    }
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_TRUE(obs.summary.received) << "no summary; last status: "
                                    << (obs.statuses.empty() ? "" : obs.statuses.back()) << "; robot at " << last_x
                                    << ", " << last_y << "; plans " << obs.plans.size();
  const Summary& s = obs.summary;
  EXPECT_TRUE(s.completed) << s.text;
  EXPECT_EQ(s.names, "pedestal, sculpture");
  ASSERT_GE(plans_at_close, 2u);  // the legs to the pedestal and to the sculpture
  EXPECT_TRUE(crosses(obs.plans[plans_at_close - 1], 10.0, 8.5, 9.6)) << "the first plan to the sculpture";
  ASSERT_GT(obs.plans.size(), plans_at_close) << "no re-plan after the closure";
  for (std::size_t i = plans_at_close; i < obs.plans.size(); ++i)
    EXPECT_FALSE(crosses(obs.plans[i], 10.0, 8.5, 9.6)) << "plan " << i;
  bool via_south = false;  // a later re-plan (a leg's timeout) may start past the south door
  for (std::size_t i = plans_at_close; i < obs.plans.size(); ++i)
    via_south = via_south || crosses(obs.plans[i], 10.0, 2.5, 3.5);
  EXPECT_TRUE(via_south) << "the re-plan goes through the south door";
  EXPECT_EQ(north, 0);
  EXPECT_GE(south, 1);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "followme_chain_door_test");
  return RUN_ALL_TESTS();
}
