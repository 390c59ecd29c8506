// The crisp input file of brian_run (same as the reference traces'
// input.txt): `NAME VALUE [RELIABILITY]` a line (reliability 1 when
// omitted), `#` comments, `---` ends a cycle.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/types.h"

namespace mrt::brian {

/// One crisp data list per cycle; throws mrt::common::ParseError with file
/// and line on a malformed line (not a number, reliability outside [0, 1],
/// extra fields).
std::vector<CrispDataList> parse_crisp_input(const std::string& text, const std::string& file);

}  // namespace mrt::brian
