// Parser of the `Name = expression;` files (manual §10.4.2-10.4.4):
// Predicate.ini, PredicateActions.ini, Cando.ini and want.txt.
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/config_ast.h"
#include "mrt_brian/lexer.h"

namespace mrt::brian {

std::vector<DefinitionDef> parse_definitions(const std::string& text, const std::string& file);

/// One expression starting at '(' (shared with the rule parser).
ExprAst parse_expression(TokenStream& ts);

}  // namespace mrt::brian
