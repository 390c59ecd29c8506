// libFuzzer target (clang only): parse_definitions on arbitrary bytes; only ParseError
// may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_brian/predicate_parser.h"
#include "mrt_common/parse_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    mrt::brian::parse_definitions(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
