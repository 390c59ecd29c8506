// Agenda, cardinality, coverage, hysteresis and tie-breaks of the SCARE
// allocator, on hand-worked numbers (times 0, so fit = attitude).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "mrt_scare/allocator.h"

using namespace mrt::scare;

namespace {

// Slots: 0 Defense, 1 BringBall, 2 Pass.passer, 3 Pass.receiver, 4 Wall.
const char* kYaml = R"Y(
fuzzy:
  shapes: "(UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))"
  data: "(A UNIT) (B UNIT)"
activities:
  - {name: Defense, opportunity: (D A HIGH)}
  - {name: BringBall, opportunity: (D B HIGH)}
  - name: Pass
    opportunity: (AND (D A HIGH) (D B HIGH))
    priority: 2
    roles: [{name: passer}, {name: receiver}]
  - {name: Wall, opportunity: 0.5, min: 2, max: 2}
options: {time_scale: 2.0, hysteresis: 0.15, min_opportunity: 0.05}
)Y";

ActivitySet set() { return parse_activities(kYaml, "test.yaml"); }

RobotView robot(const std::string& id, std::vector<double> att, int incumbent = -1) {
  RobotView r;
  r.id = id;
  r.attitude = std::move(att);
  r.time.assign(r.attitude.size(), 0.0);
  r.incumbent = incumbent;
  return r;
}

int slot_of(const Allocation& a, const std::string& id) {
  for (std::size_t i = 0; i < a.robots.size(); ++i)
    if (a.robots[i] == id) return a.slot[i];
  return -2;
}

}  // namespace

TEST(Agenda, DominanceLayersThenScore) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {0.8, 0.5, 0.5, 0.04};  // Wall below min_opportunity: not on the agenda
  in.robots = {robot("r1", {0.9, 0.4, 0.5, 0.5, 0.0}), robot("r2", {0.3, 0.8, 0.7, 0.2, 0.0})};
  // Criteria (opportunity, priority, best fit):
  //   Defense (0.8, 1, 0.9), BringBall (0.5, 1, 0.8), Pass (0.5, 2, 0.7).
  // Defense dominates BringBall; nothing dominates Defense or Pass (Pass has
  // the higher priority, Defense the higher opportunity and fit): layer 0 =
  // {Defense, Pass}, layer 1 = {BringBall}. Scores: Defense 1*0.8*0.9 = 0.72,
  // Pass 2*0.5*0.7 = 0.70, so Defense first.
  const auto ag = al.agenda(in);
  ASSERT_EQ(ag.size(), 3u);
  EXPECT_EQ(ag[0].activity, 0);
  EXPECT_EQ(ag[1].activity, 2);
  EXPECT_EQ(ag[2].activity, 1);
  EXPECT_EQ(ag[0].layer, 0);
  EXPECT_EQ(ag[1].layer, 0);
  EXPECT_EQ(ag[2].layer, 1);
  EXPECT_NEAR(ag[0].score, 0.72, 1e-12);
  EXPECT_NEAR(ag[1].score, 0.70, 1e-12);
  EXPECT_NEAR(ag[2].fit, 0.8, 1e-12);
}

TEST(Agenda, FitFallsWithTimeAndConfidence) {
  const ActivitySet s = set();
  Allocator al(s);
  RobotView r = robot("r1", {0.9, 0.4, 0.5, 0.5, 0.0});
  r.time[0] = 3.0;  // 0.9 / (1 + 3 / 2) = 0.36
  r.confidence = 0.5;
  EXPECT_NEAR(al.fit(r, 0), 0.18, 1e-12);
  r.time[0] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(al.fit(r, 0), 0.0);
}

TEST(Allocation, CardinalityMaxOneDefender) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 1.0, 0.0, 0.0};  // only Defense and BringBall
  in.robots = {robot("r1", {0.9, 0.5, 0, 0, 0}), robot("r2", {0.8, 0.7, 0, 0, 0}), robot("r3", {0.85, 0.1, 0, 0, 0})};
  // r1 D + r2 B = 1.6 beats r3 D + r2 B = 1.55 and r2 D + r1 B = 1.3; both
  // jobs hold one robot at most, so r3 is left without one.
  for (auto m : {Allocator::Method::kExact, Allocator::Method::kGreedy, Allocator::Method::kGreedyLocal}) {
    const Allocation a = al.allocate(in, m);
    EXPECT_EQ(slot_of(a, "r1"), 0);
    EXPECT_EQ(slot_of(a, "r2"), 1);
    EXPECT_EQ(slot_of(a, "r3"), -1);
    EXPECT_NEAR(a.utility, 1.6, 1e-12);
  }
}

TEST(Allocation, CardinalityMinimumTwo) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 0.0, 0.0, 1.0};  // Defense and Wall (min 2)
  in.robots = {robot("r1", {0.9, 0, 0, 0, 0.6}), robot("r2", {0.1, 0, 0, 0, 0.6})};
  // Both on the Wall: 0.6 + 0.6 = 1.2 > r1 defending alone (0.9; the Wall
  // cannot take r2 alone, and Defense only one).
  Allocation a = al.allocate(in, Allocator::Method::kExact);
  EXPECT_EQ(slot_of(a, "r1"), 4);
  EXPECT_EQ(slot_of(a, "r2"), 4);
  EXPECT_NEAR(a.utility, 1.2, 1e-12);
  // Wall attitudes 0.4: 0.8 < 0.9, r1 defends and r2 has nothing.
  in.robots[0].attitude[4] = in.robots[1].attitude[4] = 0.4;
  a = al.allocate(in, Allocator::Method::kExact);
  EXPECT_EQ(slot_of(a, "r1"), 0);
  EXPECT_EQ(slot_of(a, "r2"), -1);
}

TEST(Allocation, SchemaTakenOnlyWhenEveryRoleIsFilled) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 0.0, 0.5, 0.0};  // Pass: priority 2 * 0.5 = weight 1
  in.robots = {robot("r1", {0.5, 0, 0.9, 0.2, 0}), robot("r2", {0.6, 0, 0.3, 0.8, 0}),
               robot("r3", {0.7, 0, 0.5, 0.5, 0})};
  // Pass(r1, r2) 0.9 + 0.8 + D r3 0.7 = 2.4; Pass(r1, r3) 1.4 + D r2 0.6 = 2.0;
  // Pass(r3, r2) 1.3 + D r1 0.5 = 1.8.
  Allocation a = al.allocate(in, Allocator::Method::kExact);
  EXPECT_EQ(slot_of(a, "r1"), 2);
  EXPECT_EQ(slot_of(a, "r2"), 3);
  EXPECT_EQ(slot_of(a, "r3"), 0);
  EXPECT_NEAR(a.utility, 2.4, 1e-12);
  // r1 alone: passing would be worth 0.9 but has no receiver; it defends (0.5).
  in.robots = {in.robots[0]};
  for (auto m : {Allocator::Method::kExact, Allocator::Method::kGreedyLocal}) {
    a = al.allocate(in, m);
    EXPECT_EQ(slot_of(a, "r1"), 0);
    EXPECT_NEAR(a.utility, 0.5, 1e-12);
  }
}

TEST(Allocation, FeasibleChecksCoverageAndCardinality) {
  const ActivitySet s = set();
  Allocator al(s);
  const std::vector<char> all(4, 1);
  EXPECT_TRUE(al.feasible({2, 3, 0}, all));
  EXPECT_FALSE(al.feasible({2, 0}, all));      // passer without receiver
  EXPECT_FALSE(al.feasible({0, 0}, all));      // two defenders
  EXPECT_FALSE(al.feasible({4, 0}, all));      // Wall needs two
  EXPECT_FALSE(al.feasible({0}, {0, 1, 1, 1}));  // Defense not on the agenda
}

TEST(Allocation, LocalSearchRepairsGreedy) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 1.0, 0.0, 0.0};
  in.robots = {robot("r1", {0.9, 0.85, 0, 0, 0}), robot("r2", {0.8, 0.1, 0, 0, 0})};
  // Agenda: Defense (fit 0.9) before BringBall (0.85). Greedy gives Defense
  // its best robot r1 (0.9) and BringBall r2 (0.1): 1.0. The optimum swaps
  // them: r2 D 0.8 + r1 B 0.85 = 1.65, which the swap move finds.
  EXPECT_NEAR(al.allocate(in, Allocator::Method::kGreedy).utility, 1.0, 1e-12);
  EXPECT_NEAR(al.allocate(in, Allocator::Method::kGreedyLocal).utility, 1.65, 1e-12);
  const Allocation a = al.allocate(in, Allocator::Method::kExact);
  EXPECT_NEAR(a.utility, 1.65, 1e-12);
  EXPECT_EQ(slot_of(a, "r1"), 1);
}

TEST(Hysteresis, IncumbentKeepsItsJobUnlessClearlyBeaten) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 1.0, 0.0, 0.0};
  in.robots = {robot("r1", {0.80, 0.5, 0, 0, 0}), robot("r2", {0.75, 0.5, 0, 0, 0})};
  // No incumbent: r1 D + r2 B = 1.30 > r2 D + r1 B = 1.25.
  EXPECT_EQ(slot_of(al.allocate(in), "r1"), 0);
  // r2 defends now: r2 D + bonus 0.15 + r1 B = 1.40 > 1.30: r2 keeps it.
  in.robots[1].incumbent = 0;
  EXPECT_EQ(slot_of(al.allocate(in), "r2"), 0);
  // r1 better by 0.20 > 0.15: r1 D + r2 B = 0.95 + 0.5 = 1.45 > 1.40.
  in.robots[0].attitude[0] = 0.95;
  EXPECT_EQ(slot_of(al.allocate(in), "r1"), 0);
  // Better by 0.14 < 0.15 only: r1 D + r2 B = 1.39 < 1.40, r2 keeps it.
  in.robots[0].attitude[0] = 0.89;
  EXPECT_EQ(slot_of(al.allocate(in), "r2"), 0);
}

TEST(Hysteresis, NoiseBelowTheMarginNeverReassigns) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 1.0, 0.5, 0.0};
  in.robots = {robot("r1", {0.7, 0.7, 0.7, 0.7, 0}), robot("r2", {0.7, 0.7, 0.7, 0.7, 0}),
               robot("r3", {0.7, 0.7, 0.7, 0.7, 0})};
  Allocation a = al.allocate(in);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-0.07, 0.07);  // pairwise differences < 0.14 < 0.15
  int changes = 0;
  for (int k = 0; k < 2000; ++k) {
    TeamInput n = in;
    for (std::size_t i = 0; i < n.robots.size(); ++i) {
      n.robots[i].incumbent = a.slot[i];
      for (double& v : n.robots[i].attitude) v += noise(rng);
    }
    const Allocation b = al.allocate(n);
    changes += b.slot != a.slot;
    a = b;
  }
  EXPECT_EQ(changes, 0);
}

TEST(TieBreak, LowerIdTakesTheEarlierAgendaSlot) {
  const ActivitySet s = set();
  Allocator al(s);
  TeamInput in;
  in.opportunity = {1.0, 1.0, 0.0, 0.0};
  // Equal robots, equal jobs: Defense and BringBall tie on every criterion
  // and are in declaration order; robot "a" (first by id) gets Defense.
  in.robots = {robot("b", {0.5, 0.5, 0, 0, 0}), robot("a", {0.5, 0.5, 0, 0, 0})};
  for (auto m : {Allocator::Method::kExact, Allocator::Method::kGreedy, Allocator::Method::kGreedyLocal}) {
    const Allocation x = al.allocate(in, m);
    EXPECT_EQ(x.robots, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(slot_of(x, "a"), 0);
    EXPECT_EQ(slot_of(x, "b"), 1);
  }
}

TEST(TieBreak, SameInformationSameAllocationInAnyOrder) {
  const ActivitySet s = set();
  Allocator al(s);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> level(0, 3);  // coarse values: many exact ties
  for (int k = 0; k < 300; ++k) {
    TeamInput in;
    in.opportunity = {1.0, 1.0, 0.5, 0.5};
    for (int i = 0; i < 5; ++i) {
      std::vector<double> att;
      for (int j = 0; j < 5; ++j) att.push_back(0.25 * level(rng));
      in.robots.push_back(robot("robot" + std::to_string(i), att));
    }
    const Allocation ref = al.allocate(in);
    std::shuffle(in.robots.begin(), in.robots.end(), rng);
    EXPECT_EQ(al.allocate(in).slot, ref.slot);
  }
}
