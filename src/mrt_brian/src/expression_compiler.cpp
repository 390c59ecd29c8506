#include "mrt_brian/expression_compiler.h"

#include <vector>

namespace mrt::brian {

int ExpressionCompiler::compile(const ExprAst& e, ExpressionPool& pool) const {
  ExprNode n;
  switch (e.kind) {
    case ExprAst::kAnd:
    case ExprAst::kOr: {
      std::vector<int> operands;
      operands.reserve(e.args.size());
      for (const auto& arg : e.args) operands.push_back(compile(arg, pool));
      return pool.add_nary(e.kind == ExprAst::kAnd ? ExprNode::kAnd : ExprNode::kOr, operands);
    }
    case ExprAst::kNot:
      n.op = ExprNode::kNot;
      n.a = compile(e.args[0], pool);
      return pool.add(n);
    case ExprAst::kDatum:
      n.ref = fuzzyfier_.slot(e.name, e.label);
      n.op = n.ref < 0 ? ExprNode::kZero : ExprNode::kDatum;
      return pool.add(n);
    case ExprAst::kPredicate:
      n.ref = predicates_.find(e.name);
      n.op = n.ref < 0 ? ExprNode::kZero : ExprNode::kPredicate;
      return pool.add(n);
    case ExprAst::kProposal: {
      n.op = ExprNode::kProposal;
      n.ref = e.name == "SOMEBEHAVIOR" ? -1 : behaviors_.find(e.name);
      n.action = defuzzyfier_.action_id(e.action);
      n.label = -1;
      if (n.action >= 0 && e.label != "ANY") n.label = defuzzyfier_.label_id(n.action, e.label);
      if ((e.name != "SOMEBEHAVIOR" && n.ref < 0) || n.action < 0 || (e.label != "ANY" && n.label < 0))
        n.op = ExprNode::kZero;
      return pool.add(n);
    }
  }
  return pool.add(n);
}

}  // namespace mrt::brian
