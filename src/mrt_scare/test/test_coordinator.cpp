// The distributed coordinator: three robots exchanging messages agree,
// stale data are penalised, a silent robot's job is re-assigned in the
// cycle it is dropped, a joining robot gets a job, bad messages are refused.
#include <gtest/gtest.h>

#include <set>

#include "mrt_scare/coordinator.h"

using namespace mrt::scare;

namespace {

ActivitySet robocup() { return load_activities(MRT_SCARE_CONFIG_DIR "/robocup_activities.yaml"); }

// Our ball near midfield, the shot blocked, some threat: PassageToMate and
// Defense are opportune, BringBall little.
CrispMap passing() {
  return {{"BallX", {0.5, 1}}, {"BallY", {1.0, 1}}, {"BallSeen", {1, 1}}, {"BallOwned", {0.9, 1}},
          {"ShotClear", {0.1, 1}}, {"Threat", {0.6, 1}}, {"ReceiveX", {3.0, 1}}, {"ReceiveY", {-2.0, 1}}};
}

struct Team {
  std::vector<Coordinator> c;
  std::vector<Pose2D> pose{{0.0, 1.0, 0}, {1.0, 0.5, 0}, {2.5, -2.0, 0}};
  explicit Team(double listen = 0.0) {
    const ActivitySet s = robocup();
    CoordinatorOptions o;
    o.listen = listen;
    for (const char* id : {"robot1", "robot2", "robot3"}) c.emplace_back(s, s.robot_or_default(id), o);
  }
  /// One cycle at time t: everyone publishes, `alive` robots' messages reach the others, all step.
  void cycle(double t, const std::vector<bool>& alive, const CrispMap& crisp) {
    std::vector<CoordinationMessage> msgs;
    for (std::size_t i = 0; i < c.size(); ++i) msgs.push_back(alive[i] ? c[i].publish(t, pose[i], crisp) : CoordinationMessage{});
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j)
        if (alive[i] && alive[j] && i != j) c[i].receive(msgs[j]);
    for (std::size_t i = 0; i < c.size(); ++i)
      if (alive[i]) c[i].step(t);
  }
  std::string job(std::size_t i) const { return c[i].set().slot_name(c[i].set().slots()[static_cast<std::size_t>(c[i].own_slot())]); }
};

}  // namespace

TEST(Coordinator, ConfidenceFallsAfterTheGrace) {
  const ActivitySet s = robocup();
  Coordinator c(s, s.robot_or_default("robot1"));  // grace 0.5 s, drop 1.0 s, floor 0.5
  EXPECT_DOUBLE_EQ(c.confidence(0.5), 1.0);
  EXPECT_DOUBLE_EQ(c.confidence(0.75), 0.75);  // half-way: 1 - 0.5 * 0.5
  EXPECT_DOUBLE_EQ(c.confidence(1.0), 0.5);
}

TEST(Coordinator, ThreeRobotsAgreeAndCoverThePassage) {
  Team t;
  const std::vector<bool> all{true, true, true};
  t.cycle(0.0, all, passing());  // messages arrive before the robots allocate
  t.cycle(0.1, all, passing());
  // Every robot computed the same allocation.
  EXPECT_EQ(t.c[0].last().slot, t.c[1].last().slot);
  EXPECT_EQ(t.c[1].last().slot, t.c[2].last().slot);
  // robot2 (passer 0.9, 1.5 m/s, 0.5 m from the ball) passes, robot3
  // (receiver 0.9, 0.5 m from the reception point) receives, robot1 defends.
  EXPECT_EQ(t.job(0), "Defense");
  EXPECT_EQ(t.job(1), "PassageToMate.passer");
  EXPECT_EQ(t.job(2), "PassageToMate.receiver");
  // Coordination parameters: the passer's mate is robot3 (index 3) at (2.5, -2).
  std::map<std::string, double> crisp;
  for (const CrispOut& o : t.c[1].crisp_output()) crisp[o.name] = o.value;
  EXPECT_EQ(crisp["ScareJob_PassageToMate"], 1.0);
  EXPECT_EQ(crisp["ScareJob_Defense"], 0.0);
  EXPECT_EQ(crisp["ScareRole_PassageToMate_passer"], 1.0);
  EXPECT_EQ(crisp["ScareMate_receiver_Index"], 3.0);
  EXPECT_EQ(crisp["ScareMate_receiver_X"], 2.5);
  EXPECT_EQ(crisp["ScareMate_receiver_Y"], -2.0);
  EXPECT_EQ(crisp["ScareTeamSize"], 3.0);
}

TEST(Coordinator, StartingRobotListensBeforeTakingASlot) {
  Team t(0.5);  // the default: listen 0.5 s from the first message
  const std::vector<bool> all{true, true, true};
  for (int k = 0; k < 4; ++k) {
    t.cycle(0.125 * k, all, passing());
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(t.c[i].waiting());
      EXPECT_EQ(t.c[i].own_slot(), -1);
    }
  }
  t.cycle(0.5, all, passing());
  EXPECT_EQ(t.job(0), "Defense");
  EXPECT_EQ(t.job(1), "PassageToMate.passer");
  EXPECT_EQ(t.job(2), "PassageToMate.receiver");
}

TEST(Coordinator, DropOutReassignedInTheCycleItIsDetected) {
  Team t;
  const std::vector<bool> all{true, true, true}, no3{true, true, false};
  // Cycles every 0.125 s (exact in binary). Utilities (priority * opportunity
  // * attitude / (1 + time / 2)), hand-worked in the README's example:
  // robot1 Defense 0.1355, receiver 0.1442; robot2 passer 0.6555; robot3
  // receiver 0.6703; hysteresis 0.15.
  for (int k = 0; k <= 4; ++k) t.cycle(0.125 * k, all, passing());
  ASSERT_EQ(t.job(2), "PassageToMate.receiver");
  // robot3 falls silent after t = 0.5; it is kept, penalised, until its data
  // are more than 1.0 s old: dropped at t = 1.625, the first cycle past 1.5.
  double t_drop = -1;
  for (int k = 5; k < 20 && t_drop < 0; ++k) {
    t.cycle(0.125 * k, no3, passing());
    if (t.c[0].team_size() == 2) t_drop = 0.125 * k;
    if (t_drop < 0) {
      EXPECT_EQ(t.job(0), "Defense");
    }
  }
  EXPECT_DOUBLE_EQ(t_drop, 1.625);
  // In that same cycle the uncovered receiver role is filled again: the
  // passage (0.6555 + 0.15 + 0.1442 = 0.95) beats robot1 defending and
  // robot2 bringing the ball (0.1355 + 0.15 + 0.0728 = 0.36).
  EXPECT_EQ(t.c[0].last().slot, t.c[1].last().slot);
  EXPECT_EQ(t.job(0), "PassageToMate.receiver");
  EXPECT_EQ(t.job(1), "PassageToMate.passer");
}

TEST(Coordinator, JoiningRobotIsGivenAJob) {
  Team t;
  const std::vector<bool> two{true, true, false}, all{true, true, true};
  for (int k = 0; k < 3; ++k) t.cycle(0.1 * k, two, passing());
  EXPECT_EQ(t.c[0].team_size(), 2u);
  EXPECT_EQ(t.job(0), "PassageToMate.receiver");  // two robots: the passage (0.80) beats 0.36
  t.cycle(0.3, all, passing());  // robot3 appears
  EXPECT_EQ(t.c[0].team_size(), 3u);
  // robot3 receives (0.6703) and robot1 defends again (0.1355): 1.61 with
  // robot2's bonus, against 1.18 for robot1 staying receiver. robot1 still
  // claimed the receiver role in its last message: robot3 waits a cycle.
  EXPECT_EQ(t.job(0), "Defense");
  EXPECT_TRUE(t.c[2].waiting());
  EXPECT_EQ(t.c[2].own_slot(), -1);
  t.cycle(0.4, all, passing());
  EXPECT_FALSE(t.c[2].waiting());
  EXPECT_EQ(t.job(2), "PassageToMate.receiver");
  EXPECT_EQ(t.c[0].last().slot, t.c[2].last().slot);
}

TEST(Coordinator, SwapDoesNotDeadlock) {
  Team t;
  const std::vector<bool> all{true, true, true};
  for (int k = 0; k < 3; ++k) t.cycle(0.1 * k, all, passing());
  ASSERT_EQ(t.job(1), "PassageToMate.passer");
  ASSERT_EQ(t.job(2), "PassageToMate.receiver");
  // robot2 moves onto the reception point (3, -2), robot3 onto the ball
  // (0.5, 1): swapped, 0.6 * 0.9 + 0.5 * 0.9 = 0.99 beats keeping the roles,
  // 0.9 * 0.9 / (1 + 2.603 / 2) + 0.9 * 0.9 / (1 + 3.254 / 2) + 2 * 0.15 = 0.96.
  // Each waits for the other's release, both release in the same cycle
  // (holding nothing), both acquire in the next.
  t.pose[1] = Pose2D(3.0, -2.0, 0);
  t.pose[2] = Pose2D(0.5, 1.0, 0);
  t.cycle(0.3, all, passing());
  EXPECT_TRUE(t.c[1].waiting());
  EXPECT_TRUE(t.c[2].waiting());
  t.cycle(0.4, all, passing());
  EXPECT_EQ(t.job(1), "PassageToMate.receiver");
  EXPECT_EQ(t.job(2), "PassageToMate.passer");
}

TEST(Coordinator, RefusesMalformedAndOldMessages) {
  Team t;
  CoordinationMessage m = t.c[1].publish(1.0, t.pose[1], passing());
  EXPECT_TRUE(t.c[0].receive(m));
  CoordinationMessage bad = m;
  bad.attitude.pop_back();
  EXPECT_FALSE(t.c[0].receive(bad));
  bad = m;
  bad.time[0] = std::nan("");
  EXPECT_FALSE(t.c[0].receive(bad));
  bad = m;
  bad.intention = 99;
  EXPECT_FALSE(t.c[0].receive(bad));
  // An older message does not replace the newer one.
  CoordinationMessage old = m;
  old.seq = 0;
  old.stamp = 0.5;
  old.x = 42.0;
  EXPECT_TRUE(t.c[0].receive(old));
  t.c[0].publish(1.0, t.pose[0], passing());
  t.c[0].step(1.0);
  EXPECT_EQ(t.c[0].team_size(), 2u);
  // Leaving removes at once.
  CoordinationMessage bye = m;
  bye.leaving = true;
  EXPECT_TRUE(t.c[0].receive(bye));
  EXPECT_EQ(t.c[0].team_size(), 1u);
  EXPECT_EQ(t.c[0].drops(), 1u);
}

// robot1 (Defense in the worked example) hands Defense back at 0.15 s: it
// leaves it at once and, with the 5 s penalty, no robot's allocation gives
// it Defense again before 5.15 s; the three still agree every cycle; from
// 5.15 s on its published attitude for Defense is its own again.
TEST(Coordinator, HandBackMovesTheJobForThePenalty) {
  Team t;
  const std::vector<bool> all{true, true, true};
  t.cycle(0.0, all, passing());
  t.cycle(0.1, all, passing());
  ASSERT_EQ(t.job(0), "Defense");
  const int defense = t.c[0].set().find_slot("Defense");
  const double attitude = t.c[0].publish(0.12, t.pose[0], passing()).attitude[static_cast<std::size_t>(defense)];
  ASSERT_GT(attitude, 0.0);
  EXPECT_FALSE(t.c[0].hand_back("Nothing", 0.15));
  EXPECT_TRUE(t.c[0].hand_back("Defense", 0.15));
  EXPECT_EQ(t.c[0].own_slot(), -1);
  for (int k = 2; k <= 51; ++k) {  // 0.2 s .. 5.1 s
    t.cycle(0.1 * k, all, passing());
    EXPECT_NE(t.c[0].own_slot(), defense) << "at " << 0.1 * k << " s";
    EXPECT_EQ(t.c[0].last().slot, t.c[1].last().slot);
    EXPECT_EQ(t.c[1].last().slot, t.c[2].last().slot);
  }
  EXPECT_EQ(t.c[0].publish(5.14, t.pose[0], passing()).attitude[static_cast<std::size_t>(defense)], 0.0);
  EXPECT_EQ(t.c[0].publish(5.15, t.pose[0], passing()).attitude[static_cast<std::size_t>(defense)], attitude);
}

// robot1 lost robot3's last message (stamp 0.1 s), robot2 got it and says so
// in its next message: robot1 drops robot3 drop_timeout (1 s) after 0.1 s,
// like robot2, not after 0.0 s: kept at 1.05 s (0.95 s), dropped at 1.15 s.
TEST(Coordinator, GossipAlignsTheDrop) {
  Team t;
  const std::vector<bool> all{true, true, true};
  t.cycle(0.0, all, passing());
  const CoordinationMessage last3 = t.c[2].publish(0.1, t.pose[2], passing());
  t.c[1].receive(last3);  // lost on its way to robot1
  const CoordinationMessage from2 = t.c[1].publish(0.2, t.pose[1], passing());
  ASSERT_EQ(from2.heard.size(), 2u);
  t.c[0].receive(from2);
  t.c[0].receive(t.c[1].publish(1.0, t.pose[1], passing()));  // robot2 stays fresh
  t.c[0].step(1.05);
  EXPECT_EQ(t.c[0].team_size(), 3u);
  t.c[0].step(1.15);
  EXPECT_EQ(t.c[0].team_size(), 2u);
  // Gossip never brings back a dropped robot.
  t.c[0].receive(t.c[1].publish(1.2, t.pose[1], passing()));
  t.c[0].step(1.25);
  EXPECT_EQ(t.c[0].team_size(), 2u);
}
