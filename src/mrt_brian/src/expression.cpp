#include "mrt_brian/expression.h"

#include <algorithm>

namespace mrt::brian {

FuzzyValue ExpressionPool::evaluate(int root, const EvalState& s) const {
  const ExprNode& n = nodes_[static_cast<std::size_t>(root)];
  switch (n.op) {
    case ExprNode::kAnd: {
      const int* c = children_.data() + n.a;
      FuzzyValue acc = operand(c[0], s);
      for (int i = 1; i < n.b; ++i) {
        const FuzzyValue y = operand(c[i], s);
        acc.value = std::min(acc.value, y.value);
        acc.reliability = std::min(acc.reliability, y.reliability);
      }
      return acc;
    }
    case ExprNode::kOr: {
      const int* c = children_.data() + n.a;
      FuzzyValue acc = operand(c[0], s);
      for (int i = 1; i < n.b; ++i) {
        const FuzzyValue y = operand(c[i], s);
        acc.value = std::max(acc.value, y.value);
        acc.reliability = std::max(acc.reliability, y.reliability);
      }
      return acc;
    }
    case ExprNode::kAnd2: {
      const FuzzyValue x = operand(n.a, s), y = operand(n.b, s);
      return {std::min(x.value, y.value), std::min(x.reliability, y.reliability)};
    }
    case ExprNode::kOr2: {
      const FuzzyValue x = operand(n.a, s), y = operand(n.b, s);
      return {std::max(x.value, y.value), std::max(x.reliability, y.reliability)};
    }
    case ExprNode::kNot: {
      const FuzzyValue x = operand(n.a, s);
      return {1.0 - x.value, x.reliability};
    }
    case ExprNode::kDatum:
      return s.fuzzy[static_cast<std::size_t>(n.ref)];
    case ExprNode::kPredicate:
      return s.predicates[static_cast<std::size_t>(n.ref)];
    case ExprNode::kProposal: {
      FuzzyValue out;
      if (!s.proposals) return out;
      bool found = false;
      for (const Proposal& p : *s.proposals) {
        if (p.action != n.action || (n.ref >= 0 && p.owner != n.ref) ||
            (n.label >= 0 && p.label != n.label))
          continue;
        out.value = found ? std::max(out.value, p.value) : p.value;
        found = true;
      }
      return out;
    }
    case ExprNode::kZero:
      break;
  }
  return {};
}

}  // namespace mrt::brian
