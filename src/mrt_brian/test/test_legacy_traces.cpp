// The legacy profile against the 2009 engine's black-box traces
// (test/data/{isaac,synth,synth2}, copied from ../shared/peer/brian):
// every cycle's CMD lines, then every trace line, to 1e-4; the reliability
// column of PACT lines is undefined in the original and not compared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <sstream>

#include "mrt_brian/brian.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/lexer.h"

using namespace mrt::brian;

namespace {

struct Line {
  std::string key;             // kind and the non-numeric fields
  std::vector<double> numbers;
  bool operator<(const Line& o) const { return key < o.key || (key == o.key && numbers < o.numbers); }
};

Line split(const std::string& text) {
  std::istringstream in(text);
  std::string kind, w;
  in >> kind;
  Line l;
  l.key = kind;
  while (in >> w) {
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (end && *end == '\0')
      l.numbers.push_back(v);
    else
      l.key += " " + w;
  }
  if (kind == "PACT" && l.numbers.size() == 2) l.numbers.pop_back();
  return l;
}

using Cycles = std::vector<std::vector<std::string>>;

Cycles read_trace(const std::string& path) {
  Cycles out;
  std::istringstream in(read_text_file(path));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("=== CYCLE", 0) == 0) out.emplace_back();
    else if (!line.empty() && !out.empty()) out.back().push_back(line);
  }
  return out;
}

// Compares the lines of one kind set ("CMD" or everything) of one cycle.
::testing::AssertionResult same(const std::vector<std::string>& ours, const std::vector<std::string>& expected,
                                bool commands_only, std::size_t cycle) {
  std::vector<Line> a, b;
  for (const auto& l : ours)
    if (!commands_only || l.rfind("CMD ", 0) == 0) a.push_back(split(l));
  for (const auto& l : expected)
    if (!commands_only || l.rfind("CMD ", 0) == 0) b.push_back(split(l));
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::ostringstream why;
  if (a.size() != b.size()) why << "cycle " << cycle << ": " << a.size() << " lines, expected " << b.size() << "\n";
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    bool ok = a[i].key == b[i].key && a[i].numbers.size() == b[i].numbers.size();
    for (std::size_t k = 0; ok && k < a[i].numbers.size(); ++k)
      ok = std::abs(a[i].numbers[k] - b[i].numbers[k]) <= 1e-4;
    if (!ok) {
      why << "cycle " << cycle << ": got '" << a[i].key << "'";
      for (double v : a[i].numbers) why << " " << v;
      why << ", expected '" << b[i].key << "'";
      for (double v : b[i].numbers) why << " " << v;
      break;
    }
  }
  if (why.str().empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << why.str();
}

void check(const std::string& dir, const std::string& list, bool commands_only) {
  const std::string base = std::string(MRT_BRIAN_TEST_DATA) + "/" + dir;
  BrianOptions opt;
  opt.profile = Profile::kLegacy;
  auto brian = Brian::from_path(base + "/" + list, opt);
  const auto inputs = parse_crisp_input(read_text_file(base + "/input.txt"), "input.txt");
  const Cycles expected = read_trace(base + "/expected.trace");
  ASSERT_EQ(inputs.size(), expected.size());
  CycleTrace t;
  for (std::size_t c = 0; c < inputs.size(); ++c) {
    brian->run(inputs[c], &t);
    ASSERT_TRUE(same(t.lines(!commands_only), expected[c], commands_only, c));
  }
}

}  // namespace

TEST(LegacyTraces, SynthCommands) { check("synth", "BrianConfigs.ini", true); }
TEST(LegacyTraces, SynthTrace) { check("synth", "BrianConfigs.ini", false); }
TEST(LegacyTraces, Synth2Commands) { check("synth2", "BrianConfigs.ini", true); }
TEST(LegacyTraces, Synth2Trace) { check("synth2", "BrianConfigs.ini", false); }
TEST(LegacyTraces, IsaacCommands) { check("isaac", "bin/BrianConfigs.ini", true); }
TEST(LegacyTraces, IsaacTrace) { check("isaac", "bin/BrianConfigs.ini", false); }
