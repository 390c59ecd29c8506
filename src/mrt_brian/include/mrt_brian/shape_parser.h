// Parsers of the shape files (shape_ctof.txt, s_shape.txt) and of the
// association files (ctof.txt, s_ftoc.txt), manual §10.4.1 and §10.4.6.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"

namespace mrt::brian {

/// Throws mrt::common::ParseError (file:line:column) on a syntax error, an
/// unknown set type or a wrong number of values.
std::vector<ShapeDef> parse_shapes(const std::string& text, const std::string& file);
std::vector<AssociationDef> parse_associations(const std::string& text, const std::string& file);

}  // namespace mrt::brian
