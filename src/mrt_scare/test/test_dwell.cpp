// The dwell (options.dwell): a robot that took its slot less than `dwell`
// ago keeps it against a better robot (and while its activity is still
// opportune at all), but never against cardinality, coverage or a drop-out. Hand-worked numbers in the comments
// (utility = priority * opportunity * attitude / (1 + time / 2), + 0.15
// for the incumbent).
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_scare/coordinator.h"

using namespace mrt::scare;

namespace {

// Slots: 0 Defense, 1 BringBall, 2 Pass.passer, 3 Pass.receiver.
const char* kAllocYaml = R"Y(
fuzzy:
  shapes: "(UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))"
  data: "(A UNIT)"
activities:
  - {name: Defense, opportunity: (D A HIGH)}
  - {name: BringBall, opportunity: (D A HIGH)}
  - name: Pass
    opportunity: (D A HIGH)
    priority: 2
    roles: [{name: passer}, {name: receiver}]
options: {time_scale: 2.0, hysteresis: 0.15, min_opportunity: 0.05, dwell: 10}
)Y";

RobotView robot(const std::string& id, std::vector<double> att, int incumbent, double held) {
  RobotView r;
  r.id = id;
  r.attitude = std::move(att);
  r.time.assign(r.attitude.size(), 0.0);
  r.incumbent = incumbent;
  r.held = held;
  return r;
}

int slot_of(const Allocation& a, const std::string& id) {
  for (std::size_t i = 0; i < a.robots.size(); ++i)
    if (a.robots[i] == id) return a.slot[i];
  return -2;
}

// Slots: 0 Defense (priority 3, target (0, 0)), 1 Support (priority 0.5,
// target (5, 0)), 2 Positioning (0.1, up to 5 robots, no target); Defense
// and Support only when Threat is high. Attitude 1, 1 m/s.
const char* kTeamYaml = R"Y(
fuzzy:
  shapes: "(UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))"
  data: "(Threat UNIT)"
activities:
  - {name: Defense, opportunity: (D Threat HIGH), priority: 3, target: [0.0, 0.0]}
  - {name: Support, opportunity: (D Threat HIGH), priority: 0.5, target: [5.0, 0.0]}
  - {name: Positioning, opportunity: 0.1, max: 5}
default_attitude: 1.0
options: {time_scale: 2.0, hysteresis: 0.15, min_opportunity: 0.05, dwell: 10}
)Y";

/// Robots on 0.5 s cycles (exact in binary): all publish, the alive ones'
/// messages reach the alive others, all alive step.
struct Team {
  std::vector<Coordinator> c;
  std::vector<Pose2D> pose;
  std::vector<bool> alive;
  Team(double dwell, const std::vector<Pose2D>& poses) : pose(poses), alive(poses.size(), true) {
    ActivitySet s = parse_activities(kTeamYaml, "team.yaml");
    s.options.dwell = dwell;
    CoordinatorOptions o;
    o.listen = 0.0;
    for (std::size_t i = 0; i < poses.size(); ++i) c.emplace_back(s, s.robot_or_default("r" + std::to_string(i + 1)), o);
  }
  void cycle(double t) {
    const CrispMap w{{"Threat", {t >= 20.0 ? 1.0 : 0.0, 1.0}}};
    std::vector<CoordinationMessage> m(c.size());
    for (std::size_t i = 0; i < c.size(); ++i)
      if (alive[i]) m[i] = c[i].publish(t, pose[i], w);
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j)
        if (i != j && alive[i] && alive[j]) c[i].receive(m[j]);
    for (std::size_t i = 0; i < c.size(); ++i)
      if (alive[i]) c[i].step(t);
  }
  std::string job(std::size_t i) const {
    const int s = c[i].own_slot();
    return s < 0 ? "" : c[i].set().slot_name(c[i].set().slots()[static_cast<std::size_t>(s)]);
  }
};

/// The time r2 first holds Defense in the scene below, -1 never by 40 s.
double better_robot_scene(double dwell) {
  // r1 at (2, 0), r2 at (0, -6); before 20 s only Positioning is opportune.
  Team t(dwell, {{2.0, 0.0, 0}, {0.0, -6.0, 0}});
  for (int k = 0; k < 40; ++k) t.cycle(0.5 * k);
  EXPECT_EQ(t.job(0), "Positioning");
  EXPECT_EQ(t.job(1), "Positioning");
  // 20 s: r1 D 3 / (1 + 2 / 2) = 1.5 + r2 P 0.1 + 0.15 = 1.75 beats r1 D +
  // r2 S 0.5 / (1 + 7.81 / 2) = 0.102 (1.602) and r2 D 3 / 4 = 0.75 + r1 S
  // 0.5 / 2.5 = 0.2 (0.95): r1 takes Defense at 20.0.
  t.cycle(20.0);
  EXPECT_EQ(t.job(0), "Defense");
  EXPECT_DOUBLE_EQ(t.c[0].own_since(), 20.0);
  EXPECT_EQ(t.job(1), "Positioning");
  // 23 s: r2 is on Defense's spot: r2 D 3 + r1 S 0.2 = 3.2 beats r1 D 1.5 +
  // 0.15 + r2 P 0.25 = 1.9 (clearly better, without the dwell a switch).
  for (int k = 41; k <= 80; ++k) {
    if (k == 46) t.pose[1] = {0.0, 0.0, 0};
    t.cycle(0.5 * k);
    EXPECT_EQ(t.c[0].last().slot, t.c[1].last().slot) << "t = " << 0.5 * k;
    if (t.job(1) == "Defense") return 0.5 * k;
  }
  return -1.0;
}

}  // namespace

TEST(Dwell, IncumbentKeepsItsSlotUntilTheDwellEnds) {
  ActivitySet s = parse_activities(kAllocYaml, "test.yaml");
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 1.0, 0.0};  // Pass off the agenda
  // r2 better by 0.45: r2 D 0.95 + r1 B 0.5 = 1.45 > r1 D 0.5 + 0.15 + r2 B 0.5 = 1.15.
  in.robots = {robot("r1", {0.5, 0.5, 0, 0}, 0, 3.0), robot("r2", {0.95, 0.5, 0, 0}, -1, INFINITY)};
  EXPECT_TRUE(al.dwelling(in.robots[0]));
  EXPECT_EQ(slot_of(al.allocate(in), "r1"), 0);  // took Defense 3 s ago: keeps it
  in.robots[0].held = 9.99;
  EXPECT_EQ(slot_of(al.allocate(in), "r1"), 0);
  in.robots[0].held = 10.0;  // the dwell is over
  EXPECT_FALSE(al.dwelling(in.robots[0]));
  EXPECT_EQ(slot_of(al.allocate(in), "r2"), 0);
  EXPECT_EQ(slot_of(al.allocate(in), "r1"), 1);
  // The reported utility carries no dwell bonus: 0.5 + 0.15 + 0.5 = 1.15.
  in.robots[0].held = 3.0;
  EXPECT_NEAR(al.allocate(in).utility, 1.15, 1e-9);
  // Without a dwell (0) the better robot takes the slot at once.
  s.options.dwell = 0.0;
  EXPECT_EQ(slot_of(Allocator(s).allocate(in), "r2"), 0);
}

TEST(Dwell, CoverageAndTheAgendaBeatTheDwell) {
  const ActivitySet s = parse_activities(kAllocYaml, "test.yaml");
  Allocator al(s);
  TeamInput in;
  in.opportunity = {0.2, 0.0, 1.0};
  // Both in their Pass roles for 2 s: kept, 2 * (2 * 0.8 + 0.15) = 3.5.
  in.robots = {robot("r1", {0.9, 0, 0.8, 0.8}, 2, 2.0), robot("r2", {0.9, 0, 0.8, 0.8}, 3, 2.0)};
  Allocation a = al.allocate(in);
  EXPECT_EQ(slot_of(a, "r1"), 2);
  EXPECT_EQ(slot_of(a, "r2"), 3);
  // r2 gone: one robot cannot cover Pass (a schema is never half-filled),
  // so r1 leaves its role within the dwell: Defense 0.2 * 0.9 = 0.18.
  in.robots.pop_back();
  EXPECT_EQ(slot_of(al.allocate(in), "r1"), 0);
  // Pass below min_opportunity (0.04 < 0.05) but still opportune: kept on
  // the agenda while the dwelling robots hold it, 2 * (2 * 0.04 * 0.8 + 0.15)
  // = 0.428 (against 0.18 with r1 on Defense; the dwell keeps both anyway).
  in.robots.push_back(robot("r2", {0.9, 0, 0.8, 0.8}, 3, 2.0));
  in.opportunity = {0.2, 0.0, 0.04};
  a = al.allocate(in);
  EXPECT_EQ(slot_of(a, "r1"), 2);
  EXPECT_EQ(slot_of(a, "r2"), 3);
  EXPECT_NEAR(a.utility, 0.428, 1e-9);
  // Not opportune at all (0): both leave it, within the dwell.
  in.opportunity = {0.2, 0.0, 0.0};
  a = al.allocate(in);
  EXPECT_EQ(slot_of(a, "r1"), 0);  // tie on Defense: the lower id
  EXPECT_EQ(slot_of(a, "r2"), -1);
}

TEST(Dwell, KeepsAsManyDwellingRobotsAsCoverageAllows) {
  const ActivitySet s = parse_activities(kAllocYaml, "test.yaml");
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 1.0, 1.0};
  // r1 passes (dwelling), the receiver has left; r2 defends (dwelling),
  // r3 brings the ball (took it long ago). By utility alone r2 would
  // receive (r1 P 1.6 + 0.15 + r2 R 2.0 + r3 D 0.1 + 0.0 = 3.85 > r1 P 1.75
  // + r2 D 0.1 + 0.15 + r3 R 0.2 = 2.2); the dwell keeps r2 and moves r3,
  // the only robot not dwelling.
  in.robots = {robot("r1", {0.0, 0.0, 0.8, 0.0}, 2, 1.0), robot("r2", {0.1, 0.0, 0.0, 1.0}, 0, 1.0),
               robot("r3", {0.1, 0.0, 0.0, 0.1}, 1, 50.0)};
  const Allocation a = al.allocate(in);
  EXPECT_EQ(slot_of(a, "r1"), 2);
  EXPECT_EQ(slot_of(a, "r2"), 0);
  EXPECT_EQ(slot_of(a, "r3"), 3);
  EXPECT_NEAR(a.utility, 1.6 + 0.15 + 0.1 + 0.15 + 0.2, 1e-9);
}

TEST(Dwell, BetterRobotThreeSecondsAfterAChangeWaitsForTheDwell) {
  // With a 10 s dwell r1 keeps Defense from 20.0 until 30.0, where it
  // leaves it (to Support) and r2, released, takes it one cycle later.
  EXPECT_DOUBLE_EQ(better_robot_scene(10.0), 30.5);
  // Without: r1 leaves at once at 23.0, r2 takes it at 23.5.
  EXPECT_DOUBLE_EQ(better_robot_scene(0.0), 23.5);
}

TEST(Dwell, DropOutDuringTheDwellIsReassignedAtOnce) {
  // r1 at (5, 0), r2 at (0, 1). 20 s: r2 D 3 / (1 + 1 / 2) = 2.0 + r1 S 0.5
  // = 2.5 beats r1 D 3 / 3.5 = 0.857 + r2 S 0.5 / (1 + 5.10 / 2) = 0.141:
  // both change at 20.0 and dwell until 30.0.
  Team t(10.0, {{5.0, 0.0, 0}, {0.0, 1.0, 0}});
  for (int k = 0; k <= 46; ++k) t.cycle(0.5 * k);
  ASSERT_EQ(t.job(0), "Support");
  ASSERT_EQ(t.job(1), "Defense");
  EXPECT_DOUBLE_EQ(t.c[0].own_since(), 20.0);
  // r2 falls silent after 23.0: kept (dwelling, penalised) while its last
  // message is at most 1 s old, dropped at 24.5.
  t.alive[1] = false;
  for (int k = 47; k <= 48; ++k) {
    t.cycle(0.5 * k);
    EXPECT_EQ(t.job(0), "Support");
  }
  // 24.5: in the cycle of the drop nobody's dwell holds: r1 D 0.857 >
  // r1 S 0.5 + 0.15 = 0.65, so r1 takes Defense at once, within its dwell.
  t.cycle(24.5);
  EXPECT_EQ(t.c[0].team_size(), 1u);
  EXPECT_EQ(t.job(0), "Defense");
  EXPECT_DOUBLE_EQ(t.c[0].own_since(), 24.5);
}

TEST(Dwell, HeldTravelsInTheMessage) {
  Team t(10.0, {{5.0, 0.0, 0}, {0.0, 1.0, 0}});
  for (int k = 0; k <= 45; ++k) t.cycle(0.5 * k);
  // r2 took Defense at 20.0: at 22.5 it has held it 2.5 s.
  const CoordinationMessage m = t.c[1].publish(22.5, t.pose[1], {{"Threat", {1.0, 1.0}}});
  EXPECT_DOUBLE_EQ(m.held, 2.5);
  // r1's view at 22.75 adds the message's age: 2.75 s.
  Coordinator& r1 = t.c[0];
  ASSERT_TRUE(r1.receive(m));
  const TeamInput in = r1.team_input(22.75);
  EXPECT_DOUBLE_EQ(in.robots[1].held, 2.75);
  CoordinationMessage bad = m;
  bad.seq += 1;
  bad.held = -1.0;
  EXPECT_FALSE(r1.receive(bad));
  bad.held = std::nan("");
  EXPECT_FALSE(r1.receive(bad));
}
