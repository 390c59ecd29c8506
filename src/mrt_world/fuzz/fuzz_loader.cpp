// libFuzzer target of the world-file loader: any input must either load or
// throw mrt::common::ParseError; anything else (another exception, a crash,
// a sanitizer report) is a bug. Built by the sanitizer stage
// (mrt_add_fuzz_target), seeded with worlds/ and test/data/.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_world/world_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    mrt::world::parse_world(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
