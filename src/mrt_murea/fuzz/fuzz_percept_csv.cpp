// libFuzzer target of the percept CSV reader: any input either parses or
// throws ParseError; nothing else (no crash, no other exception, no UB).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_murea/percept_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    for (const auto& f : mrt::murea::read_percept_csv(in, "fuzz.csv"))
      if (f.percepts.size() + f.dropped.total() == 0) __builtin_trap();  // a frame has at least one row
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
