// libFuzzer target for every Mr. BRIAN parser (built with clang only): the
// first byte selects the parser, the rest is the file. Only ParseError may
// escape a parser.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_brian/behavior_list_parser.h"
#include "mrt_brian/crisp_input.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_brian/rule_parser.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  using namespace mrt::brian;
  try {
    switch (data[0] % 6) {
      case 0: parse_shapes(text, "f"); break;
      case 1: parse_associations(text, "f"); break;
      case 2: parse_definitions(text, "f"); break;
      case 3: parse_rules(text, "f"); break;
      case 4: parse_behavior_list(text, "f"); break;
      default: parse_crisp_input(text, "f"); break;
    }
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
