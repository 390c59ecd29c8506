// brian_check: one malformed configuration per error kind, asserting the
// exact file:line reported, and the tool's exit codes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <sys/wait.h>

#include <string>
#include <vector>

#include "mrt_brian/brian.h"
#include "mrt_brian/checker.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

class CheckerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("brian_check_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "behaviors");
    write(dir_ / "shape_ctof.txt", "(DIST (TOL (NEAR 0 100)) (TOR (FAR 0 100)))\n(SP (TOL (SLOW 10 30)) (TOR (FAST 10 30)))\n");
    write(dir_ / "ctof.txt", "(Obstacle DIST)\n(ProposedSpeed SP)\n");
    write(dir_ / "Predicate.ini", "ObstacleNear = (D Obstacle NEAR);\nObstacleFar = (D Obstacle FAR);\n");
    write(dir_ / "PredicateActions.ini", "GoingFast = (D ProposedSpeed FAST);\n");
    write(dir_ / "Cando.ini", "Cruise = (P ObstacleFar);\nBrake = (P ObstacleNear);\n");
    write(dir_ / "want.txt", "Cruise = (NOT (P ObstacleNear));\nBrake = (P ObstacleNear);\n");
    write(dir_ / "behavior.txt", "(level 1 Cruise behaviors/cruise.rul)\n(level 2 Brake behaviors/brake.rul)\n");
    write(dir_ / "behaviors/cruise.rul", "# cruise\n(ObstacleFar) => (Speed FAST);\n(ObstacleNear) => (Speed SLOW);\n");
    write(dir_ / "behaviors/brake.rul",
          "(AND (GoingFast)\n     (ObstacleNear)) => (&DEL.Speed ANY) (Speed STOP);\n(&Cruise.Speed.FAST) => (Speed SLOW);\n");
    write(dir_ / "s_shape.txt", "(SPD (SNG (STOP 0)) (SNG (SLOW 10)) (SNG (FAST 30)))\n");
    write(dir_ / "s_ftoc.txt", "(Speed SPD)\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Exactly one diagnostic, at `file`:`line`, whose message contains `what`.
  void expect_one(const std::string& file, int line, const std::string& what) {
    const auto d = Checker().check_path(dir_.string());
    ASSERT_EQ(d.size(), 1u) << (d.empty() ? "none" : d[0].str() + (d.size() > 1 ? " / " + d[1].str() : ""));
    EXPECT_EQ(fs::path(d[0].file).lexically_relative(dir_).string(), file) << d[0].str();
    EXPECT_EQ(d[0].line, line) << d[0].str();
    EXPECT_NE(d[0].message.find(what), std::string::npos) << d[0].str();
    EXPECT_EQ(run_tool(dir_.string()), 1);
  }
  // Exactly one diagnostic: `file`:`line`: `message`, word for word.
  void expect_exactly(const std::string& file, int line, const std::string& message) {
    const auto d = Checker().check_path(dir_.string());
    ASSERT_EQ(d.size(), 1u) << (d.empty() ? "none" : d[0].str() + (d.size() > 1 ? " / " + d[1].str() : ""));
    EXPECT_EQ(fs::path(d[0].file).lexically_relative(dir_).string(), file) << d[0].str();
    EXPECT_EQ(d[0].line, line) << d[0].str();
    EXPECT_EQ(d[0].message, message);
    EXPECT_EQ(run_tool(dir_.string()), 1);
  }
  static int run_tool(const std::string& arg) {
    const std::string cmd = std::string(MRT_BRIAN_CHECK) + " " + arg + " >/dev/null 2>&1";
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  }
  fs::path dir_;
};

}  // namespace

TEST_F(CheckerTest, CleanBaseExitsZero) {
  EXPECT_TRUE(Checker().check_path(dir_.string()).empty());
  EXPECT_EQ(run_tool(dir_.string()), 0);
}

TEST_F(CheckerTest, UsageErrorsExitTwo) {
  EXPECT_EQ(run_tool(""), 2);
  EXPECT_EQ(run_tool((dir_ / "nonexistent").string()), 2);
  EXPECT_EQ(run_tool(dir_.string() + " extra"), 2);
}

TEST_F(CheckerTest, ListFileResolvesFromItsDirectory) {
  write(dir_ / "BrianConfigs.ini",
        "ctof.txt\nshape_ctof.txt\nPredicate.ini\nPredicateActions.ini\nCando.ini\nbehavior.txt\nwant.txt\ns_ftoc.txt\ns_shape.txt\n");
  EXPECT_EQ(run_tool((dir_ / "BrianConfigs.ini").string()), 0);
  write(dir_ / "BrianConfigs.ini", "ctof.txt\nshape_ctof.txt\n");
  EXPECT_EQ(run_tool((dir_ / "BrianConfigs.ini").string()), 1);
}

TEST_F(CheckerTest, RuleWithoutSemicolon) {
  write(dir_ / "behaviors/cruise.rul", "# cruise\n(ObstacleFar) => (Speed FAST)\n(ObstacleNear) => (Speed SLOW);\n");
  expect_exactly("behaviors/cruise.rul", 3, "expected ';' after rule (rule starting at line 2), got '('");
}

// A file that does not parse is reported once: what depends on it (here the
// data associated with shape DIST) is not reported again.
TEST_F(CheckerTest, UnknownFuzzySetType) {
  write(dir_ / "shape_ctof.txt", "(DIST (TOL (NEAR 0 100))\n (TOX (FAR 0 100)))\n(SP (TOL (SLOW 10 30)) (TOR (FAST 10 30)))\n");
  expect_exactly("shape_ctof.txt", 2, "unknown fuzzy set type 'TOX' (expected TRI TOL TOR DIV TRA REC SNG)");
}

// The labels of a datum whose shape is unknown are not reported again.
TEST_F(CheckerTest, UnknownShape) {
  write(dir_ / "ctof.txt", "(Obstacle DIST)\n(ProposedSpeed SPX)\n");
  expect_exactly("ctof.txt", 2, "unknown shape 'SPX' for datum 'ProposedSpeed'");
}

TEST_F(CheckerTest, UnknownOutputShape) {
  write(dir_ / "s_ftoc.txt", "\n(Speed SPEED)\n");
  expect_exactly("s_ftoc.txt", 2, "unknown shape 'SPEED' for action 'Speed'");
}

// Duplicate definitions, one per kind of file.
TEST_F(CheckerTest, ShapeDefinedTwice) {
  write(dir_ / "s_shape.txt", "(SPD (SNG (STOP 0)) (SNG (SLOW 10)) (SNG (FAST 30)))\n(SPD (SNG (STOP 0)))\n");
  expect_exactly("s_shape.txt", 2, "shape 'SPD' defined twice");
}

TEST_F(CheckerTest, LabelDefinedTwiceInAShape) {
  write(dir_ / "shape_ctof.txt",
        "(DIST (TOL (NEAR 0 100))\n (TOR (FAR 0 100))\n (TOR (NEAR 50 60)))\n(SP (TOL (SLOW 10 30)) (TOR (FAST 10 30)))\n");
  expect_exactly("shape_ctof.txt", 3, "label 'NEAR' defined twice in shape 'DIST'");
}

TEST_F(CheckerTest, DatumAssociatedTwice) {
  write(dir_ / "ctof.txt", "(Obstacle DIST)\n(ProposedSpeed SP)\n(Obstacle DIST)\n");
  expect_exactly("ctof.txt", 3, "datum 'Obstacle' associated twice (first at line 1)");
}

TEST_F(CheckerTest, PredicateDefinedTwice) {
  write(dir_ / "PredicateActions.ini", "GoingFast = (D ProposedSpeed FAST);\nObstacleFar = (D ProposedSpeed SLOW);\n");
  expect_exactly("PredicateActions.ini", 2,
                 "predicate 'ObstacleFar' defined twice (first at " + (dir_ / "Predicate.ini").string() + ":2)");
}

TEST_F(CheckerTest, BehaviourListedTwice) {
  write(dir_ / "behavior.txt",
        "(level 1 Cruise behaviors/cruise.rul)\n(level 2 Brake behaviors/brake.rul)\n(level 2 Cruise behaviors/cruise.rul)\n");
  expect_exactly("behavior.txt", 3, "behaviour 'Cruise' listed twice");
}

TEST_F(CheckerTest, CandoDefinedTwice) {
  write(dir_ / "Cando.ini", "Cruise = (P ObstacleFar);\nBrake = (P ObstacleNear);\nCruise = (P ObstacleNear);\n");
  expect_exactly("Cando.ini", 3, "CANDO of 'Cruise' defined twice");
}

TEST_F(CheckerTest, WantDefinedTwice) {
  write(dir_ / "want.txt", "Cruise = (NOT (P ObstacleNear));\nBrake = (P ObstacleNear);\n\nBrake = (P ObstacleFar);\n");
  expect_exactly("want.txt", 4, "WANT of 'Brake' defined twice");
}

TEST_F(CheckerTest, UnknownLabel) {
  write(dir_ / "Predicate.ini", "ObstacleNear = (D Obstacle NEAR);\nObstacleFar = (D Obstacle FARR);\n");
  expect_one("Predicate.ini", 2, "unknown label 'FARR'");
}

TEST_F(CheckerTest, UnknownDatum) {
  write(dir_ / "Predicate.ini", "ObstacleNear = (D Obstacle NEAR);\n\nObstacleFar = (D Obstacl FAR);\n");
  expect_one("Predicate.ini", 3, "unknown datum 'Obstacl'");
}

TEST_F(CheckerTest, UnknownPredicate) {
  write(dir_ / "behaviors/cruise.rul", "# cruise\n(ObstacleFar) => (Speed FAST);\n(ObstacleNeer) => (Speed SLOW);\n");
  expect_one("behaviors/cruise.rul", 3, "unknown predicate 'ObstacleNeer'");
}

TEST_F(CheckerTest, ForwardReference) {
  write(dir_ / "Predicate.ini", "ObstacleNear = (D Obstacle NEAR);\nClear = (NOT (P ObstacleFar));\nObstacleFar = (D Obstacle FAR);\n");
  expect_one("Predicate.ini", 2, "forward reference to predicate 'ObstacleFar'");
}

// §10.4.3 allows predicate actions in CANDO and WANT conditions: clean.
TEST_F(CheckerTest, PredicateActionInCandoIsAllowed) {
  write(dir_ / "Cando.ini", "Cruise = (P ObstacleFar);\nBrake = (AND (P ObstacleNear)\n  (P GoingFast));\n");
  write(dir_ / "want.txt", "Cruise = (NOT (P ObstacleNear));\nBrake = (P GoingFast);\n");
  const auto d = Checker().check_path(dir_.string());
  EXPECT_TRUE(d.empty()) << d[0].str();
}

// A `#(` block comment runs to the next ';': here from line 2 over the
// definition of ObstacleFar (line 3) -> a warning at line 2 (and, since
// ObstacleFar is then undefined, Cando.ini:1 and cruise.rul:2 name an
// unknown predicate).
TEST_F(CheckerTest, BlockCommentSwallowingADefinitionIsAWarning) {
  write(dir_ / "Predicate.ini",
        "ObstacleNear = (D Obstacle NEAR);\n#( far side\nObstacleFar = (D Obstacle FAR);\n");
  const auto d = Checker().check_path(dir_.string());
  ASSERT_EQ(d.size(), 3u) << d[0].str();
  EXPECT_EQ(d[0].str(), (dir_ / "Predicate.ini").string() +
                            ":2: warning: block comment '#(' runs to the ';' at line 3 and swallows a definition "
                            "(a '#' comment ends at the end of the line)");
  EXPECT_EQ(d[0].kind, Diagnostic::kWarning);
  EXPECT_EQ(d[1].line, 1);
  EXPECT_NE(d[1].message.find("unknown predicate 'ObstacleFar'"), std::string::npos);
  EXPECT_EQ(d[2].line, 2);
  EXPECT_EQ(fs::path(d[2].file).filename(), "cruise.rul");
  // The same in a rules file swallows a rule; a one-line '#(' note without
  // '=' is fine.
  write(dir_ / "Predicate.ini", "ObstacleNear = (D Obstacle NEAR);\nObstacleFar = (D Obstacle FAR);\n");
  write(dir_ / "behaviors/cruise.rul", "#( note ;\n#( old\n(ObstacleFar) => (Speed FAST);\n(ObstacleNear) => (Speed SLOW);\n");
  expect_one("behaviors/cruise.rul", 2, "swallows a rule");
}

TEST_F(CheckerTest, UnknownAction) {
  write(dir_ / "behaviors/cruise.rul", "# cruise\n(ObstacleFar) => (Sped FAST);\n(ObstacleNear) => (Speed SLOW);\n");
  expect_one("behaviors/cruise.rul", 2, "unknown action 'Sped'");
}

TEST_F(CheckerTest, UnknownActionLabel) {
  write(dir_ / "behaviors/cruise.rul", "# cruise\n(ObstacleFar) => (Speed FAST);\n(ObstacleNear) => (Speed SLOWER);\n");
  expect_one("behaviors/cruise.rul", 3, "unknown label 'SLOWER'");
}

TEST_F(CheckerTest, UnknownBehaviourInProposalPredicate) {
  write(dir_ / "behaviors/brake.rul", "(AND (GoingFast)\n     (ObstacleNear)) => (&DEL.Speed ANY) (Speed STOP);\n(&Cruse.Speed.FAST) => (Speed SLOW);\n");
  expect_one("behaviors/brake.rul", 3, "unknown behaviour 'Cruse'");
}

TEST_F(CheckerTest, DeleteAtLevelOne) {
  write(dir_ / "behaviors/cruise.rul", "# cruise\n(ObstacleFar) => (Speed FAST);\n(ObstacleNear) =>\n (&DEL.Speed ANY) (Speed SLOW);\n");
  expect_one("behaviors/cruise.rul", 4, "&DEL.Speed in level-1 behaviour");
}

TEST_F(CheckerTest, LevelGap) {
  write(dir_ / "behavior.txt", "(level 1 Cruise behaviors/cruise.rul)\n\n(level 3 Brake behaviors/brake.rul)\n");
  expect_one("behavior.txt", 3, "level gap");
}

TEST_F(CheckerTest, CandoForUndefinedBehaviour) {
  write(dir_ / "Cando.ini", "Cruise = (P ObstacleFar);\nBrake = (P ObstacleNear);\nReverse = (P ObstacleNear);\n");
  expect_one("Cando.ini", 3, "CANDO for undefined behaviour 'Reverse'");
}

TEST_F(CheckerTest, WantForUndefinedBehaviour) {
  write(dir_ / "want.txt", "Cruis = (NOT (P ObstacleNear));\nBrake = (P ObstacleNear);\n");
  expect_one("want.txt", 1, "WANT for undefined behaviour 'Cruis'");
}

TEST_F(CheckerTest, MissingBehaviourFile) {
  write(dir_ / "behavior.txt", "(level 1 Cruise behaviors/cruise.rul)\n(level 2 Brake behaviors/brakes.rul)\n");
  expect_one("behavior.txt", 2, "cannot open behaviour file");
}

TEST_F(CheckerTest, ReportsEveryProblemNotOnlyTheFirst) {
  write(dir_ / "want.txt", "Cruis = (NOT (P ObstacleNear));\nBrake = (P ObstacleNear);\n");
  write(dir_ / "Cando.ini", "Cruise = (P ObstacleFar);\nBrake = (P ObstacleNeer);\n");
  EXPECT_EQ(Checker().check_path(dir_.string()).size(), 2u);
}

TEST(CheckerShipped, EveryExampleRuleBaseIsClean) {
  int bases = 0;
  for (const auto& e : fs::directory_iterator(MRT_BRIAN_EXAMPLES_DIR)) {
    if (!e.is_directory()) continue;
    ++bases;
    const auto d = Checker().check_path(e.path().string());
    EXPECT_TRUE(d.empty()) << e.path() << ": " << (d.empty() ? "" : d[0].str());
    if (fs::exists(e.path() / "BrianConfigs.ini")) {
      EXPECT_TRUE(Checker().check_path((e.path() / "BrianConfigs.ini").string()).empty()) << e.path();
    }
  }
  EXPECT_GE(bases, 1);  // examples/harvesting
}

TEST(CheckerShipped, NotARegularFile) {
  const auto d = Checker().check_path("/dev/null");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NE(d[0].message.find("not a regular file"), std::string::npos);
}

TEST(CheckerShipped, ReferenceRuleBases) {
  // IsAac is clean; synth's `Later = (P Early);` is a deliberate forward
  // reference (a probe of the 2009 engine's file-order evaluation).
  EXPECT_TRUE(Checker().check_path(std::string(MRT_BRIAN_TEST_DATA) + "/isaac/bin/BrianConfigs.ini").empty());
  const auto d = Checker().check_path(std::string(MRT_BRIAN_TEST_DATA) + "/synth");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].line, 7);
}

// The loaders apply the checker's rules (one validate()): in the manual
// profile a rule base naming an unknown predicate fails to load with
// brian_check's very line; brian_run exits 2 with it on stderr. The legacy
// profile loads it (the name reads 0) and warns once per unknown name, even
// when the name is used twice.
TEST_F(CheckerTest, ManualProfileRefusesUnknownNamesAsTheCheckerReportsThem) {
  write(dir_ / "want.txt", "Cruise = (NOT (P ObstacleNeer));\nBrake = (P ObstacleNeer);\n");
  const auto d = Checker().check_path(dir_.string());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].str(), (dir_ / "want.txt").string() + ":1: unknown predicate 'ObstacleNeer'");
  try {
    Brian::from_path(dir_.string());
    FAIL() << "the manual profile loaded a rule base with an unknown name";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(std::string(e.what()), d[0].str());
  }
  const std::string input = (dir_ / "in.txt").string();
  write(input, "Obstacle 50\n---\n");
  const std::string cmd = std::string(MRT_BRIAN_RUN) + " " + dir_.string() + " " + input + " 2>" +
                          (dir_ / "err.txt").string() + " >/dev/null";
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  std::ifstream err(dir_ / "err.txt");
  std::string line;
  std::getline(err, line);
  EXPECT_EQ(line, d[0].str());

  BrianOptions legacy;
  legacy.profile = Profile::kLegacy;
  std::vector<std::string> warnings;
  legacy.warn = [&](const std::string& w) { warnings.push_back(w); };
  auto b = Brian::from_path(dir_.string(), legacy);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], d[0].str());
  // Obstacle 80 is NEAR 0.2 and FAR 0.8: Cruise's CANDO 0.8 passes the
  // legacy filter, its WANT NOT(<0, 1>) = <1, 1> (the unknown name reads 0);
  // it proposes FAST 0.8 and SLOW 0.2; Brake's CANDO 0.2 does not pass ->
  // (30*0.8 + 10*0.2) / 1 = 26.
  const auto out = b->run({{"Obstacle", 80, 1.0}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].value, 26.0, 1e-5);
}
