// "No heap allocation per cycle in steady state" (issue 3's benchmark
// target), checked: this executable replaces the global operator new and
// counts its calls, then runs many cycles of the allocation-free interface
// (input_id / clear_inputs / set_input / run_cycle / command) on the IsAac
// rule base and on a generated rule base that uses every engine feature
// (&DEL of ANY, a label and a *substring, predicate actions, &B.A.L
// predicates, an angle output whose labels can cancel out), in both
// profiles and with both defuzzification methods. Its own executable, so
// that the replacement does not disturb the other tests.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include "mrt_brian/brian.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/lexer.h"

namespace {
std::atomic<std::size_t> g_news{0};

void* counted_alloc(std::size_t n) {
  ++g_news;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* counted_aligned_alloc(std::size_t n, std::align_val_t al) {
  ++g_news;
  const std::size_t a = static_cast<std::size_t>(al);
  if (void* p = std::aligned_alloc(a, (n + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void* operator new(std::size_t n, std::align_val_t a) { return counted_aligned_alloc(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return counted_aligned_alloc(n, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

using namespace mrt::brian;
namespace fs = std::filesystem;

namespace {

struct IdInput {
  int id;
  double value, reliability;
};
using Cycles = std::vector<std::vector<IdInput>>;

Cycles resolve(const Brian& b, const std::vector<CrispDataList>& cycles) {
  Cycles out;
  for (const auto& c : cycles) {
    out.emplace_back();
    for (const auto& d : c) out.back().push_back({b.input_id(d.name), d.value, d.reliability});
  }
  return out;
}

struct Counts {
  std::size_t allocations = 0;
  std::size_t cycles = 0;
  std::size_t commands = 0;  // commands produced (the runs must do something)
};

// Warm-up pass, then `passes` passes over all cycles, counting operator new.
Counts steady_state(Brian& b, const Cycles& cycles, int passes) {
  Counts n;
  double v = 0.0;
  auto one = [&](const std::vector<IdInput>& c) {
    b.clear_inputs();
    for (const auto& d : c) b.set_input(d.id, d.value, d.reliability);
    b.run_cycle();
    for (int a = 0; a < b.defuzzyfier().action_count(); ++a)
      if (b.command(a, &v)) ++n.commands;
  };
  for (const auto& c : cycles) one(c);
  n.commands = 0;
  const std::size_t before = g_news.load();
  for (int p = 0; p < passes; ++p)
    for (const auto& c : cycles) {
      one(c);
      ++n.cycles;
    }
  n.allocations = g_news.load() - before;
  return n;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// 20 inputs, 12 behaviours on 3 levels, 10 rules each; every feature of
// the engine appears. Output sets are triangles so that both
// defuzzification methods apply.
fs::path generate_base() {
  const fs::path d = fs::temp_directory_path() / ("brian_alloc_" + std::to_string(::getpid()));
  fs::create_directories(d);
  unsigned state = 4242;
  auto rnd = [&](unsigned n) {
    state = state * 1103515245u + 12345u;
    return (state >> 16) % n;
  };
  const char* in_labels[] = {"LOW", "MID", "HIGH"};
  const char* speed_labels[] = {"STOP", "SLOW", "FAST", "VERY_FAST"};
  const char* angle_labels[] = {"N", "E", "S", "W"};
  write(d / "shape_ctof.txt",
        "(S (TOL (LOW 20 40)) (TRA (MID 20 40 60 80)) (TOR (HIGH 60 80)))\n"
        "(PS (TOL (LOW 5 15)) (TRI (MID 5 15 25)) (TOR (HIGH 15 25)))\n");
  write(d / "s_shape.txt",
        "(SPD (TRI (STOP -10 0 10)) (TRI (SLOW 0 10 20)) (TRI (FAST 10 20 30)) (TRI (VERY_FAST 20 30 40)))\n"
        "(ANG (CIRCULAR 0 360) (TRI (N -30 0 30)) (TRI (E 60 90 120)) (TRI (S 150 180 210)) (TRI (W 240 270 300)))\n");
  write(d / "s_ftoc.txt", "(Speed SPD)\n(SpeedAngle ANG)\n");
  std::string ctof, pred, cando, want, blist;
  for (int i = 0; i < 20; ++i) {
    ctof += "(X" + std::to_string(i) + " S)\n";
    for (const char* l : in_labels) pred += "X" + std::to_string(i) + "_" + l + " = (D X" + std::to_string(i) + " " + l + ");\n";
  }
  ctof += "(ProposedSpeed PS)\n";
  write(d / "ctof.txt", ctof);
  write(d / "Predicate.ini", pred);
  write(d / "PredicateActions.ini", "GoingFast = (D ProposedSpeed HIGH);\nGoingSlow = (D ProposedSpeed LOW);\n");
  auto atom = [&](int level) -> std::string {
    if (level > 1) {
      switch (rnd(5)) {
        case 0: return rnd(2) ? "(GoingFast)" : "(GoingSlow)";
        case 1: return "(&B0.Speed." + std::string(speed_labels[rnd(4)]) + ")";
        default: break;
      }
    }
    return "(X" + std::to_string(rnd(20)) + "_" + in_labels[rnd(3)] + ")";
  };
  for (int b = 0; b < 12; ++b) {
    const int level = b % 3 + 1;
    const std::string name = "B" + std::to_string(b);
    blist += "(level " + std::to_string(level) + " " + name + " " + name + ".rul)\n";
    cando += name + " = (OR (P X" + std::to_string(rnd(20)) + "_MID) (P X" + std::to_string(rnd(20)) + "_HIGH));\n";
    want += name + " = (NOT (P X" + std::to_string(rnd(20)) + "_LOW));\n";
    std::string rul;
    for (int r = 0; r < 10; ++r) {
      rul += "(AND " + atom(level) + " (OR " + atom(level) + " (NOT " + atom(level) + "))) =>";
      if (level > 1 && r % 3 == 0) {
        const char* del[] = {"(&DEL.Speed ANY)", "(&DEL.Speed FAST)", "(&DEL.Speed *FAST)", "(&DEL.SpeedAngle E)"};
        rul += std::string(" ") + del[rnd(4)];
      }
      rul += std::string(" (Speed ") + speed_labels[rnd(4)] + ") (SpeedAngle " + angle_labels[rnd(4)] + ");\n";
    }
    write(d / (name + ".rul"), rul);
  }
  write(d / "Cando.ini", cando);
  write(d / "want.txt", want);
  write(d / "behavior.txt", blist);
  return d;
}

class TempCleanup : public ::testing::Environment {
 public:
  void TearDown() override { fs::remove_all(fs::temp_directory_path() / ("brian_alloc_" + std::to_string(::getpid()))); }
};
const auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new TempCleanup);

std::string name(Profile p, DefuzzMethod m) {
  return std::string(p == Profile::kLegacy ? "legacy" : "manual") +
         (m == DefuzzMethod::kBarycenter ? "/barycenter" : "/singleton");
}

}  // namespace

// The counter sees allocations (otherwise the zeros below would prove nothing).
TEST(Allocations, CounterCountsOperatorNew) {
  const std::size_t before = g_news.load();
  auto* p = new std::vector<double>(100);
  static double* volatile sink;
  sink = p->data();
  delete p;
  EXPECT_GE(g_news.load() - before, 2u);
  (void)sink;
}

TEST(Allocations, IsaacSteadyStateAllocatesNothing) {
  const std::string data = MRT_BRIAN_TEST_DATA;
  const auto inputs = parse_crisp_input(read_text_file(data + "/isaac/input.txt"), "input.txt");
  ASSERT_GT(inputs.size(), 300u);
  for (Profile p : {Profile::kLegacy, Profile::kManual}) {
    BrianOptions opt;
    opt.profile = p;
    Brian b(ConfigFiles::from_list_file(data + "/isaac/bin/BrianConfigs.ini"), opt);
    const Counts n = steady_state(b, resolve(b, inputs), 5);
    EXPECT_EQ(n.allocations, 0u) << name(p, DefuzzMethod::kSingleton) << " over " << n.cycles << " cycles";
    EXPECT_GT(n.commands, n.cycles) << name(p, DefuzzMethod::kSingleton);
    // The string-keyed run() with a trace is not allocation-free (it fills
    // names): the same counter must see that.
    CycleTrace t;
    const std::size_t before = g_news.load();
    b.run(inputs[0], &t);
    EXPECT_GT(g_news.load() - before, 0u);
  }
}

TEST(Allocations, GeneratedBaseSteadyStateAllocatesNothing) {
  const fs::path dir = generate_base();
  std::vector<CrispDataList> inputs(60);
  unsigned s = 99;
  for (auto& c : inputs)
    for (int i = 0; i < 20; ++i) {
      s = s * 1103515245u + 12345u;
      c.push_back({"X" + std::to_string(i), static_cast<double>((s >> 16) % 1000) / 10.0, 0.5 + ((s >> 8) % 6) / 10.0});
    }
  for (Profile p : {Profile::kManual, Profile::kLegacy})
    for (DefuzzMethod m : {DefuzzMethod::kSingleton, DefuzzMethod::kBarycenter}) {
      BrianOptions opt;
      opt.profile = p;
      opt.defuzzification = m;
      Brian b(ConfigFiles::from_directory(dir.string()), opt);
      ASSERT_EQ(b.engine().size(), 12);
      const Counts n = steady_state(b, resolve(b, inputs), 20);
      EXPECT_EQ(n.allocations, 0u) << name(p, m) << " over " << n.cycles << " cycles";
      EXPECT_GT(n.commands, 0u) << name(p, m);
    }
}
