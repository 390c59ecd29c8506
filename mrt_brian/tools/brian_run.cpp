// brian_run [--profile manual|legacy] [--trace | --time] <dir | BrianConfigs.ini> <input-file>
// Runs Mr. BRIAN on a crisp input file and prints, per cycle, "=== CYCLE n",
// an empty line and the sorted CMD lines (with --trace all trace lines), in
// the format of the 2009 engine's reference traces. With --time it prints
// instead the engine's own time per cycle on that input (the id-based
// interface, no parsing, no name lookups, no printing).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "mrt_brian/brian.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/lexer.h"
#include "mrt_common/parse_error.h"

namespace {

using mrt::brian::Brian;
using mrt::brian::CrispDataList;

// The engine alone on `cycles`, repeated for at least 0.5 s (and 3 times):
// names resolved to ids beforehand, so the loop is what a robot's control
// loop would call. Prints `engine_us_per_cycle: X us` and the counts.
void time_engine(Brian& brian, const std::vector<CrispDataList>& cycles) {
  struct Input { int id; double value, reliability; };
  std::vector<std::vector<Input>> ids(cycles.size());
  for (std::size_t n = 0; n < cycles.size(); ++n)
    for (const auto& c : cycles[n]) ids[n].push_back({brian.input_id(c.name), c.value, c.reliability});
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  long reps = 0;
  double seconds = 0.0;
  do {
    for (const auto& cycle : ids) {
      brian.clear_inputs();
      for (const Input& in : cycle) brian.set_input(in.id, in.value, in.reliability);
      brian.run_cycle();
    }
    ++reps;
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } while (!cycles.empty() && (seconds < 0.5 || reps < 3));
  const double n = static_cast<double>(reps) * static_cast<double>(cycles.size());
  std::printf("engine_us_per_cycle: %.3f us\ncycles: %zu count\nrepetitions: %ld count\n",
              n > 0 ? seconds * 1e6 / n : 0.0, cycles.size(), reps);
}

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "brian_run: %s\n", msg);
  std::fprintf(stderr,
               "usage: brian_run [--profile manual|legacy] [--trace | --time] [--threshold T]\n"
               "                 [--weight mult|max|min] [--float average|max|min|best]\n"
               "                 [--defuzz singleton|barycenter] <dir | BrianConfigs.ini> <input-file>\n");
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace mrt::brian;
  BrianOptions opt;
  bool trace = false, timing = false;
  std::string config, input;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        return argv[++i];
      };
      if (a == "--trace") trace = true;
      else if (a == "--time") timing = true;
      else if (a == "--profile") opt.profile = parse_profile(value());
      else if (a == "--threshold") opt.threshold = std::stod(value());
      else if (a == "--weight") opt.weight_composer = parse_weight_composer(value());
      else if (a == "--float") opt.float_composer = parse_float_composer(value());
      else if (a == "--defuzz") opt.defuzzification = parse_defuzz_method(value());
      else if (a == "-h" || a == "--help") return usage(nullptr);
      else if (!a.empty() && a[0] == '-') return usage(("unknown option " + a).c_str());
      else if (config.empty()) config = a;
      else if (input.empty()) input = a;
      else return usage("too many arguments");
    }
  } catch (const std::exception& e) {
    return usage(e.what());
  }
  if (config.empty() || input.empty()) return usage("expected a configuration and an input file");
  try {
    auto brian = Brian::from_path(config, opt);
    const auto cycles = parse_crisp_input(read_text_file(input), input);
    if (timing) {
      time_engine(*brian, cycles);
      return 0;
    }
    CycleTrace t;
    std::string out;
    for (std::size_t n = 0; n < cycles.size(); ++n) {
      brian->run(cycles[n], &t);
      out += "=== CYCLE " + std::to_string(n) + "\n\n";
      for (const auto& l : t.lines(trace)) out += l + "\n";
    }
    std::fwrite(out.data(), 1, out.size(), stdout);
  } catch (const mrt::common::ParseError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {  // e.g. std::filesystem::filesystem_error, std::bad_alloc
    std::fprintf(stderr, "brian_run: %s\n", e.what());
    return 2;
  }
  return 0;
}
