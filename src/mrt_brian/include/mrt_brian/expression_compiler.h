// Resolves the names of a parsed expression to ids and adds its nodes to an
// ExpressionPool. Unknown data, labels and predicates read <0, 1>, as in the
// 2009 engine (brian_check reports them).
#pragma once

#include "mrt_brian/config_ast.h"
#include "mrt_brian/defuzzyfier.h"
#include "mrt_brian/expression.h"
#include "mrt_brian/fuzzyfier.h"
#include "mrt_brian/symbol_table.h"

namespace mrt::brian {

class ExpressionCompiler {
 public:
  ExpressionCompiler(const Fuzzyfier& fuzzyfier, const SymbolTable& predicates,
                     const SymbolTable& behaviors, const Defuzzyfier& defuzzyfier)
      : fuzzyfier_(fuzzyfier), predicates_(predicates), behaviors_(behaviors), defuzzyfier_(defuzzyfier) {}
  /// Root node of the compiled expression.
  int compile(const ExprAst& e, ExpressionPool& pool) const;

 private:
  const Fuzzyfier& fuzzyfier_;
  const SymbolTable& predicates_;
  const SymbolTable& behaviors_;
  const Defuzzyfier& defuzzyfier_;
};

}  // namespace mrt::brian
