// rostest: the distributed FollowMe guides its visitor on the 4-exhibit
// tour; the visitor wanders off once (after the second exhibit, to the
// globe). The bounds: every exhibit in order, a WaitVisitor at
// each, the wander followed (FollowVisitor) and the leg re-planned, the
// visitor never out of sight > 10 s, nobody closer than 0.3 m, MUREA's
// error < 10 cm (the summary of followme_monitor_node, from ground truth).
#include "rostest_common.h"

TEST(FollowMeChain, TourWithOneWander) {
  ros::NodeHandle nh;
  FollowMeObserver obs(nh);
  ASSERT_NO_FATAL_FAILURE(expect_twice_refused("/robot1/guide/set_tour", 30.0));
  ASSERT_TRUE(obs.wait(130.0)) << "no summary; last status: " << (obs.statuses.empty() ? "" : obs.statuses.back());
  expect_tour_with_one_wander(obs);
  // It followed the visitor, then re-planned (SCARE's Replan task, SPIKE's
  // leg from where the wander left the robot).
  std::size_t follow = obs.statuses.size(), replan = obs.statuses.size();
  for (std::size_t i = 0; i < obs.statuses.size(); ++i) {
    if (follow == obs.statuses.size() && obs.statuses[i].rfind("FollowVisitor", 0) == 0) follow = i;
    if (follow < i && obs.statuses[i].rfind("Replan", 0) == 0) {
      replan = i;
      break;
    }
  }
  EXPECT_LT(follow, obs.statuses.size()) << "no FollowVisitor";
  EXPECT_LT(replan, obs.statuses.size()) << "no Replan after FollowVisitor";
  EXPECT_GE(obs.plans.size(), 4u);  // a leg to each exhibit
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "followme_chain_tour_test");
  return RUN_ALL_TESTS();
}
