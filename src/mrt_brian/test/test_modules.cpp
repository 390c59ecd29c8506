// The whole engine in the manual profile on a small rule base whose
// numbers are worked by hand in the comments, plus the hierarchy rules
// (predicate actions, &DEL of lower levels, threshold, file order).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "mrt_brian/behavior_engine.h"
#include "mrt_brian/brian.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/lexer.h"
#include "mrt_brian/trace.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// Obstacle distance -> NEAR/FAR; Cruise (level 1) proposes FAST when far and
// SLOW when near; Brake (level 2) sees the proposed speed through the
// predicate action GoingFast and deletes FAST.
fs::path make_base(const std::string& brake_rules) {
  const fs::path d = fs::temp_directory_path() / ("brian_modules_" + std::to_string(::getpid()));
  fs::create_directories(d);
  write(d / "shape_ctof.txt", "(DIST (TOL (NEAR 0 100)) (TOR (FAR 0 100)))\n(SP (TOL (SLOW 10 30)) (TOR (FAST 10 30)))\n");
  write(d / "ctof.txt", "(Obstacle DIST)\n(ProposedSpeed SP)\n");
  write(d / "Predicate.ini", "ObstacleNear = (D Obstacle NEAR);\nObstacleFar = (D Obstacle FAR);\n");
  write(d / "PredicateActions.ini", "GoingFast = (D ProposedSpeed FAST);\n");
  write(d / "Cando.ini", "Cruise = (OR (P ObstacleFar) (P ObstacleNear));\nBrake = (P ObstacleNear);\n");
  write(d / "want.txt", "Cruise = (NOT (P ObstacleNear));\nBrake = (P ObstacleNear);\n");
  write(d / "behavior.txt", "(level 1 Cruise cruise.rul)\n(level 2 Brake brake.rul)\n");
  write(d / "cruise.rul", "(ObstacleFar) => (Speed FAST);\n(ObstacleNear) => (Speed SLOW);\n");
  write(d / "brake.rul", brake_rules);
  write(d / "s_shape.txt", "(SPD (SNG (STOP 0)) (SNG (SLOW 10)) (SNG (FAST 30)))\n");
  write(d / "s_ftoc.txt", "(Speed SPD)\n");
  return d;
}

// Removes the rule bases written by make_base when the tests end.
class TempCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    fs::remove_all(fs::temp_directory_path() / ("brian_modules_" + std::to_string(::getpid())));
  }
};
const auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new TempCleanup);

double command(const CommandList& c, const std::string& name) {
  for (const auto& x : c)
    if (x.name == name) return x.value;
  ADD_FAILURE() << "no command " << name;
  return -1;
}

}  // namespace

TEST(Modules, ManualProfileHandWorked) {
  const fs::path d = make_base("(AND (GoingFast) (ObstacleNear)) => (&DEL.Speed FAST) (Speed STOP);\n");
  Brian b(ConfigFiles::from_directory(d.string()));
  // Obstacle 40 (rel 0.5): NEAR <0.6, 0.5>, FAR <0.4, 0.5>. CANDO Cruise 0.6,
  // Brake 0.6 (both > 0.49); WANT Cruise 0.4, Brake 0.6.
  // Cruise: FAST 0.4*0.5 = 0.2, SLOW 0.6*0.5 = 0.3.
  // Before level 2: FAST 0.2*0.4 = 0.08, SLOW 0.3*0.4 = 0.12 -> (30*0.08 + 10*0.12)/0.2 = 18
  // -> ProposedSpeed 18: FAST 0.4 -> GoingFast <0.4, 1>.
  // Brake: AND(<0.4,1>, <0.6,0.5>) = <0.4,0.5> -> 0.2: deletes FAST, STOP 0.2.
  // Final: SLOW 0.12, STOP 0.2*0.6 = 0.12 -> (10*0.12 + 0*0.12)/0.24 = 5.
  CycleTrace t;
  const CommandList& out = b.run({{"Obstacle", 40, 0.5}}, &t);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(command(out, "Speed"), 5.0, 1e-9);
  bool saw_going_fast = false;
  for (const auto& p : t.predicates)
    if (p.name == "GoingFast") {
      saw_going_fast = true;
      EXPECT_NEAR(p.v.value, 0.4, 1e-9);
    }
  EXPECT_TRUE(saw_going_fast);
  ASSERT_EQ(t.actions.size(), 2u);
  for (const auto& a : t.actions) EXPECT_NEAR(a.mu, 0.12, 1e-9) << a.label;
  // Obstacle 150: FAR <1,1>; only Cruise is active, FAST 1 -> 30.
  EXPECT_NEAR(command(b.run({{"Obstacle", 150, 1}}), "Speed"), 30.0, 1e-9);
  // No datum at all: Obstacle reads <0,1> everywhere -> NEAR = 1 (TOL at 0)?
  // No: a missing datum is not fuzzified, every fuzzy datum reads <0, 1>, so
  // nothing is active and there is no command.
  EXPECT_TRUE(b.run({}).empty());
}

TEST(Modules, ManualProfileWithoutDeletionAveragesAllProposals) {
  const fs::path d = make_base("(AND (GoingFast) (ObstacleNear)) => (Speed STOP);\n");
  Brian b(ConfigFiles::from_directory(d.string()));
  // As above without &DEL: FAST 0.08, SLOW 0.12, STOP 0.12 -> (2.4 + 1.2)/0.32 = 11.25.
  EXPECT_NEAR(command(b.run({{"Obstacle", 40, 0.5}}), "Speed"), 11.25, 1e-9);
}

// §10.4.3: a predicate action in a CANDO/WANT condition (manual profile).
// Brake's CANDO and WANT are GoingFast. Obstacle 60 (reliability 1): NEAR
// 0.4, FAR 0.6; Cruise CANDO max = 0.6 (active), WANT NOT near = 0.6;
// proposals FAST 0.6, SLOW 0.4, weighted 0.36, 0.24 -> ProposedSpeed
// (30*0.36 + 10*0.24)/0.6 = 22 -> FAST (22-10)/20 = 0.6 = GoingFast.
// Brake's CANDO, evaluated again before level 2, is 0.6 > 0.49: it runs,
// deletes Cruise's proposals and proposes STOP 0.6 (weight 0.6) -> Speed 0.
// Read at the start of the cycle (before any proposal) GoingFast would be
// 0, Brake inactive and Speed 22.
TEST(Modules, PredicateActionInCandoAndWant) {
  const fs::path d = make_base("(GoingFast) => (&DEL.Speed ANY) (Speed STOP);\n");
  write(d / "Cando.ini", "Cruise = (OR (P ObstacleFar) (P ObstacleNear));\nBrake = (P GoingFast);\n");
  write(d / "want.txt", "Cruise = (NOT (P ObstacleNear));\nBrake = (P GoingFast);\n");
  Brian b(ConfigFiles::from_directory(d.string()));
  EXPECT_NEAR(command(b.run({{"Obstacle", 60, 1.0}}), "Speed"), 0.0, 1e-9);
  EXPECT_NEAR(b.cando()[static_cast<std::size_t>(b.engine().size() - 1)].value + b.cando()[0].value, 1.2, 1e-9);
  // Obstacle 20: NEAR 0.8, FAR 0.2, Cruise WANT 0.2: FAST 0.04, SLOW 0.16
  // -> 14 -> GoingFast 0.2: Brake stays inactive, Speed 14.
  EXPECT_NEAR(command(b.run({{"Obstacle", 20, 1.0}}), "Speed"), 14.0, 1e-9);
}

TEST(Modules, ThresholdIsSettable) {
  const fs::path d = make_base("(AND (GoingFast) (ObstacleNear)) => (Speed STOP);\n");
  BrianOptions opt;
  opt.threshold = 0.65;  // CANDO 0.6 no longer activates anything
  Brian b(ConfigFiles::from_directory(d.string()), opt);
  EXPECT_TRUE(b.run({{"Obstacle", 40, 0.5}}).empty());
  b.engine().set_threshold(0.5);
  EXPECT_FALSE(b.run({{"Obstacle", 40, 0.5}}).empty());
}

TEST(Modules, LegacyProfileUsesValueNotValueTimesReliability) {
  const fs::path d = make_base("(AND (GoingFast) (ObstacleNear)) => (Speed STOP);\n");
  BrianOptions opt;
  opt.profile = Profile::kLegacy;
  Brian b(ConfigFiles::from_directory(d.string()), opt);
  // Reliability 0.5 > 0.49, CANDO/WANT pass the composite filter only where
  // value > 0.49: Cruise CANDO <0.6,0.5> active; WANT Cruise 0.4 -> weight 0,
  // Brake CANDO <0.6,0.5> active, WANT 0.6. Cruise: FAST 0.4, SLOW 0.6
  // (values, not value*rel). Brake start: weights in place -> 0, 0: no
  // ProposedSpeed command, GoingFast 0, Brake does not fire. End: 0 again.
  CycleTrace t;
  b.run({{"Obstacle", 40, 0.5}}, &t);
  EXPECT_TRUE(t.commands.empty());
  ASSERT_EQ(t.rules.size(), 2u);
  for (const auto& r : t.rules) EXPECT_EQ(r.behavior, "Cruise");
}

TEST(Modules, ManualListFileWithEightFilesAndErrors) {
  const fs::path d = make_base("(ObstacleNear) => (Speed STOP);\n");
  write(d / "list8.ini", "ctof.txt\nshape_ctof.txt\nPredicate.ini\nCando.ini\nbehavior.txt\nwant.txt\ns_ftoc.txt\ns_shape.txt\n");
  EXPECT_NO_THROW(Brian::from_path((d / "list8.ini").string()));
  write(d / "list3.ini", "ctof.txt\nshape_ctof.txt\nPredicate.ini\n");
  EXPECT_THROW(Brian::from_path((d / "list3.ini").string()), mrt::common::ParseError);
  write(d / "brake.rul", "(ObstacleNear) => (Speed NOPE);\n");
  try {
    Brian::from_path(d.string());
    FAIL() << "no error for an unknown label";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(e.file().find("brake.rul"), std::string::npos);
  }
}

namespace {
// A behaviour that is not a rule base: always proposes one action.
class ConstantBehavior : public Behavior {
 public:
  ConstantBehavior(std::string name, int level, int action, int label, double value)
      : Behavior(std::move(name), level), action_(action), label_(label), value_(value) {}
  void run(BehaviorContext& ctx) const override { ctx.propose(action_, label_, value_, 1.0); }

 private:
  int action_, label_;
  double value_;
};

struct LevelLog : HierarchyObserver {
  std::vector<int> levels;
  void before_level(int level) override { levels.push_back(level); }
};
}  // namespace

TEST(Modules, CustomBehaviorPlugsIntoTheEngine) {
  BehaviorEngine e;
  e.add(std::make_unique<ConstantBehavior>("Low", 1, 0, 0, 0.7));
  e.add(std::make_unique<ConstantBehavior>("High", 2, 0, 1, 0.9));
  e.add(std::make_unique<ConstantBehavior>("Top", 3, 0, 2, 0.2));
  e.finalize(Profile::kManual);
  ExpressionPool pool;
  EvalState s;
  ProposalList proposals;
  BehaviorContext ctx;
  ctx.pool = &pool;
  ctx.state = &s;
  ctx.proposals = &proposals;
  std::vector<std::uint8_t> active;
  LevelLog log;
  // CANDO: Low 0.8 and Top 0.5 pass the default 0.49 threshold, High 0.3 does not.
  e.run({{0.8, 1.0}, {0.3, 1.0}, {0.5, 1.0}}, ctx, &log, active);
  ASSERT_EQ(proposals.size(), 2u);
  EXPECT_EQ(proposals[0].owner, 0);
  EXPECT_DOUBLE_EQ(proposals[0].value, 0.7);
  EXPECT_EQ(proposals[1].owner, 2);
  EXPECT_EQ(proposals[1].level, 3);
  EXPECT_EQ(log.levels, (std::vector<int>{2, 3}));
  EXPECT_EQ(active, (std::vector<std::uint8_t>{1, 0, 1}));
}

TEST(Modules, CustomBehaviorKindThroughTheFacade) {
  const fs::path d = make_base("unused");
  write(d / "behavior.txt", "(level 1 Cruise cruise.rul)\n(level 2 Brake brake.const)\n");
  write(d / "brake.const", "Speed STOP 0.5\n");
  BrianOptions opt;
  opt.behavior_kinds[".const"] = [](const BehaviorDef& e, const std::string& path,
                                   const Defuzzyfier& dz) -> std::unique_ptr<Behavior> {
    std::ifstream in(path);
    std::string action, label;
    double value = 0;
    in >> action >> label >> value;
    const int a = dz.action_id(action);
    if (a < 0) throw mrt::common::ParseError(path, 1, 1, "unknown action");
    return std::make_unique<ConstantBehavior>(e.name, e.level, a, dz.label_id(a, label), value);
  };
  Brian b(ConfigFiles::from_directory(d.string()), opt);
  // Cruise as in ManualProfileHandWorked (FAST 0.2, SLOW 0.3, weight 0.4);
  // Brake (CANDO 0.6, WANT 0.6) proposes STOP 0.5 -> 0.3.
  // (30*0.08 + 10*0.12 + 0*0.3) / 0.5 = 7.2.
  EXPECT_NEAR(command(b.run({{"Obstacle", 40, 0.5}}), "Speed"), 7.2, 1e-9);
}

// Where the 2009 engine crashed, loading fails with file:line.
TEST(Modules, ClearErrorsWhereTheOriginalCrashed) {
  const fs::path d = make_base("(ObstacleNear) => (Speed STOP);\n");
  write(d / "cruise.rul", "(ObstacleFar) => (&DEL.Speed ANY) (Speed FAST);\n");
  BrianOptions legacy;
  legacy.profile = Profile::kLegacy;
  try {
    Brian b(ConfigFiles::from_directory(d.string()), legacy);
    FAIL() << "no error for &DEL at level 1";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(fs::path(e.file()).filename(), "behavior.txt");
    EXPECT_EQ(e.line(), 1);
  }
  // The manual profile accepts it: there is simply nothing below to delete.
  EXPECT_NO_THROW(Brian(ConfigFiles::from_directory(d.string())));
  write(d / "cruise.rul", "(ObstacleFar) => (Speed FAST);\n");
  write(d / "Cando.ini", "Cruise = (P ObstacleFar);\nBrake = (P ObstacleNear);\nGhost = (P ObstacleNear);\n");
  try {
    Brian b(ConfigFiles::from_directory(d.string()), legacy);
    FAIL() << "no error for a CANDO of an unknown behaviour";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(fs::path(e.file()).filename(), "Cando.ini");
    EXPECT_EQ(e.line(), 3);
  }
}

// The legacy WANT filter follows a threshold changed at run time. Obstacle
// 40 (rel 0.5): CANDO Cruise <0.6,0.5>, Brake <0.6,0.5>; WANT Cruise
// <0.4,0.5>, Brake <0.6,0.5>. At 0.49 Cruise's WANT fails the composite
// filter (weight 0) and nothing is commanded (see above). At 0.35 it
// passes: Cruise FAST 0.4, SLOW 0.6; before Brake, in place x0.4 -> 0.16,
// 0.24 -> ProposedSpeed (30*0.16 + 10*0.24)/0.4 = 18 -> GoingFast <0.4,1>;
// Brake: AND(<0.4,1>, <0.6,0.5>) -> STOP 0.4; at the end in place again:
// FAST 0.064, SLOW 0.096, STOP 0.24 -> (1.92 + 0.96)/0.4 = 7.2.
TEST(Modules, LegacyThresholdChangedAtRunTimeAppliesToWant) {
  const fs::path d = make_base("(AND (GoingFast) (ObstacleNear)) => (Speed STOP);\n");
  BrianOptions opt;
  opt.profile = Profile::kLegacy;
  Brian b(ConfigFiles::from_directory(d.string()), opt);
  EXPECT_TRUE(b.run({{"Obstacle", 40, 0.5}}).empty());
  b.engine().set_threshold(0.35);
  EXPECT_DOUBLE_EQ(b.engine().threshold(), 0.35);
  EXPECT_NEAR(command(b.run({{"Obstacle", 40, 0.5}}), "Speed"), 7.2, 1e-6);
  opt.threshold = 0.35;  // the same from the start
  Brian c(ConfigFiles::from_directory(d.string()), opt);
  EXPECT_NEAR(command(c.run({{"Obstacle", 40, 0.5}}), "Speed"), 7.2, 1e-6);
  b.engine().set_threshold(0.49);
  EXPECT_TRUE(b.run({{"Obstacle", 40, 0.5}}).empty());
}

namespace {
// Cruise (level 1) proposes all three labels; Brake (level 2) proposes FAST
// and deletes with `del`.
const char* kCruise3 = "(ObstacleFar) => (Speed FAST);\n(ObstacleNear) => (Speed SLOW);\n(ObstacleNear) => (Speed STOP);\n";

double deleted_speed(Profile p, const std::string& del) {
  const fs::path d = make_base("(ObstacleFar) => (Speed FAST);\n(ObstacleNear) => (&DEL.Speed " + del + ");\n");
  write(d / "cruise.rul", kCruise3);
  BrianOptions opt;
  opt.profile = p;
  Brian b(ConfigFiles::from_directory(d.string()), opt);
  return command(b.run({{"Obstacle", 50, 1}}), "Speed");
}
}  // namespace

// &DEL with ANY, a label and a *substring. Obstacle 50 (rel 1): NEAR and FAR
// <0.5,1>; both CANDOs 0.5 and both WANTs 0.5 pass 0.49. Cruise proposes
// FAST, SLOW, STOP 0.5 each; Brake proposes FAST 0.5, then deletes.
// Singletons STOP 0, SLOW 10, FAST 30.
//
// Manual (value x reliability, weighted once by WANT 0.5, average):
//   ANY:  Brake's FAST 0.25 only                            -> 30
//   FAST: SLOW 0.25, STOP 0.25, Brake FAST 0.25             -> (2.5 + 7.5)/0.75 = 13.3333
//   *ST (STOP and FAST, not SLOW): SLOW 0.25, Brake FAST 0.25 -> (2.5 + 7.5)/0.5 = 20
// Legacy (value; before Brake the list is weighted in place, x0.5, and once
// more at the end; max):
//   ANY:  Brake FAST 0.5 -> 0.25                              -> 30
//   FAST: SLOW 0.125, STOP 0.125, Brake FAST 0.25             -> (1.25 + 7.5)/0.5 = 17.5
//   *ST:  SLOW 0.125, Brake FAST 0.25                          -> (1.25 + 7.5)/0.375 = 23.3333
TEST(Modules, DeleteAnyLabelAndSubstringManual) {
  EXPECT_NEAR(deleted_speed(Profile::kManual, "ANY"), 30.0, 1e-9);
  EXPECT_NEAR(deleted_speed(Profile::kManual, "FAST"), 10.0 / 0.75, 1e-9);
  EXPECT_NEAR(deleted_speed(Profile::kManual, "*ST"), 20.0, 1e-9);
}

TEST(Modules, DeleteAnyLabelAndSubstringLegacy) {
  EXPECT_NEAR(deleted_speed(Profile::kLegacy, "ANY"), 30.0, 1e-6);
  EXPECT_NEAR(deleted_speed(Profile::kLegacy, "FAST"), 17.5, 1e-6);
  EXPECT_NEAR(deleted_speed(Profile::kLegacy, "*ST"), 8.75 / 0.375, 1e-6);
}

// &Behaviour.Action.Label in the manual profile: the value the behaviour
// proposed (max over matches), before WANT weighting. Obstacle 40 (rel 1):
// NEAR 0.6, FAR 0.4; CANDOs 0.6; WANT Cruise 0.4, Brake 0.6. Cruise: FAST
// 0.4, SLOW 0.6, STOP 0.6, weighted 0.16, 0.24, 0.24.
//   (&Cruise.Speed.FAST) = 0.4 -> Brake FAST 0.4 x 0.6 = 0.24; FAST average
//   (0.16 + 0.24)/2 = 0.2 -> (6 + 2.4)/(0.2 + 0.24 + 0.24) = 12.352941
//   (&Cruise.Speed.ANY) = 0.6 -> Brake FAST 0.36; FAST 0.26 -> 10.2/0.74 = 13.783784
//   (&Cruise.Speed.STOP) AND (&Cruise.Speed.FAST) = 0.4 -> as the first.
// (Were the weighted 0.16 read instead, the first would give 10.263.)
TEST(Modules, ProposalPredicatesManual) {
  auto speed = [](const std::string& pre) {
    const fs::path d = make_base(pre + " => (Speed FAST);\n");
    write(d / "cruise.rul", kCruise3);
    Brian b(ConfigFiles::from_directory(d.string()));
    return command(b.run({{"Obstacle", 40, 1}}), "Speed");
  };
  EXPECT_NEAR(speed("(&Cruise.Speed.FAST)"), 8.4 / 0.68, 1e-9);
  EXPECT_NEAR(speed("(P &Cruise.Speed.FAST)"), 8.4 / 0.68, 1e-9);
  EXPECT_NEAR(speed("(&Cruise.Speed.ANY)"), 10.2 / 0.74, 1e-9);
  EXPECT_NEAR(speed("(AND (&Cruise.Speed.STOP) (&Cruise.Speed.FAST))"), 8.4 / 0.68, 1e-9);
  // A label Cruise did not propose reads 0: Brake does not fire -> (4.8 + 2.4)/0.64.
  const fs::path d = make_base("(&Cruise.Speed.FAST) => (Speed FAST);\n");
  write(d / "cruise.rul", "(ObstacleNear) => (Speed SLOW);\n(ObstacleNear) => (Speed STOP);\n");
  Brian b(ConfigFiles::from_directory(d.string()));
  EXPECT_NEAR(command(b.run({{"Obstacle", 40, 1}}), "Speed"), 2.4 / 0.48, 1e-9);
}

// A directory read with the other conventional spellings: behaviour.txt and
// Want.ini (the IsAac configuration directory itself, whose BrianConfigs.ini
// names exactly those files) gives the same commands as its list file.
TEST(Modules, DirectoryWithWantIniAndBehaviourTxt) {
  const std::string data = MRT_BRIAN_TEST_DATA;
  const ConfigFiles f = ConfigFiles::from_directory(data + "/isaac/config");
  EXPECT_EQ(fs::path(f.want).filename(), "Want.ini");
  EXPECT_EQ(fs::path(f.behaviors).filename(), "behaviour.txt");
  EXPECT_EQ(fs::path(f.predicate_actions).filename(), "PredicateActions.ini");
  BrianOptions opt;
  opt.profile = Profile::kLegacy;
  Brian dir(f, opt);
  Brian list(ConfigFiles::from_list_file(data + "/isaac/bin/BrianConfigs.ini"), opt);
  EXPECT_EQ(dir.engine().size(), 8);
  const auto inputs = parse_crisp_input(read_text_file(data + "/isaac/input.txt"), "input.txt");
  ASSERT_GT(inputs.size(), 100u);
  int commands = 0;
  for (std::size_t i = 0; i < 100; ++i) {
    const CommandList a = dir.run(inputs[i]);
    const CommandList& b = list.run(inputs[i]);
    ASSERT_EQ(a.size(), b.size()) << "cycle " << i;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].name, b[k].name);
      EXPECT_EQ(a[k].value, b[k].value) << a[k].name << " cycle " << i;
    }
    commands += static_cast<int>(a.size());
  }
  EXPECT_GT(commands, 100);
  // A directory with want.txt and Want.ini both: want.txt wins.
  const fs::path d = make_base("(ObstacleNear) => (Speed STOP);\n");
  write(d / "Want.ini", "Cruise = (P ObstacleNear);\n");
  EXPECT_EQ(fs::path(ConfigFiles::from_directory(d.string()).want).filename(), "want.txt");
  fs::remove(d / "want.txt");
  fs::rename(d / "behavior.txt", d / "behaviour.txt");
  const ConfigFiles g = ConfigFiles::from_directory(d.string());
  EXPECT_EQ(fs::path(g.want).filename(), "Want.ini");
  EXPECT_EQ(fs::path(g.behaviors).filename(), "behaviour.txt");
  // Want.ini: Cruise wants ObstacleNear (0.6), Brake has no WANT (0):
  // Obstacle 40 (rel 1): Cruise FAST 0.4, SLOW 0.6 x 0.6; Brake's STOP x 0
  // -> (30*0.24 + 10*0.36)/(0.24 + 0.36 + 0) = 10.8/0.6 = 18.
  Brian w(g);
  EXPECT_NEAR(command(w.run({{"Obstacle", 40, 1}}), "Speed"), 18.0, 1e-9);
}

TEST(CycleTrace, NumbersAreWrittenAsPrintfPercentF) {
  // The reference traces were written with printf("%f"): every number must
  // come out with exactly those characters (rounding, -0, nan, inf, huge).
  const double values[] = {0.0, -0.0, 1.0, 0.5, 64.13, 0.0000005, 0.0000015, -0.34773, 2.5e-7,
                           123456789.123456789, 1e300, -1.7976931348623157e308, 0.1 + 0.2,
                           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()};
  for (double v : values) {
    CycleTrace t;
    t.commands.push_back({"Speed", v});
    t.rules.push_back({"B", 17, v});
    const auto lines = t.lines(true);
    ASSERT_EQ(lines.size(), 2u);
    std::vector<char> buf(512);
    std::snprintf(buf.data(), buf.size(), "CMD Speed %f", v);
    EXPECT_EQ(lines[0], std::string(buf.data())) << v;
    std::snprintf(buf.data(), buf.size(), "RULE B 17 %f", v);
    EXPECT_EQ(lines[1], std::string(buf.data())) << v;
  }
}
