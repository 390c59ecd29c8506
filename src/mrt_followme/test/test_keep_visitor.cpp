// FollowMe's combined rule base (config/brian/BrianConfigs.ini: Roby's
// files plus KeepVisitor) on hand-made crisp data: the robot guides towards
// a path point 5 m straight ahead, nothing near it, in Auto, and the visitor
// stands at various distances behind (or ahead of) it.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "mrt_brian/brian.h"

namespace {

using mrt::brian::Brian;
using mrt::brian::CommandList;
using mrt::brian::CrispDataList;

// Roby's data (units cm, degrees, mrt_roby/config/brian/shape_ctof.txt):
// Status 1 -> Auto 1; HaveGoal 1 -> HasGoal 1; GoalDistance 500 -> FAR 1
// (TOR 80 200), NEAR 0; GoalBearing 0 -> AHEAD 1, LEFT = RIGHT 0; every
// obstacle sector 500 -> CLOSE = DANGER 0 (ObstacleClose 0: AvoidObstacle
// is not active); FreeSide 0 -> LEFT = RIGHT 0; ManualMove needs Manual.
// Level 1: ReachPathPoint (CANDO = WANT = 1) proposes Speed FAST (55 cm/s)
// at 1 and Jog ZERO at 1: without KeepVisitor the robot drives at 55 cm/s.
CrispDataList guiding(double visitor_cm, double visitor_deg, double reliability = 1.0) {
  CrispDataList c = {{"Status", 1},          {"HaveGoal", 1},           {"GoalDistance", 500},
                     {"GoalBearing", 0},     {"ObstacleFront", 500},    {"ObstacleFrontLeft", 500},
                     {"ObstacleFrontRight", 500}, {"ObstacleLeft", 500}, {"ObstacleRight", 500},
                     {"ObstacleBack", 500},  {"FreeSide", 0},           {"RemoteSpeed", 0},
                     {"RemoteTurn", 0},      {"LastJog", 0}};
  c.push_back({"VisitorDistance", visitor_cm, reliability});
  c.push_back({"VisitorAngle", visitor_deg, reliability});
  return c;
}

double command(const CommandList& c, const std::string& name) {
  for (const auto& x : c)
    if (x.name == name) return x.value;
  ADD_FAILURE() << "no command " << name;
  return -1.0;
}

class KeepVisitorRules : public ::testing::Test {
 protected:
  void SetUp() override {
    mrt::brian::BrianOptions o;
    o.packages = mrt::common::package_finder({{"mrt_roby", MRT_ROBY_DIR}});  // Roby's rule base, by the build
    brian_ = Brian::from_path(std::string(MRT_FOLLOWME_CONFIG) + "/brian/BrianConfigs.ini", o);
  }
  double speed(const CrispDataList& c) { return command(brian_->run(c), "Speed"); }
  std::unique_ptr<Brian> brian_;
};

}  // namespace

TEST_F(KeepVisitorRules, TheCombinedBaseHasRobysBehavioursAndKeepVisitor) {
  ASSERT_EQ(brian_->engine().size(), 4);  // ReachPathPoint, ManualMove, AvoidObstacle, KeepVisitor
  EXPECT_EQ(brian_->engine().behavior(3).name(), "KeepVisitor");
  EXPECT_EQ(brian_->engine().behavior(3).level(), 3);
}

TEST_F(KeepVisitorRules, VisitorThreeMetresBehindIsSlowerThanOneMetreBehind) {
  // 1 m behind (100 cm, 180 deg): LAGGING = TOR(150, 220)(100) = 0, so
  // VisitorLaggingBehind = 0, KeepVisitor's CANDO 0: Speed FAST alone = 55.
  const double near = speed(guiding(100, 180));
  EXPECT_NEAR(near, 55.0, 1e-9);
  // 3 m behind: LAGGING 1, FAR = TOR(220, 280)(300) = 1, BEHIND_LEFT =
  // TOR(70, 110)(180) = 1 -> CANDO = WANT = 1. Before level 3 the proposals
  // give ProposedSpeed 55: FORWARD = TOR(1, 5) = 1, FAST = TOR(20, 35) = 1.
  // The slow-down rule reads NOT FAR = 0; the stop rule fires at 1: &DEL
  // removes the 55 and only STOP (0) is left -> 0 cm/s. The heading stays.
  const CommandList far = brian_->run(guiding(300, 180));
  EXPECT_NEAR(command(far, "Speed"), 0.0, 1e-9);
  EXPECT_NEAR(command(far, "Jog"), 0.0, 1e-9);
  EXPECT_LT(command(far, "Speed"), near);
}

TEST_F(KeepVisitorRules, SpeedFallsWithTheVisitorsDistanceBehind) {
  // 2 m behind, on the right (-170 deg: BEHIND_RIGHT = TOL(-110, -70) = 1):
  // LAGGING = (200 - 150) / 70 = 5/7, FAR 0. CANDO = WANT = 5/7 > 0.49.
  // Slow-down rule: min(5/7, NOT FAR 1, 1, FAST 1) = 5/7, weighted by WANT:
  // SLOW (20) at 25/49; no deletion, so FAST (55) at 1 stays:
  // (55 * 1 + 20 * 25/49) / (1 + 25/49) = 3195/74 = 43.176 cm/s.
  EXPECT_NEAR(speed(guiding(200, -170)), 3195.0 / 74.0, 1e-9);
  // 2.5 m behind: LAGGING 1, FAR = 30/60 = 0.5. Slow-down min(1, 0.5, 1, 1)
  // = 0.5 -> SLOW 0.5; stop rule 0.5 -> &DEL (the 55 goes), STOP 0.5:
  // (20 * 0.5 + 0 * 0.5) / 1 = 10 cm/s.
  EXPECT_NEAR(speed(guiding(250, 180)), 10.0, 1e-9);
  // 1.8 m: LAGGING = 30/70 = 0.43, below the CANDO threshold 0.49: 55.
  EXPECT_NEAR(speed(guiding(180, 180)), 55.0, 1e-9);
}

TEST_F(KeepVisitorRules, AVisitorAheadIsNeverWaitedFor) {
  // FollowVisitor drives towards the visitor: 3 m ahead (0 deg) is behind
  // neither way (BEHIND_LEFT = BEHIND_RIGHT = 0), KeepVisitor stays out.
  EXPECT_NEAR(speed(guiding(300, 0)), 55.0, 1e-9);
  // 3 m at 90 deg (to the left): BEHIND_LEFT = (90 - 70) / 40 = 0.5, so
  // VisitorLaggingBehind 0.5 > 0.49: the stop rule fires (0.5) and deletes.
  EXPECT_NEAR(speed(guiding(300, 90)), 0.0, 1e-9);
}

TEST_F(KeepVisitorRules, AnUnreliableTrackStillStopsTheRobot) {
  // MAP's reliability 0.3: every predicate <value, 0.3>; the stop rule fires
  // at 1 * 0.3 > 0 and &DEL is all or nothing: STOP alone -> 0 cm/s.
  EXPECT_NEAR(speed(guiding(300, 180, 0.3)), 0.0, 1e-9);
  // No visitor data at all (MAP has no track): KeepVisitor reads 0: 55.
  CrispDataList none = guiding(0, 0);
  none.resize(none.size() - 2);
  EXPECT_NEAR(speed(none), 55.0, 1e-9);
}
