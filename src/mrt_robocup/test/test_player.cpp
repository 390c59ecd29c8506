// The player's crisp data, its referee gate and its behaviours on the
// differential and omni rule bases (config/brian). Expected numbers are
// worked out by hand in the comments from the shapes (common/shape_ctof.txt)
// and the singletons (*/s_shape.txt).
#include <gtest/gtest.h>

#include <limits>

#include <cmath>
#include <string>
#include <vector>

#include "mrt_robocup/coordination.h"
#include "mrt_robocup/player.h"

namespace mrt::robocup {
namespace {

const std::string kConfig = MRT_ROBOCUP_CONFIG;

double crisp(const brian::CrispDataList& c, const std::string& name, double* rel = nullptr) {
  for (const auto& d : c)
    if (d.name == name) {
      if (rel) *rel = d.reliability;
      return d.value;
    }
  ADD_FAILURE() << "no crisp datum " << name;
  return NAN;
}

PlayerOptions options(const std::string& kinematics) {
  PlayerOptions o;
  o.kinematics = kinematics;
  o.rule_base = kConfig + "/brian/" + kinematics + "/BrianConfigs.ini";
  o.max_speed = 1.5;  // above FAST (1.2 m/s): the rules' numbers come through
  return o;
}

PlayerInput ball_ahead(double bx, double by) {
  PlayerInput in;
  in.time = 1.0;
  in.pose_valid = true;
  in.pose = Pose2D(0.0, 0.0, 0.0);
  in.anchors.push_back({"Ball", bx, by, 0.0, 0.0, 1.0});
  in.coordination["ScareJob_BringBall"] = {1.0, 1.0};
  in.referee = Referee::kStart;
  return in;
}

TEST(Situation, CrispUnitsAndCoordination) {
  SituationAssessor a;
  SituationInput in;
  in.pose = Pose2D(1.0, 1.0, common::kPi / 2);  // facing +y
  in.anchors.push_back({"Ball", 1.0, 3.0, 0, 0, 0.8});
  in.anchors.push_back({"Opponent", 3.0, 1.0, 0, 0, 1.0});
  in.coordination["ScareRole_PassageToMate_passer"] = {1.0, 1.0};
  in.coordination["ScareMate_receiver_X"] = {1.0, 1.0};
  in.coordination["ScareMate_receiver_Y"] = {-1.0, 1.0};
  const Situation s = a.assess(in);
  EXPECT_EQ(s.job, "PassageToMate.passer");
  const auto c = a.crisp(s, in.pose, in.coordination);
  double rel = 0.0;
  // Ball 2 m straight ahead: 2000 mm, 0 deg, reliability 0.8.
  EXPECT_NEAR(crisp(c, "BallDistance", &rel), 2000.0, 1e-6);
  EXPECT_DOUBLE_EQ(rel, 0.8);
  EXPECT_NEAR(crisp(c, "BallAngle"), 0.0, 1e-9);
  // Opponent 2 m to the right (-90 deg); the gap is 2000 - 2 * 250 = 1500 mm.
  EXPECT_NEAR(crisp(c, "ObstacleDistance"), 1500.0, 1e-6);
  EXPECT_NEAR(crisp(c, "ObstacleAngle"), -90.0, 1e-9);
  // The receiver at (1, -1): 2 m behind, 180 deg.
  EXPECT_NEAR(crisp(c, "MateDistance"), 2000.0, 1e-6);
  EXPECT_NEAR(std::abs(crisp(c, "MateAngle")), 180.0, 1e-9);
  EXPECT_EQ(crisp(c, "RolePasser"), 1.0);
  EXPECT_EQ(crisp(c, "JobBringBall"), 0.0);
  // Own goal (-9, 0) from (1, 1) facing +y: atan2(-1, -10) = -174.29 deg
  // world, -264.29 relative = 95.71 deg; distance sqrt(101) m.
  EXPECT_NEAR(crisp(c, "OwnGoalAngle"), 95.7106, 1e-3);
  EXPECT_NEAR(crisp(c, "OwnGoalDistance"), 1000.0 * std::sqrt(101.0), 1e-6);
  // No kicker sensor: the ball 2 m away is not owned.
  EXPECT_EQ(crisp(c, "BallOwned"), 0.0);
}

TEST(Situation, AreaTimeCounts) {
  SituationAssessor a;
  SituationInput in;
  in.pose = Pose2D(7.5, 0.0, 0.0);  // inside the area (x >= 9 - 2.25)
  in.time = 10.0;
  EXPECT_DOUBLE_EQ(a.assess(in).area_time, 0.0);
  in.time = 13.5;
  EXPECT_DOUBLE_EQ(a.assess(in).area_time, 3.5);
  in.pose = Pose2D(6.0, 0.0, 0.0);  // out: reset
  EXPECT_DOUBLE_EQ(a.assess(in).area_time, 0.0);
}

TEST(Coordination, FromTeamMessages) {
  std::map<std::string, TeamEntry> team;
  team["robot1"] = {"PassageToMate.passer", 0.0, 0.0, 5.0};
  team["robot2"] = {"PassageToMate.receiver", 3.0, -2.0, 5.0};
  team["robot3"] = {"Defense", -7.0, 0.0, 5.0};
  Parameters p = coordination_from_team("robot1", team, 5.5, 1.0);
  EXPECT_EQ(job_of(p), "PassageToMate.passer");
  EXPECT_EQ(p["ScareMate_receiver_X"].value, 3.0);
  EXPECT_EQ(p["ScareMate_receiver_Y"].value, -2.0);
  EXPECT_EQ(job_of(coordination_from_team("robot3", team, 5.5, 1.0)), "Defense");
  EXPECT_TRUE(coordination_from_team("robot3", team, 6.5, 1.0).empty());  // stale
}

// Ball 3 m straight ahead, job BringBall: GoToBall alone (CANDO BallFree 1,
// WANT Attacker 1): BallFar 1 -> Speed FAST 120 cm/s, BallAhead 1 -> Jog 0.
TEST(Player, DifferentialGoesToTheBall) {
  Player p(options("differential"));
  const PlayerOutput out = p.cycle(ball_ahead(3.0, 0.0));
  EXPECT_FALSE(out.halted);
  EXPECT_NEAR(out.twist.vx, 1.2, 1e-6);
  EXPECT_NEAR(out.twist.omega, 0.0, 1e-6);
  EXPECT_FALSE(out.kick);
}

// Ball at 3 m, 15 deg left: LEFT 15/60 = 0.25, AHEAD 1 - 15/30 = 0.5 ->
// Jog (0.25 * 150 + 0.5 * 0) / 0.75 = 50 deg/s = 0.8727 rad/s.
TEST(Player, DifferentialTurnsProportionally) {
  Player p(options("differential"));
  const double a = common::deg_to_rad(15.0);
  const PlayerOutput out = p.cycle(ball_ahead(3.0 * std::cos(a), 3.0 * std::sin(a)));
  EXPECT_NEAR(out.twist.omega, common::deg_to_rad(50.0), 1e-6);
}

// Referee stop with the same inputs: zero twist, no kick, no ball handler.
TEST(Player, RefereeStopHaltsWhateverTheRules) {
  Player p(options("differential"));
  PlayerInput in = ball_ahead(3.0, 0.0);
  in.referee = Referee::kStop;
  const PlayerOutput out = p.cycle(in);
  EXPECT_TRUE(out.halted);
  EXPECT_EQ(out.twist.vx, 0.0);
  EXPECT_EQ(out.twist.omega, 0.0);
  EXPECT_FALSE(out.kick);
  in.referee = Referee::kKickOff;  // placement before the start: still halted
  EXPECT_TRUE(p.cycle(in).halted);
  in.referee = Referee::kStart;
  in.pose_valid = false;           // no pose: halted too
  EXPECT_TRUE(p.cycle(in).halted);
}

// The robot at (6, 0.85) facing +x, the ball at its kicker (6.36, 0.85)
// and held (the kicker sensor says so).
PlayerInput ball_held_at_shot() {
  PlayerInput in = ball_ahead(6.36, 0.85);
  in.pose = Pose2D(6.0, 0.85, 0.0);
  in.possession_known = true;
  in.possession = true;
  return in;
}

// Ball held (kicker sensor) at (6, 0.85) facing +x, nobody around: the aim
// is (9, 0.85) (aim_offset 0.85 m, robot on the +y side), 3 m away:
// SHOOTING 1 (below 3000 mm), NARROW 1, ShotClear -> KickToGoal: Kick HARD
// = strength 1.
TEST(Player, KicksWhenTheShotIsClear) {
  for (const char* k : {"differential", "omni"}) {
    Player p(options(k));
    PlayerInput in = ball_held_at_shot();
    const PlayerOutput out = p.cycle(in);
    EXPECT_TRUE(out.kick) << k;
    EXPECT_DOUBLE_EQ(out.kick_strength, 1.0) << k;
    // A second kick within the cooldown (0.5 s) is refused.
    in.time += 0.1;
    EXPECT_FALSE(p.cycle(in).kick) << k;
  }
}

// The same clear shot while the odometry says the robot turns: 0.5 rad/s
// (above kick_max_omega 0.1) holds the kick; once it turns at 0.1 rad/s or
// less, or the turn rate is unknown (NaN), it kicks. Turning right (-0.5)
// holds it too. While the kick is held the turn is stopped (omega 0), so
// the robot settles instead of swinging through the aim.
TEST(Player, NoKickWhileTurning) {
  Player p(options("differential"));
  PlayerInput in = ball_held_at_shot();
  for (double w : {0.5, -0.5, 0.11}) {
    in.omega = w;
    const PlayerOutput out = p.cycle(in);
    EXPECT_FALSE(out.kick) << w;
    EXPECT_TRUE(out.kick_held) << w;
    EXPECT_EQ(out.twist.omega, 0.0) << w;  // it stops turning to settle the aim
  }
  in.omega = -0.1;
  PlayerOutput out = p.cycle(in);
  EXPECT_TRUE(out.kick);
  EXPECT_FALSE(out.kick_held);
  Player q(options("differential"));
  in.omega = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(q.cycle(in).kick);
}

// An opponent on the shot line: no kick.
TEST(Player, NoKickWhenBlocked) {
  Player p(options("differential"));
  PlayerInput in = ball_held_at_shot();
  in.anchors.push_back({"Opponent", 7.5, 0.85, 0, 0, 1.0});
  EXPECT_FALSE(p.cycle(in).kick);
}

// Omni, ball 3 m ahead: SpeedModule FAST 120 cm/s, SpeedAngle 0 -> vx 1.2.
TEST(Player, OmniGoesToTheBall) {
  Player p(options("omni"));
  const PlayerOutput out = p.cycle(ball_ahead(3.0, 0.0));
  EXPECT_NEAR(out.twist.vx, 1.2, 1e-6);
  EXPECT_NEAR(out.twist.vy, 0.0, 1e-6);
}

TEST(Player, BadKinematicsIsRefused) {
  PlayerOptions o = options("differential");
  o.kinematics = "legged";
  EXPECT_THROW(Player{o}, std::invalid_argument);
}

}  // namespace
}  // namespace mrt::robocup

namespace mrt::robocup {
namespace {

// The ball held at kick-off, 9.2 m from the goal, job RecoverWanderingBall:
// out of range (SHOOTING 0 beyond 4000 mm) and ClearBall not wanted (a
// ball job): no kick, CarryBallToGoal carries it (Speed MEDIUM 80 cm/s
// with the goal ahead).
TEST(Player, NoKickFromFarAway) {
  Player p(options("differential"));
  PlayerInput in = ball_ahead(0.16, 0.0);
  in.pose = Pose2D(-0.2, 0.0, 0.0);
  in.coordination.clear();
  in.coordination["ScareJob_RecoverWanderingBall"] = {1.0, 1.0};
  in.possession_known = true;
  in.possession = true;
  const PlayerOutput out = p.cycle(in);
  EXPECT_FALSE(out.kick) << out.behaviors;
  EXPECT_NEAR(out.twist.vx, 0.8, 1e-6) << out.behaviors;
}

}  // namespace
}  // namespace mrt::robocup

namespace mrt::robocup {
namespace {

// The shot (doc/shooting.md), keeper at (8.4, 0), field defaults (goal at
// x = 9, aim_offset 0.85 m, spot 3.3 m out and 1.3 m aside, hysteresis
// 0.25 m, keeper_clearance 0.65 m, shot_clearance 0.45 m).
TEST(Situation, ShotAtTheNearPostClearOfTheKeeper) {
  const SituationOptions o;
  const std::vector<Point2D> keeper{{8.4, 0.0}};
  // From (5.4, 0.85), first shot: the +y side; the line y = 0.85 passes
  // 0.85 m from the keeper: clear.
  Shot s = plan_shot({5.4, 0.85}, keeper, 0.0, o);
  EXPECT_EQ(s.side, 1.0);
  EXPECT_NEAR(s.aim.y, 0.85, 1e-12);
  EXPECT_NEAR(s.spot.x, 5.7, 1e-12);
  EXPECT_NEAR(s.spot.y, 1.3, 1e-12);
  EXPECT_NEAR(s.keeper_clearance, 0.85, 1e-9);
  EXPECT_TRUE(s.clear);
  // From (6.4, -0.2), last side +1: -0.2 m is within the hysteresis, the
  // aim stays at (9, 0.85); line direction (2.6, 1.05), keeper offset
  // (2.0, 0.2): |2.0 * 1.05 - 0.2 * 2.6| / sqrt(2.6^2 + 1.05^2)
  // = 1.58 / 2.80401 = 0.56348 m: beyond shot_clearance, short of the
  // keeper's 0.65 m: not clear.
  s = plan_shot({6.4, -0.2}, keeper, 1.0, o);
  EXPECT_EQ(s.side, 1.0);
  EXPECT_NEAR(s.keeper_clearance, 0.56348, 1e-5);
  EXPECT_FALSE(s.clear);
  // From (5.4, -0.5): beyond the hysteresis, the -y side; direction
  // (3.6, -0.35), offset (3.0, 0.5): |3.0 * -0.35 - 0.5 * 3.6| /
  // sqrt(3.6^2 + 0.35^2) = 2.85 / 3.61697 = 0.78795 m: clear.
  s = plan_shot({5.4, -0.5}, keeper, 1.0, o);
  EXPECT_EQ(s.side, -1.0);
  EXPECT_NEAR(s.aim.y, -0.85, 1e-12);
  EXPECT_NEAR(s.spot.y, -1.3, 1e-12);
  EXPECT_NEAR(s.keeper_clearance, 0.78795, 1e-5);
  EXPECT_TRUE(s.clear);
}

// From (0, 0) facing +x, no keeper: the +y side; the shooting spot
// (5.7, 1.3) is sqrt(5.7^2 + 1.3^2) = 5846.37 mm away at
// atan2(1.3, 5.7) = 12.8477 deg.
TEST(Situation, ShootingSpotCrisp) {
  SituationAssessor a;
  SituationInput in;
  in.pose = Pose2D(0.0, 0.0, 0.0);
  const Situation s = a.assess(in);
  const auto c = a.crisp(s, in.pose, in.coordination);
  EXPECT_NEAR(crisp(c, "SpotDistance"), 5846.37, 0.01);
  EXPECT_NEAR(crisp(c, "SpotAngle"), 12.8477, 1e-4);
}

// The ball held at (6, 0.85), heading 0.03 rad: the aim (9, 0.85) is
// 1.71887 deg to the right, NARROW 1 - 1.71887 / 2 = 0.14 < 0.49: no kick.
// CarryBallToGoal: ShotPosition 1 (ShotClear, SHOOTING 1 at 3 m) -> Speed
// ZERO; AimRight = RIGHT 1.71887 / 60 = 0.028648, AimAhead = 1 - 1.71887 /
// 30 = 0.942704 -> Jog -150 * 0.028648 / 0.971352 = -4.42394 deg/s.
TEST(Player, NoKickUntilAimedWithinOneDegree) {
  Player p(options("differential"));
  PlayerInput in = ball_ahead(6.0 + 0.36 * std::cos(0.03), 0.85 + 0.36 * std::sin(0.03));
  in.pose = Pose2D(6.0, 0.85, 0.03);
  in.possession_known = true;
  in.possession = true;
  const PlayerOutput out = p.cycle(in);
  EXPECT_FALSE(out.kick) << out.behaviors;
  EXPECT_NEAR(out.twist.vx, 0.0, 1e-9) << out.behaviors;
  EXPECT_NEAR(out.twist.omega, common::deg_to_rad(-4.42394), 1e-6) << out.behaviors;
}

}  // namespace
}  // namespace mrt::robocup
