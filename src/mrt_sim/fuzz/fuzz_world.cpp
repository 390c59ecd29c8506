// libFuzzer target for the world-file parser: any input must either load
// or throw mrt::common::ParseError; anything else (another exception, a
// crash, a sanitizer report) is a bug. Build and run (see README):
//   clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined \
//     -Imrt_sim/include -Imrt_common/include mrt_sim/test/fuzz/fuzz_world.cpp \
//     mrt_sim/src/world.cpp mrt_sim/src/kinematics.cpp -lyaml-cpp -o /tmp/fuzz_world
//   /tmp/fuzz_world -max_total_time=60 mrt_sim/test/data mrt_world/worlds
#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_sim/world.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    mrt::sim::parse_world(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
