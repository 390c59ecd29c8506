// A slot left vacant is filled: a silent teammate's slot in the cycle it
// is dropped, though the survivors' hysteresis favours staying put; and
// two robots moving the same way do not leave a slot to each other because
// each holds a message of its own newer than the other's (it publishes,
// steps, and hears this cycle's after its step): teammates' times to reach
// are brought to the allocation's time with the rate of their last two
// messages.
#include <gtest/gtest.h>

#include "mrt_scare/coordinator.h"

using namespace mrt::scare;

namespace {

// Slots: 0 Chase (the ball at (0, 0), priority 2, once A is high),
// 1 Positioning (0.1, up to 5). Attitude 1, 1 m/s.
const char* kYaml = R"Y(
fuzzy:
  shapes: "(UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))"
  data: "(A UNIT) (BallX UNIT) (BallY UNIT)"
activities:
  - {name: Chase, opportunity: (D A HIGH), priority: 2, target: [BallX, BallY]}
  - {name: Positioning, opportunity: 0.1, max: 5}
default_attitude: 1.0
options: {time_scale: 2.0, hysteresis: 0.15, min_opportunity: 0.05}
)Y";

/// Two robots on 0.125 s cycles (exact in binary), in the order of the
/// real nodes: each sends, steps on what it has heard so far, and this
/// cycle's messages arrive after the step.
struct Pipeline {
  std::vector<Coordinator> c;
  std::vector<CoordinationMessage> in_flight;
  Pipeline() {
    const ActivitySet s = parse_activities(kYaml, "chase.yaml");
    CoordinatorOptions o;
    o.listen = 0.0;
    for (const char* id : {"a", "b"}) c.emplace_back(s, s.robot_or_default(id), o);
  }
  void cycle(double t, const std::vector<Pose2D>& pose, bool ball) {
    const CrispMap w{{"A", {ball ? 1.0 : 0.0, 1.0}}, {"BallX", {0.0, 1.0}}, {"BallY", {0.0, 1.0}}};
    std::vector<CoordinationMessage> sent;
    for (std::size_t i = 0; i < c.size(); ++i) sent.push_back(c[i].publish(t, pose[i], w));
    for (auto& co : c) co.step(t);
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j)
        if (i != j) c[i].receive(sent[j]);
  }
  std::string job(std::size_t i) const {
    const int s = c[i].own_slot();
    return s < 0 ? "" : c[i].set().slot_name(c[i].set().slots()[static_cast<std::size_t>(s)]);
  }
};

// Slots: 0 Chase (the ball at (0, 0), priority 2), 1 Guard (target
// (1.6, 0)), 2 Positioning (0.1, up to 5); all opportune. Attitude 1 (c
// guards with 0.5), 1 m/s; utility = priority * attitude / (1 + time / 2),
// + 0.15 for the incumbent.
const char* kDropYaml = R"Y(
fuzzy:
  shapes: "(UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))"
  data: "(BallX UNIT) (BallY UNIT)"
activities:
  - {name: Chase, opportunity: 1.0, priority: 2, target: [BallX, BallY]}
  - {name: Guard, opportunity: 1.0, target: [1.6, 0.0]}
  - {name: Positioning, opportunity: 0.1, max: 5}
default_attitude: 1.0
options: {time_scale: 2.0, hysteresis: 0.15, min_opportunity: 0.05}
robots:
  - {id: c, attitude: {Guard: 0.5}}
)Y";

}  // namespace

TEST(DropOut, VacantSlotIsFilledAgainstTheSurvivorsHysteresis) {
  // d chases the ball from on top of it, a guards from the Guard spot 1.6 m
  // from the ball, c is 18 m away. d falls silent after t = 0.5.
  const ActivitySet s = parse_activities(kDropYaml, "drop.yaml");
  CoordinatorOptions o;
  o.listen = 0.0;
  std::vector<Coordinator> c;
  for (const char* id : {"a", "c", "d"}) c.emplace_back(s, s.robot_or_default(id), o);
  const std::vector<Pose2D> pose{{1.6, 0.0, 0}, {-18.0, 0.0, 0}, {0.0, 0.0, 0}};
  const CrispMap w{{"BallX", {0.0, 1.0}}, {"BallY", {0.0, 1.0}}};
  auto job = [&](std::size_t i) {
    const int sl = c[i].own_slot();
    return sl < 0 ? std::string() : c[i].set().slot_name(c[i].set().slots()[static_cast<std::size_t>(sl)]);
  };
  auto cycle = [&](double t, std::size_t n) {  // the first n robots talk
    std::vector<CoordinationMessage> m;
    for (std::size_t i = 0; i < n; ++i) m.push_back(c[i].publish(t, pose[i], w));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (i != j) c[i].receive(m[j]);
    for (std::size_t i = 0; i < n; ++i) c[i].step(t);
  };
  for (int k = 0; k <= 12; ++k) {
    const double t = 0.125 * k;
    cycle(t, t <= 0.5 ? 3 : 2);
    ASSERT_EQ(job(0), "Guard") << t;  // d, though fading, keeps Chase: 2 * 0.5 + 0.15 at 1.5
    ASSERT_EQ(job(1), "Positioning") << t;
  }
  EXPECT_EQ(job(2), "Chase");
  // At t = 1.625 d is dropped. Utilities: a Chase 2 / (1 + 1.6 / 2) =
  // 1.111, a Guard 1, c Chase 2 / (1 + 18 / 2) = 0.2, c Guard 0.5 / (1 +
  // 19.6 / 2) = 0.046, Positioning 0.1. With the survivors' hysteresis the
  // status quo (a Guard 1.15 + c Positioning 0.25 = 1.4) beat every way of
  // filling Chase (a Chase 1.111 + c Positioning 0.25 = 1.361; c Chase 0.2
  // + a Guard 1.15 = 1.35): the ball was left to nobody. In the drop cycle
  // Chase carries d's hysteresis: a Chase 1.261 + c Positioning 0.25 =
  // 1.511 beats the status quo 1.4 and c Chase 0.35 + a Guard 1.15 = 1.5.
  cycle(1.625, 2);
  EXPECT_EQ(c[0].team_size(), 2u);
  EXPECT_EQ(job(0), "Chase");
  EXPECT_EQ(job(1), "Positioning");
  // And it stays so with the hysteresis back: a Chase 1.261 + c 0.25 =
  // 1.511 against a Guard 1.0 + c 0.25 = 1.25.
  cycle(1.75, 2);
  EXPECT_EQ(job(0), "Chase");
  EXPECT_EQ(job(1), "Positioning");
}

TEST(MessageAge, RobotsMovingAwayDoNotLeaveTheSlotToEachOther) {
  // a at x = -(2 + t), b at x = 1.95 + t: both move away from the ball at
  // 1 m/s, b always 0.05 m nearer. Chase from t = 1: b's utility
  // 2 / (1 + (1.95 + t) / 2) beats a's by a margin that nothing else
  // decides, so both must give it to b. Unextrapolated, a saw b 0.125 m
  // nearer than b is and b saw a 0.125 - 0.05 = 0.075 m nearer than b
  // itself: each left Chase to the other, for as long as they moved.
  Pipeline p;
  for (int k = 0; k <= 24; ++k) {
    const double t = 0.125 * k;
    p.cycle(t, {{-(2.0 + t), 0.0, 0}, {1.95 + t, 0.0, 0}}, t >= 1.0);
    if (t < 1.0) continue;
    SCOPED_TRACE("t = " + std::to_string(t));
    EXPECT_EQ(p.c[0].last().slot, p.c[1].last().slot);  // the same allocation on both
    EXPECT_EQ(p.job(1), "Chase");
    EXPECT_EQ(p.job(0), "Positioning");
  }
}

TEST(MessageAge, ExtrapolationIsLimitedToTheGrace) {
  // b falls silent at t = 0.5 while nearing the ball at 1 m/s from 3 m;
  // a, still at 2.6 m, must not extrapolate b onto the ball: 0.5 s of b's
  // rate at most (the grace), so b is taken at 2.5 - 0.5 = 2.0 m, ahead of
  // a (2.6 m), until b's confidence falls (age > 0.5 s).
  Pipeline p;
  for (int k = 0; k <= 4; ++k) p.cycle(0.125 * k, {{-2.6, 0.0, 0}, {3.0 - 0.125 * k, 0.0, 0}}, false);
  const TeamInput at_grace = p.c[0].team_input(0.5 + 0.125 + 0.5);
  ASSERT_EQ(at_grace.robots.size(), 2u);
  EXPECT_NEAR(at_grace.robots[1].time[0], 2.5 - 0.5, 1e-9);  // message of 0.5, 0.625 s old: 0.5 s used
  EXPECT_NEAR(at_grace.robots[0].time[0], 2.6, 1e-9);        // its own: as measured
}
