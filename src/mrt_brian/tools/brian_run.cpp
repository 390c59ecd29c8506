// brian_run [--profile manual|legacy] [--trace | --time] <dir | BrianConfigs.ini> <input-file>
// Runs Mr. BRIAN on a crisp input file and prints, per cycle, "=== CYCLE n",
// an empty line and the sorted CMD lines (with --trace all trace lines), in
// the format of the 2009 engine's reference traces. With --time it prints
// instead the engine's own time per cycle on that input (the id-based
// interface, no parsing, no name lookups, no printing).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "mrt_brian/brian.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/lexer.h"
#include "mrt_common/cli.h"
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

}  // namespace

int main(int argc, char** argv) {
  using namespace mrt::brian;
  BrianOptions opt;
  bool trace = false, timing = false;
  std::string config, input, profile, weight, floating, defuzz;
  CLI::App app{"Runs Mr. BRIAN on a crisp input file and prints, per cycle, \"=== CYCLE n\", an empty\n"
               "line and the sorted CMD lines (the 2009 engine's reference trace format); with --time\n"
               "the engine's own time per cycle instead.",
               "brian_run"};
  app.add_option("--profile", profile, "manual|legacy: the manual's semantics or the 2009 engine's");
  app.add_flag("--trace", trace, "print every trace line, not only the CMD lines");
  app.add_flag("--time", timing, "print engine_us_per_cycle (us) and the counts instead of the trace");
  app.add_option("--threshold", opt.threshold, "activation threshold of the behaviours (0..1)");
  app.add_option("--weight", weight, "mult|max|min: weight composer");
  app.add_option("--float", floating, "average|max|min|best: float composer");
  app.add_option("--defuzz", defuzz, "singleton|barycenter: defuzzification");
  app.add_option("config", config, "configuration directory or its BrianConfigs.ini")->required();
  app.add_option("input", input, "crisp input file (one block of NAME VALUE [RELIABILITY] per cycle)")
      ->required();
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {  // the names given to --profile/--weight/--float/--defuzz: usage errors too
    if (!profile.empty()) opt.profile = parse_profile(profile);
    if (!weight.empty()) opt.weight_composer = parse_weight_composer(weight);
    if (!floating.empty()) opt.float_composer = parse_float_composer(floating);
    if (!defuzz.empty()) opt.defuzzification = parse_defuzz_method(defuzz);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "brian_run: %s\nRun with --help for more information.\n", e.what());
    return mrt::cli::kUsageError;
  }
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
