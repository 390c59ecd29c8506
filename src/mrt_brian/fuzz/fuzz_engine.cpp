// libFuzzer target for the engine (built with clang only): the input is a
// crisp input file run through the IsAac rule base in both profiles; then,
// split at NUL bytes, a whole rule base (nine files) built and run.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "mrt_brian/brian.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_common/parse_error.h"

using namespace mrt::brian;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static std::unique_ptr<Brian> legacy, manual;
  if (!legacy) {
    BrianOptions o;
    o.profile = Profile::kLegacy;
    legacy = Brian::from_path(MRT_BRIAN_FUZZ_DATA "/isaac/bin/BrianConfigs.ini", o);
    manual = Brian::from_path(MRT_BRIAN_FUZZ_DATA "/isaac/bin/BrianConfigs.ini");
  }
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    for (const auto& c : parse_crisp_input(text, "in")) {
      legacy->run(c);
      manual->run(c);
    }
  } catch (const mrt::common::ParseError&) {
  }
  // Nine files separated by NUL.
  std::vector<std::string> parts(1);
  for (char ch : text) {
    if (ch == '\0') parts.emplace_back();
    else parts.back() += ch;
  }
  if (parts.size() < 9) return 0;
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("brian_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const char* names[] = {"ctof.txt", "shape_ctof.txt", "Predicate.ini", "PredicateActions.ini", "Cando.ini",
                         "behavior.txt", "want.txt", "s_ftoc.txt", "s_shape.txt"};
  for (int i = 0; i < 9; ++i) std::ofstream(dir / names[i]) << parts[static_cast<std::size_t>(i)];
  std::ofstream(dir / "b.rul") << (parts.size() > 9 ? parts[9] : "");
  try {
    for (Profile p : {Profile::kManual, Profile::kLegacy}) {
      BrianOptions o;
      o.profile = p;
      Brian b(ConfigFiles::from_directory(dir.string()), o);
      CycleTrace t;
      b.run({{"x", 1.0, 1.0}, {"y", 25.0, 0.5}}, &t);
      t.lines(true);
    }
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
