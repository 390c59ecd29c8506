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

struct ExprNode {
  enum Op : std::uint8_t { kAnd, kOr, kNot, kDatum, kPredicate, kProposal, kZero };
  Op op = kZero;
  int a = -1, b = -1;  // children (kAnd, kOr: both; kNot: a)
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
  FuzzyValue evaluate(int root, const EvalState& s) const;
  std::size_t size() const { return nodes_.size(); }

 private:
  std::vector<ExprNode> nodes_;
};

}  // namespace mrt::brian
