// libFuzzer target (clang only): parse_associations on arbitrary bytes; only ParseError
// may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    mrt::brian::parse_associations(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
