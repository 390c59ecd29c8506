// Compiled predicate expressions (manual §10.3.2): a flat pool of nodes that
// evaluates AND (min, min), OR (max, max) and NOT (1 - value, same
// reliability) over fuzzy data, predicates and current proposals.
#pragma once

#include <cstdint>
#include <vector>

#include "mrt_brian/types.h"

namespace mrt::brian {

/// An action proposed by a behaviour: `<action, label, behaviour, value>`
/// (ids are those of the Defuzzyfier and of the BehaviorEngine).
struct Proposal {
  int action = 0;
  int label = 0;
  int owner = 0;
  int level = 0;
  double value = 0.0;
  double reliability = 1.0;
};
using ProposalList = std::vector<Proposal>;

/// The values an expression reads: one entry per fuzzy slot and per
/// predicate, and the proposals of the behaviours run so far.
struct EvalState {
  std::vector<FuzzyValue> fuzzy;
  std::vector<FuzzyValue> predicates;
  const ProposalList* proposals = nullptr;
};

/// AND and OR are n-ary (their operands are `b` consecutive entries of the
/// pool's child list from `a`): a flat `(AND e1 ... e100000)` is one loop,
/// not a chain of 100 000 nested nodes, so evaluation recurses only as deep
/// as the parser's nesting limit.
struct ExprNode {
  enum Op : std::uint8_t { kAnd, kOr, kAnd2, kOr2, kNot, kDatum, kPredicate, kProposal, kZero };
  Op op = kZero;
  int a = -1, b = -1;  // kAnd, kOr: first child slot and count; kAnd2, kOr2: the two operands; kNot: a
  int ref = -1;        // fuzzy slot, predicate id, or behaviour id (-1: any)
  int action = -1;     // kProposal
  int label = -1;      // kProposal (-1: ANY)
};

class ExpressionPool {
 public:
  int add(const ExprNode& n) {
    nodes_.push_back(n);
    return static_cast<int>(nodes_.size()) - 1;
  }
  /// An AND or OR node over `operands` (node ids); two operands (the
  /// common case) are held in the node itself.
  int add_nary(ExprNode::Op op, const std::vector<int>& operands) {
    ExprNode n;
    if (operands.size() == 2) {
      n.op = op == ExprNode::kAnd ? ExprNode::kAnd2 : ExprNode::kOr2;
      n.a = operands[0];
      n.b = operands[1];
      return add(n);
    }
    n.op = op;
    n.a = static_cast<int>(children_.size());
    n.b = static_cast<int>(operands.size());
    children_.insert(children_.end(), operands.begin(), operands.end());
    return add(n);
  }
  FuzzyValue evaluate(int root, const EvalState& s) const;
  std::size_t size() const { return nodes_.size(); }

 private:
  /// An AND/OR operand: fuzzy data and predicates (most operands) are read
  /// here, anything else through evaluate().
  FuzzyValue operand(int id, const EvalState& s) const {
    const ExprNode& n = nodes_[static_cast<std::size_t>(id)];
    if (n.op == ExprNode::kDatum) return s.fuzzy[static_cast<std::size_t>(n.ref)];
    if (n.op == ExprNode::kPredicate) return s.predicates[static_cast<std::size_t>(n.ref)];
    return evaluate(id, s);
  }

  std::vector<ExprNode> nodes_;
  std::vector<int> children_;
};

}  // namespace mrt::brian
