// Tests of the match (match.h, a step hook of mrt_sim's Simulator): ball
// physics, kicker, ball handling, referee (goal, throw-in, restarts),
// scripted goalkeeper and defender.
// Every expected number is worked out by hand in the comment next to it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mrt_common/parse_error.h"
#include "mrt_robocup/match.h"

namespace mrt::robocup {
namespace {

using common::Point2D;
using sim::Mover;
using sim::parse_world;
using sim::RobotState;
using sim::Simulator;
using sim::World;

// A 18 x 12 m MSL field inside 20 x 14 m walls; the yellow goal (team 1
// defends it) at +x, the blue one (team 0, the world's robots) at -x; one
// IANUS3 (body radius 0.25 m) at `pose`.
World field(const std::string& ball, const std::string& pose = "[-2, 0, 0]") {
  const std::string yaml =
      "name: test_field\n"
      "bounds: [-10, -7, 10, 7]\n"
      "walls:\n  - [-10, -7, 10, -7]\n  - [10, -7, 10, 7]\n  - [10, 7, -10, 7]\n  - [-10, 7, -10, -7]\n"
      "goals:\n"
      "  - {name: yellow_goal, color: yellow, x: 9, y: 0, theta: 0, width: 2, depth: 0.5}\n"
      "  - {name: blue_goal, color: blue, x: -9, y: 0, theta: 180, width: 2, depth: 0.5}\n"
      "ball: " + ball + "\n"
      "robots:\n  - {name: r1, base: ianus3, pose: " + pose + "}\n";
  return parse_world(yaml, "test_field.yaml", "");
}

// No automatic kick-off: the referee stays stopped until told.
MatchConfig quiet() {
  MatchConfig c;
  c.referee.auto_start = false;
  c.referee.restart_delay = 0.5;
  return c;
}

struct Fixture {
  Simulator sim;
  Match match;
  std::vector<RefereeEvent> events;
  Fixture(World w, MatchConfig c) : sim(prepared(std::move(w), c)), match(c, sim) {}
  static World prepared(World w, const MatchConfig& c) {
    setup_match_world(c, w);
    return w;
  }
  void run(double seconds) {
    const long n = std::lround(seconds / sim.dt());
    for (long k = 0; k < n; ++k)
      for (const RefereeEvent& e : match.step()) events.push_back(e);
  }
  const RefereeEvent* find(RefereeCommand c) const {
    for (const RefereeEvent& e : events)
      if (e.command == c) return &e;
    return nullptr;
  }
};

TEST(Match, BallRollsToTheFrictionStoppingDistance) {
  // Constant deceleration a = 0.4 m/s^2 from v0 = 2 m/s: it stops after
  // v0 / a = 5 s, having rolled v0^2 / (2 a) = 4 / 0.8 = 5 m. The 1 ms
  // steps (speed reduced, then position advanced) roll
  // sum_{k=1..5000} (2 - 0.0004 k) * 0.001 = 10 - 0.0004*5000*5001/2*0.001
  // = 4.9990 m: from x = -5 it stops at -0.0010.
  Fixture f(field("{x: -5, y: 0, vx: 2, friction: 0.4}", "[0, 3, 0]"), quiet());
  f.run(4.9);
  EXPECT_GT(std::hypot(f.sim.ball().velocity.x, f.sim.ball().velocity.y), 0.03);  // 2 - 0.4*4.9 = 0.04
  f.run(1.1);
  EXPECT_NEAR(f.sim.ball().position.x, -0.0010, 2e-4);
  EXPECT_NEAR(f.sim.ball().position.y, 0.0, 1e-12);
  EXPECT_EQ(f.sim.ball().velocity.x, 0.0);
}

TEST(Match, BallBouncesOffAWallWithRestitution) {
  // No friction, 2 m/s into the wall x = 10 (well clear of the goal at
  // |y| <= 1): it comes back at restitution * 2 = 0.6 * 2 = 1.2 m/s.
  Fixture f(field("{x: 9.5, y: 4, vx: 2, friction: 0, restitution: 0.6}"), quiet());
  f.run(0.5);
  EXPECT_NEAR(f.sim.ball().velocity.x, -1.2, 1e-9);
  EXPECT_NEAR(f.sim.ball().velocity.y, 0.0, 1e-12);
  EXPECT_LE(f.sim.ball().position.x, 10 - 0.11 + 1e-9);
}

TEST(Match, BallBouncesOffARobot) {
  // A ball at 2 m/s into a robot at rest, restitution against bodies 0.3:
  // it leaves at 0.3 * 2 = 0.6 m/s (not the 0.05 m/s of a bare push).
  MatchConfig c = quiet();
  c.ball_robot_restitution = 0.3;
  Fixture f(field("{x: -1, y: 0, vx: 2, friction: 0}", "[0, 0, 0]"), c);
  f.run(0.6);
  EXPECT_NEAR(f.sim.ball().velocity.x, -0.6, 1e-9);
  EXPECT_NEAR(f.sim.ball().velocity.y, 0.0, 1e-9);
}

TEST(Match, KickGivesTheSetSpeedAlongTheHeading) {
  // Robot at the origin facing 30 deg, ball touching its front at
  // 0.36 m (0.25 + 0.11): (0.31177, 0.18). Strength 0.5 of 8 m/s = 4 m/s
  // along 30 deg: (4 cos 30, 4 sin 30) = (3.4641, 2.0).
  const double th = M_PI / 6;
  Fixture f(field("{x: 0.31177, y: 0.18, friction: 0.4}", "[0, 0, 30]"), quiet());
  ASSERT_TRUE(f.match.in_reach(0));
  f.match.kick(0, 0.5);
  f.match.step();
  EXPECT_NEAR(f.sim.ball().velocity.x, 4 * std::cos(th), 1e-9);
  EXPECT_NEAR(f.sim.ball().velocity.y, 4 * std::sin(th), 1e-9);
  EXPECT_NEAR(f.sim.ball().velocity.x, 3.4641, 1e-4);
  EXPECT_EQ(f.match.kicks(), 1);
  EXPECT_EQ(f.match.last_touch(), 0);
  // Out of reach (ball 1 m away): the kicker fires in the air.
  f.sim.ball().position = {1.0, 0.0};
  f.sim.ball().velocity = {0.0, 0.0};
  f.match.kick(0, 1.0);
  f.match.step();
  EXPECT_EQ(f.match.kicks(), 1);
  EXPECT_EQ(f.sim.ball().velocity.x, 0.0);
}

TEST(Match, DribbledBallStaysAtTheKickerWithinTheLimits) {
  // Dribbler on, 1 m/s and 0.5 rad/s (limits 1.5 m/s, 2 rad/s): after 2 s
  // the robot has turned 1 rad and the ball is still 0.36 m ahead of it.
  Fixture f(field("{x: 0.36, y: 0, friction: 0.4}", "[0, 0, 0]"), quiet());
  f.match.set_dribbler(0, true);
  f.sim.set_twist(0, {1.0, 0.0, 0.5});
  int held = 0;
  for (int k = 0; k < 2000; ++k) {
    f.match.step();
    held += f.match.holder() == 0;
  }
  EXPECT_EQ(held, 2000);
  const RobotState& r = f.sim.robots()[0];
  EXPECT_NEAR(r.pose.theta, 1.0, 1e-6);
  EXPECT_NEAR(f.sim.ball().position.x, r.pose.x + 0.36 * std::cos(1.0), 1e-9);
  EXPECT_NEAR(f.sim.ball().position.y, r.pose.y + 0.36 * std::sin(1.0), 1e-9);
  // Turning at 4 rad/s (> 2) in place: the ball is lost and rolls on
  // ahead at about the 1 m/s it had, while the kicker swings away: after
  // 0.5 s it is far (> 0.1 m) from the kicker.
  f.sim.set_twist(0, {0.0, 0.0, 4.0});
  f.run(0.5);
  EXPECT_EQ(f.match.holder(), -1);
  const Point2D kicker{r.pose.x + 0.36 * std::cos(r.pose.theta), r.pose.y + 0.36 * std::sin(r.pose.theta)};
  EXPECT_GT(std::hypot(f.sim.ball().position.x - kicker.x, f.sim.ball().position.y - kicker.y), 0.1);
}

TEST(Match, BallHandlerLetsGoWithoutARepeatedOn) {
  // dribble_timeout 0.5 s, dt 1 ms, the robot still with the ball at its
  // kicker: held while the on is repeated every 0.1 s (1 s), then, without
  // a repeat, for 0.5 s after the last on and not after: steps 1..500
  // after it hold, from step 501 on the handler is off (one timeout).
  MatchConfig c = quiet();
  c.kicker.dribble_timeout = 0.5;
  Fixture f(field("{x: 0.36, y: 0, friction: 0.4}", "[0, 0, 0]"), c);
  for (int k = 0; k < 1000; ++k) {
    if (k % 100 == 0) f.match.set_dribbler(0, true);
    f.match.step();
    ASSERT_EQ(f.match.holder(), 0) << k;
  }
  f.match.set_dribbler(0, true);  // at t = 1.0 s
  int held = 0;
  for (int k = 0; k < 1000; ++k) {
    f.match.step();
    held += f.match.holder() == 0;
  }
  EXPECT_EQ(held, 500);
  EXPECT_EQ(f.match.dribble_timeouts(), 1);
}

TEST(Match, GoalBetweenThePostsScoresAndRestartsWithAKickOff) {
  // Automatic kick-off for team 0 at t = 1 ms, start 0.5 s later.
  MatchConfig c = quiet();
  c.referee.auto_start = true;
  Fixture f(field("{x: 0, y: 0, friction: 0.4}"), c);
  f.run(0.6);
  ASSERT_NE(f.find(RefereeCommand::kKickOff), nullptr);
  EXPECT_EQ(f.find(RefereeCommand::kKickOff)->team, 0);
  ASSERT_NE(f.find(RefereeCommand::kStart), nullptr);
  ASSERT_EQ(f.match.state(), Match::State::kPlaying);
  // A shot at 3 m/s from (8, 0.5): the whole ball is past the yellow
  // goal line (x > 9 + 0.11) with |y| = 0.5 < 1 (the posts): goal for
  // team 0 (cyan), 1-0; then kick-off for team 1 at the centre.
  f.events.clear();
  f.sim.ball().position = {8.0, 0.5};
  f.sim.ball().velocity = {3.0, 0.0};
  f.run(0.6);
  const RefereeEvent* g = f.find(RefereeCommand::kGoal);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->team, 0);
  EXPECT_EQ(g->score[0], 1);
  EXPECT_EQ(g->score[1], 0);
  EXPECT_GT(g->position.x, 9.11);
  ASSERT_NE(f.find(RefereeCommand::kStop), nullptr);
  EXPECT_EQ(f.match.state(), Match::State::kStopped);
  f.run(0.6);
  const RefereeEvent* k = f.find(RefereeCommand::kKickOff);
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->team, 1);
  EXPECT_NEAR(f.sim.ball().position.x, 0.0, 1e-12);
  f.run(0.5);
  EXPECT_NE(f.find(RefereeCommand::kStart), nullptr);
  // Wide of the posts (y = 3): no goal, a goal kick for the defenders.
  f.events.clear();
  f.sim.ball().position = {8.0, 3.0};
  f.sim.ball().velocity = {3.0, 0.0};
  f.run(1.2);
  EXPECT_EQ(f.find(RefereeCommand::kGoal), nullptr);
  ASSERT_NE(f.find(RefereeCommand::kGoalKick), nullptr);
  EXPECT_EQ(f.find(RefereeCommand::kGoalKick)->team, 1);
  EXPECT_EQ(f.match.score()[0], 1);
}

// A throw-in for `team` announced at `spot`, where the ball now lies.
void expect_throw_in(const Fixture& f, int team, const Point2D& spot) {
  const RefereeEvent* t = f.find(RefereeCommand::kThrowIn);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->team, team);
  EXPECT_NEAR(t->position.x, spot.x, 1e-9);
  EXPECT_NEAR(t->position.y, spot.y, 1e-9);
  EXPECT_NEAR(f.sim.world().ball.position.x, spot.x, 1e-9);
  EXPECT_NEAR(f.sim.world().ball.position.y, spot.y, 1e-9);
}

TEST(Match, BallOverTheTouchLineGivesAThrowIn) {
  // The robot at (2, 5) facing +y kicks at 0.25 * 8 = 2 m/s: the ball
  // crosses y = 6 + 0.11 at x = 2. Last touch team 0: throw-in for team 1
  // at (2, 6) on the touch line, 0.5 s after the stop.
  MatchConfig c = quiet();
  Fixture f(field("{x: 2, y: 5.36, friction: 0.4}", "[2, 5, 90]"), c);
  f.match.command(RefereeCommand::kStart);
  f.match.kick(0, 0.25);
  f.run(1.0);
  ASSERT_NE(f.find(RefereeCommand::kStop), nullptr);
  expect_throw_in(f, 1, {2.0, 6.0});
  EXPECT_EQ(f.sim.ball().velocity.y, 0.0);
}

TEST(Match, ThrowInSpotUnderARobotMovesToTheNearestFreePoint) {
  // The robot at (2, 5.8) touches the ball at (2, 6.16) (0.36 m = 0.25 +
  // 0.11), which is over the touch line (6.16 > 6 + 0.11): throw-in for
  // team 1 at (2, 6), 0.2 m from the robot's centre, inside its body. The
  // referee puts the ball on the nearest point of the field (y <= 6) at
  // least 0.25 + 0.11 + 0.05 = 0.41 m from it, on rings 5 cm apart: along
  // the line, r^2 + 0.2^2 >= 0.41^2 needs r >= 0.358, so r = 0.40 and the
  // first direction (+x): (2.40, 6). Seen in the bringup before: the ball
  // put inside the robot was pushed out at once, throw-in after throw-in.
  MatchConfig c = quiet();
  Fixture f(field("{x: 2, y: 6.16, friction: 0.4}", "[2, 5.8, 90]"), c);
  f.match.command(RefereeCommand::kStart);
  f.run(0.6);
  expect_throw_in(f, 1, {2.40, 6.0});
  // Play restarts 0.5 s later and the ball stays in.
  f.events.clear();
  f.run(1.0);
  EXPECT_NE(f.find(RefereeCommand::kStart), nullptr);
  EXPECT_EQ(f.find(RefereeCommand::kStop), nullptr);
  EXPECT_EQ(f.match.state(), Match::State::kPlaying);
}

TEST(Match, GoalkeeperStaysBetweenBallAndGoalCentre) {
  // Yellow goal mouth g = (9, 0). Ball still at (5, 3): direction to it
  // (-4, 3) / 5, so the keeper (1 m from g) stands at (8.2, 0.6) and the
  // defender (2 m from the ball towards g) at (5, 3) + 2 (4, -3) / 5 =
  // (6.6, 1.8). Then ball at (6, -4): direction (-3, -4) / 5, keeper at
  // (8.4, -0.8).
  MatchConfig c = quiet();
  c.keeper_distance = 1.0;
  c.defender_distance = 2.0;
  c.opponents = {{"keeper", "goalkeeper", {8.4, 0.0}, 0.25, 1.5}, {"back", "defender", {4.0, 0.0}, 0.25, 1.5}};
  Fixture f(field("{x: 5, y: 3, friction: 0.4}"), c);
  f.match.command(RefereeCommand::kStart);
  f.run(3.0);
  const Mover& keeper = f.sim.world().movers[0];
  const Mover& back = f.sim.world().movers[1];
  EXPECT_NEAR(keeper.position.x, 8.2, 1e-6);
  EXPECT_NEAR(keeper.position.y, 0.6, 1e-6);
  EXPECT_NEAR(back.position.x, 6.6, 1e-6);
  EXPECT_NEAR(back.position.y, 1.8, 1e-6);
  f.sim.ball().position = {6.0, -4.0};
  f.run(2.0);
  EXPECT_NEAR(keeper.position.x, 8.4, 1e-6);
  EXPECT_NEAR(keeper.position.y, -0.8, 1e-6);
  // On the segment from g to the ball: zero cross product.
  const double cross = (keeper.position.x - 9) * (-4 - 0) - (keeper.position.y - 0) * (6 - 9);
  EXPECT_NEAR(cross, 0.0, 1e-5);
}

TEST(Match, ScriptedAttackerScoresOnAnEmptyGoal) {
  // Kick-off at t = 0, start at 2 s. The attacker (home (1.5, 2), 1 m/s)
  // walks to the point behind the ball on the line from the blue goal
  // (-9, 0): (0.38, 0), 2.29 m away, reached at about 4.3 s, with the
  // ball 0.38 m < 0.41 m away: it shoots at 5 m/s towards (-9, 0). The ball
  // is past x = -9.11 after 9.11 m: speed sqrt(25 - 0.8 * 9.11) = 4.2 m/s,
  // about 2 s later. Goal for magenta, 0-1, before 8 s; never before 4 s.
  MatchConfig c = quiet();
  c.referee.auto_start = true;
  c.referee.restart_delay = 2.0;
  c.referee.kickoff_team = 1;  // theirs: no waiting
  c.opponents = {{"forward", "attacker", {1.5, 2.0}, 0.25, 1.0}};
  Fixture f(field("{x: 0, y: 0, friction: 0.4}", "[-2, 5, 0]"), c);
  f.run(4.0);
  EXPECT_EQ(f.find(RefereeCommand::kGoal), nullptr);
  f.run(4.0);
  const RefereeEvent* g = f.find(RefereeCommand::kGoal);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->team, 1);
  EXPECT_EQ(g->score[1], 1);
  EXPECT_LT(g->position.x, -9.11);
  EXPECT_GT(g->time, 5.5);
  EXPECT_EQ(f.match.last_touch(), 1);
}

TEST(Match, OpponentsLeaveTheKickOffToTheKickingTeam) {
  // Kick-off for team 0 (cyan) at t = 0, start at 2 s: the attacker stays
  // at its home (1.5, 2) until 2 + restart_wait 5 = 7 s, then goes for the
  // ball (the behind point (0.38, 0) is 2.29 m away: 2.29 s at 1 m/s) and
  // scores about 2 s after that: no goal before 7 s, a goal before 13 s.
  MatchConfig c = quiet();
  c.referee.auto_start = true;
  c.referee.restart_delay = 2.0;
  c.opponents = {{"forward", "attacker", {1.5, 2.0}, 0.25, 1.0}};
  Fixture f(field("{x: 0, y: 0, friction: 0.4}", "[-2, 5, 0]"), c);
  f.run(6.9);
  EXPECT_NEAR(f.sim.world().movers[0].position.x, 1.5, 1e-12);
  EXPECT_NEAR(f.sim.world().movers[0].position.y, 2.0, 1e-12);
  EXPECT_EQ(f.find(RefereeCommand::kGoal), nullptr);
  f.run(6.0);
  const RefereeEvent* g = f.find(RefereeCommand::kGoal);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->team, 1);
  EXPECT_GT(g->time, 9.0);
}

TEST(Match, OperatorStopAndStart) {
  Fixture f(field("{x: 0, y: 0}"), quiet());
  EXPECT_EQ(f.match.state(), Match::State::kStopped);
  f.match.command(RefereeCommand::kStart);
  f.run(0.01);
  ASSERT_NE(f.find(RefereeCommand::kStart), nullptr);
  EXPECT_EQ(f.match.state(), Match::State::kPlaying);
  f.match.command(RefereeCommand::kStop);
  f.run(0.01);
  ASSERT_NE(f.find(RefereeCommand::kStop), nullptr);
  EXPECT_EQ(f.match.state(), Match::State::kStopped);
  // A drop ball: placed where the ball is, then start after 0.5 s.
  f.events.clear();
  f.match.command(RefereeCommand::kDropBall);
  f.run(0.6);
  ASSERT_NE(f.find(RefereeCommand::kDropBall), nullptr);
  EXPECT_NE(f.find(RefereeCommand::kStart), nullptr);
}

TEST(Match, CommandNamesAndMatchFile) {
  EXPECT_EQ(referee_command_from_string("drop_ball"), RefereeCommand::kDropBall);
  EXPECT_STREQ(to_string(RefereeCommand::kThrowIn), "throw_in");
  EXPECT_THROW(referee_command_from_string("penalty"), std::invalid_argument);
  const MatchConfig c = parse_match_config(
      "kicker: {max_speed: 6, half_angle: 30}\nopponents:\n  - {name: k, role: goalkeeper, x: 8, y: 0}\n", "m.yaml");
  EXPECT_EQ(c.kicker.max_speed, 6.0);
  EXPECT_NEAR(c.kicker.half_angle, M_PI / 6, 1e-12);
  ASSERT_EQ(c.opponents.size(), 1u);
  EXPECT_EQ(c.opponents[0].role, "goalkeeper");
  try {
    parse_match_config("opponents:\n  - {name: k, role: striker, x: 8, y: 0}\n", "m.yaml");
    FAIL() << "no error";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("m.yaml:2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mrt::robocup
