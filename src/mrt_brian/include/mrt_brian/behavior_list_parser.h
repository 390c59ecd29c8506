// Parser of the behaviour list (behavior.txt, manual §10.4.8):
// `(level <n> <Name> <path>)` per behaviour.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"

namespace mrt::brian {

std::vector<BehaviorDef> parse_behavior_list(const std::string& text, const std::string& file);

}  // namespace mrt::brian
