// rostest: the north door closes as the leg from the pedestal to the
// sculpture starts; SPIKE re-plans through the south door and the tour is
// completed.
#include "rostest_common.h"

TEST(FollowMeNode, ClosedDoorReplansThroughAnotherDoor) {
  ros::NodeHandle nh;
  FollowMeObserver obs(nh);
  ASSERT_TRUE(obs.wait(75.0)) << "no summary; last status: " << (obs.statuses.empty() ? "" : obs.statuses.back());
  EXPECT_TRUE(obs.summary.completed) << obs.summary.text;
  EXPECT_EQ(obs.summary.names, "pedestal, sculpture");
  ASSERT_GE(obs.plans.size(), 3u);
  // the north door is x = 10, y in [8.5, 9.6]; the south door y in [2.5, 3.5]
  EXPECT_TRUE(crosses(obs.plans[1], 10.0, 8.5, 9.6));
  EXPECT_FALSE(crosses(obs.plans[2], 10.0, 8.5, 9.6));
  EXPECT_TRUE(crosses(obs.plans[2], 10.0, 2.5, 3.5));
  EXPECT_GE(obs.summary.person_gap, 0.3);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "followme_door_test");
  return RUN_ALL_TESTS();
}
