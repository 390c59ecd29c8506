// Several files in one BrianConfigs.ini slot (doc/formats.md, "Several files a
// slot"): the union is loaded, every message names the file and line the
// definition came from, and a name defined in two files names both places.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mrt_brian/brian.h"
#include "mrt_brian/checker.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// base/: a one-behaviour rule base (Cruise, level 1); extra/: a second file
// for seven of the nine slots (a datum Visitor, a predicate VisitorFar, a
// level-2 behaviour Wait that stops the robot). base/BrianConfigs.ini names
// both on one line per slot.
class MultiFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("brian_multi_" + std::to_string(::getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    base_ = root_ / "base";
    extra_ = root_ / "extra";
    fs::create_directories(base_ / "behaviors");
    fs::create_directories(extra_);
    write(base_ / "shape_ctof.txt", "(DIST (TOL (NEAR 0 100)) (TOR (FAR 0 100)))\n(SP (TOL (SLOW 10 30)) (TOR (FAST 10 30)))\n");
    write(base_ / "ctof.txt", "(Obstacle DIST)\n(ProposedSpeed SP)\n");
    write(base_ / "Predicate.ini", "ObstacleNear = (D Obstacle NEAR);\nObstacleFar = (D Obstacle FAR);\n");
    write(base_ / "PredicateActions.ini", "GoingFast = (D ProposedSpeed FAST);\n");
    write(base_ / "Cando.ini", "Cruise = (P ObstacleFar);\n");
    write(base_ / "want.txt", "Cruise = (P ObstacleFar);\n");
    write(base_ / "behavior.txt", "(level 1 Cruise behaviors/cruise.rul)\n");
    write(base_ / "behaviors/cruise.rul", "(ObstacleFar) => (Speed FAST);\n");
    write(base_ / "s_shape.txt", "(SPD (SNG (STOP 0)) (SNG (SLOW 10)) (SNG (FAST 30)))\n");
    write(base_ / "s_ftoc.txt", "(Speed SPD)\n");
    write(extra_ / "shape_ctof.txt", "(GAP (TOL (SMALL 50 150)) (TOR (BIG 50 150)))\n");
    write(extra_ / "ctof.txt", "(Visitor GAP)\n");
    write(extra_ / "Predicate.ini", "# the visitor\nVisitorFar = (D Visitor BIG);\n");
    write(extra_ / "Cando.ini", "Wait = (P VisitorFar);\n");
    write(extra_ / "want.txt", "Wait = (P VisitorFar);\n");
    // Rule paths resolve from the BrianConfigs.ini directory (base/).
    write(extra_ / "behavior.txt", "(level 2 Wait ../extra/wait.rul)\n");
    write(extra_ / "wait.rul", "(VisitorFar) => (&DEL.Speed ANY) (Speed STOP);\n");
    write(list(), "ctof.txt ../extra/ctof.txt\n"
                  "shape_ctof.txt\t../extra/shape_ctof.txt\n"
                  "Predicate.ini ../extra/Predicate.ini  # a comment after the names\n"
                  "PredicateActions.ini\n"
                  "Cando.ini ../extra/Cando.ini\n"
                  "behavior.txt ../extra/behavior.txt\n"
                  "want.txt ../extra/want.txt\n"
                  "s_ftoc.txt\n"
                  "s_shape.txt\n");
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string list() const { return (base_ / "BrianConfigs.ini").string(); }
  static bool same(const std::string& a, const fs::path& b) { return fs::weakly_canonical(a) == fs::weakly_canonical(b); }
  // Exactly one checker diagnostic, at `file`:`line`.
  std::vector<Diagnostic> one_diagnostic(const fs::path& file, int line) const {
    const auto d = Checker().check_path(list());
    EXPECT_EQ(d.size(), 1u) << (d.empty() ? "none" : d[0].str());
    if (d.empty()) return d;
    EXPECT_TRUE(same(d[0].file, file)) << d[0].str();
    EXPECT_EQ(d[0].line, line) << d[0].str();
    return d;
  }
  // Loading throws a ParseError at `file`:`line`; returns its message.
  std::string load_error(const fs::path& file, int line) const {
    try {
      Brian b(ConfigFiles::from_list_file(list()));
    } catch (const mrt::common::ParseError& e) {
      EXPECT_TRUE(same(e.file(), file)) << e.what();
      EXPECT_EQ(e.line(), line) << e.what();
      return e.message();
    }
    ADD_FAILURE() << "loaded without error";
    return "";
  }

  fs::path root_, base_, extra_;
};

double speed(const CommandList& c) {
  for (const auto& x : c)
    if (x.name == "Speed") return x.value;
  ADD_FAILURE() << "no Speed command";
  return -1.0;
}

}  // namespace

TEST_F(MultiFileTest, ListFileSplitsALineIntoTheFilesOfOneSlot) {
  const ConfigFiles f = ConfigFiles::from_list_file(list());
  EXPECT_TRUE(same(f.predicates, base_ / "Predicate.ini"));
  ASSERT_EQ(f.more[static_cast<std::size_t>(Slot::kPredicates)].size(), 1u);  // the comment is no file
  EXPECT_TRUE(same(f.more[static_cast<std::size_t>(Slot::kPredicates)][0], extra_ / "Predicate.ini"));
  EXPECT_EQ(f.all(Slot::kShapeCtof).size(), 2u);  // tab-separated
  EXPECT_EQ(f.all(Slot::kSShape).size(), 1u);
  EXPECT_TRUE(f.more[static_cast<std::size_t>(Slot::kPredicateActions)].empty());
}

TEST_F(MultiFileTest, TwoFilesForOneSlotLoadTheUnion) {
  EXPECT_TRUE(Checker().check_path(list()).empty());
  Brian b(ConfigFiles::from_list_file(list()));
  EXPECT_GE(b.fuzzyfier().datum_id("Obstacle"), 0);
  EXPECT_GE(b.fuzzyfier().datum_id("Visitor"), 0);
  EXPECT_GE(b.predicates().find("ObstacleFar"), 0);
  EXPECT_GE(b.predicates().find("VisitorFar"), 0);
  ASSERT_EQ(b.engine().size(), 2);
  // Obstacle 150: FAR = 1 (TOR 0 100), Cruise proposes FAST (30 cm/s).
  // Visitor 50: BIG = 0 (TOR 50 150), Wait is not active -> Speed 30.
  EXPECT_NEAR(speed(b.run({{"Obstacle", 150, 1}, {"Visitor", 50, 1}})), 30.0, 1e-9);
  // Visitor 150: BIG = 1, Wait (level 2, CANDO = WANT = 1) deletes Cruise's
  // FAST and proposes STOP (0) -> Speed 0: the second files' behaviour runs.
  EXPECT_NEAR(speed(b.run({{"Obstacle", 150, 1}, {"Visitor", 150, 1}})), 0.0, 1e-9);
}

TEST_F(MultiFileTest, DuplicatePredicateAcrossFilesNamesBothPlaces) {
  write(extra_ / "Predicate.ini", "VisitorFar = (D Visitor BIG);\nObstacleFar = (D Obstacle NEAR);\n");
  const std::string both =
      "predicate 'ObstacleFar' defined twice (first at " + (base_ / "Predicate.ini").string() + ":2)";
  const auto d = one_diagnostic(extra_ / "Predicate.ini", 2);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, both);
  EXPECT_EQ(d[0].kind, Diagnostic::kDuplicate);
  EXPECT_EQ(load_error(extra_ / "Predicate.ini", 2), both);
  // The legacy profile refuses it too (no 2009 behaviour to keep).
  BrianOptions legacy;
  legacy.profile = Profile::kLegacy;
  EXPECT_THROW(Brian(ConfigFiles::from_list_file(list()), legacy), mrt::common::ParseError);
}

TEST_F(MultiFileTest, DuplicateShapeAndBehaviourAcrossFilesNameBothPlaces) {
  write(extra_ / "shape_ctof.txt", "(GAP (TOL (SMALL 50 150)) (TOR (BIG 50 150)))\n(SP (SNG (X 1)))\n");
  const auto d = one_diagnostic(extra_ / "shape_ctof.txt", 2);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, "shape 'SP' defined twice (first at " + (base_ / "shape_ctof.txt").string() + ":2)");
  EXPECT_EQ(load_error(extra_ / "shape_ctof.txt", 2), d[0].message);

  write(extra_ / "shape_ctof.txt", "(GAP (TOL (SMALL 50 150)) (TOR (BIG 50 150)))\n");
  write(extra_ / "behavior.txt", "(level 2 Wait ../extra/wait.rul)\n(level 2 Cruise ../extra/wait.rul)\n");
  const auto b = one_diagnostic(extra_ / "behavior.txt", 2);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].message, "behaviour 'Cruise' listed twice (first at " + (base_ / "behavior.txt").string() + ":1)");
  EXPECT_EQ(load_error(extra_ / "behavior.txt", 2), b[0].message);
}

TEST_F(MultiFileTest, SyntaxErrorInTheSecondFileNamesThatFileAndLine) {
  write(extra_ / "Predicate.ini", "VisitorFar = (D Visitor BIG);\n\nVisitorNear = (D Visitor SMALL;\n");
  const auto d = one_diagnostic(extra_ / "Predicate.ini", 3);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NE(d[0].message.find("expected"), std::string::npos) << d[0].str();
  EXPECT_EQ(load_error(extra_ / "Predicate.ini", 3), d[0].message);
}

TEST_F(MultiFileTest, UnknownNameInTheSecondFileNamesThatFileAndEveryFileOfTheSlot) {
  write(extra_ / "Cando.ini", "Wait =\n  (AND (P VisitorFar) (D Visitr BIG));\n");
  const std::string msg = "unknown datum 'Visitr' (not in " + (base_ / "ctof.txt").string() + ", " +
                          (base_ / "../extra/ctof.txt").string() + ")";
  const auto d = one_diagnostic(extra_ / "Cando.ini", 2);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, msg);
  EXPECT_EQ(load_error(extra_ / "Cando.ini", 2), msg);
}

// Another package's files by package path (FollowMe names Roby's rule base
// so, in a source tree, a devel and an install space alike): extra/ as the
// package "extra_rules", found through the finder (ROS_PACKAGE_PATH when
// none is given), in BrianConfigs.ini and in a behaviour list.
TEST_F(MultiFileTest, PackagePathsResolveThroughTheFinder) {
  write(extra_ / "behavior.txt", "(level 2 Wait package://extra_rules/wait.rul)\n");
  write(list(), "ctof.txt package://extra_rules/ctof.txt\n"
                "shape_ctof.txt package://extra_rules/shape_ctof.txt\n"
                "Predicate.ini package://extra_rules/Predicate.ini\n"
                "PredicateActions.ini\n"
                "Cando.ini package://extra_rules/Cando.ini\n"
                "behavior.txt package://extra_rules/behavior.txt\n"
                "want.txt package://extra_rules/want.txt\n"
                "s_ftoc.txt\n"
                "s_shape.txt\n");
  const mrt::common::PackageFinder finder = [&](const std::string& n) {
    return n == "extra_rules" ? extra_.string() : std::string();
  };
  const ConfigFiles f = ConfigFiles::from_list_file(list(), finder);
  ASSERT_EQ(f.more[static_cast<std::size_t>(Slot::kPredicates)].size(), 1u);
  EXPECT_EQ(f.more[static_cast<std::size_t>(Slot::kPredicates)][0], (extra_ / "Predicate.ini").string());
  BrianOptions o;
  o.packages = finder;
  const auto b = Brian::from_path(list(), o);
  ASSERT_EQ(b->engine().size(), 2);
  // As in TwoFilesForOneSlotLoadTheUnion: Visitor 150 stops the robot.
  EXPECT_NEAR(speed(b->run({{"Obstacle", 150, 1}, {"Visitor", 150, 1}})), 0.0, 1e-9);
  // A package nobody knows: the list file's line and column, and its name.
  const mrt::common::PackageFinder none = [](const std::string&) { return std::string(); };
  try {
    ConfigFiles::from_list_file(list(), none);
    ADD_FAILURE() << "no error for an unknown package";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_EQ(e.column(), 10);
    EXPECT_NE(e.message().find("package 'extra_rules'"), std::string::npos) << e.what();
  }
}
