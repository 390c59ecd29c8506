// No input crashes the engine: deterministic mutations of the shipped rule
// bases (bytes flipped, inserted, deleted, lines duplicated) are parsed,
// built and run in both profiles; only ParseError may come out. Runs the
// same entry points as the libFuzzer targets under gcc (and ASan/UBSan with
// -DMRT_BRIAN_SANITIZE=ON).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "mrt_brian/brian.h"
#include "mrt_brian/checker.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/lexer.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;
namespace fs = std::filesystem;

namespace {

struct Rng {
  unsigned s;
  unsigned operator()(unsigned n) {
    s = s * 1103515245u + 12345u;
    return n ? (s >> 8) % n : 0;
  }
};

std::string mutate(std::string t, Rng& r) {
  const char alphabet[] = "()=;>#&*.- \n\tANDORNOTDP0123456789xyzHIGH\xC2\xA0";
  const int edits = 1 + static_cast<int>(r(4));
  for (int e = 0; e < edits; ++e) {
    const std::size_t pos = t.empty() ? 0 : r(static_cast<unsigned>(t.size()));
    switch (r(4)) {
      case 0: if (!t.empty()) t[pos] = alphabet[r(sizeof alphabet - 1)]; break;
      case 1: t.insert(pos, 1, alphabet[r(sizeof alphabet - 1)]); break;
      case 2: if (!t.empty()) t.erase(pos, 1 + r(8)); break;
      default: t.insert(pos, t.substr(pos, r(40))); break;
    }
  }
  return t;
}

void run_all(const fs::path& dir) {
  for (Profile p : {Profile::kManual, Profile::kLegacy}) {
    try {
      BrianOptions o;
      o.profile = p;
      Brian b(ConfigFiles::from_directory(dir.string()), o);
      CycleTrace t;
      b.run({{"x", 25.0, 1.0}, {"y", 30.0, 0.45}, {"Obstacle", 40, 0.5}}, &t);
      b.run({}, &t);
      t.lines(true);
    } catch (const mrt::common::ParseError&) {
    }
  }
  Checker().check_path(dir.string());
}

}  // namespace

TEST(Robustness, MutatedRuleBasesNeverCrash) {
  const fs::path src = fs::path(MRT_BRIAN_TEST_DATA) / "synth";
  const fs::path dir = fs::temp_directory_path() / ("brian_robust_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& e : fs::directory_iterator(src))
    if (e.path().filename() != "expected.trace") files.emplace_back(e.path().filename().string(), read_text_file(e.path().string()));
  for (const auto& f : files) std::ofstream(dir / f.first) << f.second;
  Rng r{2024};
  for (int round = 0; round < 300; ++round) {
    const auto& victim = files[r(static_cast<unsigned>(files.size()))];
    std::ofstream(dir / victim.first) << mutate(victim.second, r);
    ASSERT_NO_FATAL_FAILURE(run_all(dir));
    std::ofstream(dir / victim.first) << victim.second;
  }
  fs::remove_all(dir);
}

TEST(Robustness, HostileCrispInput) {
  BrianOptions o;
  o.profile = Profile::kLegacy;
  auto b = Brian::from_path(std::string(MRT_BRIAN_TEST_DATA) + "/isaac/bin/BrianConfigs.ini", o);
  auto m = Brian::from_path(std::string(MRT_BRIAN_TEST_DATA) + "/isaac/bin/BrianConfigs.ini");
  const double big = 1e308;
  CrispDataList l = {{"DistanceNorth", big, 1}, {"DistanceSouth", -big, 0}, {"TowerPosition", 1e-300, 1},
                     {"RandomSearch", 50, 0.0}, {"Unknown", 1, 1},      {"DistanceNorth", 3, 0.5}};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NO_THROW(b->run(l));
    EXPECT_NO_THROW(m->run(l));
  }
  EXPECT_THROW(parse_crisp_input("x nan\n", "in"), mrt::common::ParseError);
  EXPECT_THROW(parse_crisp_input("x 1e999\n", "in"), mrt::common::ParseError);
}

TEST(Robustness, DeepNestingIsAnError) {
  std::string deep = "A = ";
  for (int i = 0; i < 100000; ++i) deep += "(NOT ";
  EXPECT_THROW(parse_definitions(deep, "P"), mrt::common::ParseError);
}

// A flat AND of 100 000 operands is one n-ary node: it compiles and
// evaluates without recursion. Operands: (D X HIGH) with X = 0.7 on
// (TOR (HIGH 0 1)) -> 0.7, and once (D X LOW) -> 1 - 0.7 = 0.3 in the middle:
// AND = min = 0.3; OR over the same operands = max = 0.7.
TEST(Robustness, FlatAndOfAHundredThousandOperands) {
  const fs::path d = fs::temp_directory_path() / ("brian_flat_" + std::to_string(::getpid()));
  fs::create_directories(d);
  std::string ops;
  for (int i = 0; i < 100000; ++i) ops += i == 50000 ? "(D X LOW)" : "(D X HIGH)";
  std::ofstream(d / "shape_ctof.txt") << "(S (TOR (HIGH 0 1)) (TOL (LOW 0 1)))\n";
  std::ofstream(d / "ctof.txt") << "(X S)\n";
  std::ofstream(d / "Predicate.ini") << "All = (AND " << ops << ");\nAny = (OR " << ops << ");\n";
  std::ofstream(d / "Cando.ini") << "B = (P All);\nC = (P Any);\n";
  std::ofstream(d / "want.txt") << "B = (P All);\nC = (P Any);\n";
  std::ofstream(d / "behavior.txt") << "(level 1 B b.rul)\n(level 1 C c.rul)\n";
  std::ofstream(d / "b.rul") << "(All) => (Out LO);\n";
  std::ofstream(d / "c.rul") << "(Any) => (Out2 HI);\n";
  std::ofstream(d / "s_shape.txt") << "(O (SNG (LO 0)) (SNG (HI 1)))\n";
  std::ofstream(d / "s_ftoc.txt") << "(Out O)\n(Out2 O)\n";
  BrianOptions o;
  o.threshold = 0.2;
  auto brian = Brian::from_path(d.string(), o);
  CycleTrace t;
  brian->run({{"X", 0.7, 1.0}}, &t);
  std::map<std::string, double> pred;
  for (const auto& p : t.predicates) pred[p.name] = p.v.value;
  EXPECT_NEAR(pred["All"], 0.3, 1e-12);
  EXPECT_NEAR(pred["Any"], 0.7, 1e-12);
  fs::remove_all(d);
}

// 10 000 nested NOTs are rejected with a clear error at the 257th level,
// never a stack overflow.
TEST(Robustness, TenThousandNestedNotsAreRejectedClearly) {
  std::string deep = "A = ";
  for (int i = 0; i < 10000; ++i) deep += "(NOT ";
  deep += "(D X HIGH)";
  for (int i = 0; i < 10000; ++i) deep += ")";
  deep += ";\n";
  try {
    parse_definitions(deep, "Predicate.ini");
    FAIL() << "expected a ParseError";
  } catch (const mrt::common::ParseError& e) {
    EXPECT_EQ(e.file(), "Predicate.ini");
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("nested deeper than 256 levels"), std::string::npos) << e.what();
  }
}
