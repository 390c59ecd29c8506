// Parser of a rules behaviour file (.rul, manual §10.4.7):
// `precondition => (Action Label) (&DEL.Action ANY|Label|*sub) ... ;`.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"

namespace mrt::brian {

std::vector<RuleDef> parse_rules(const std::string& text, const std::string& file);

}  // namespace mrt::brian
