// Preacher (manual §10.3.2): evaluates the predicates of Predicate.ini (and,
// per level, PredicateActions.ini) in file order: a predicate used before
// its definition reads <0, 1>.
#pragma once

#include <utility>
#include <vector>

#include "mrt_brian/expression.h"

namespace mrt::brian {

/// An ordered list of `target = expression` evaluated into an output array.
class DefinitionList {
 public:
  void add(int target, int root) { items_.emplace_back(target, root); }
  const std::vector<std::pair<int, int>>& items() const { return items_; }
  /// out[target] = value of the expression, in order.
  void evaluate(const ExpressionPool& pool, const EvalState& s, FuzzyValue* out) const {
    for (const auto& [target, root] : items_) out[target] = pool.evaluate(root, s);
  }

 private:
  std::vector<std::pair<int, int>> items_;
};

class Preacher {
 public:
  Preacher() = default;
  Preacher(const ExpressionPool* pool, DefinitionList defs) : pool_(pool), defs_(std::move(defs)) {}
  /// Resets the defined predicates to <0, 1>, then evaluates them in order
  /// into s.predicates.
  void evaluate(EvalState& s) const {
    for (const auto& item : defs_.items()) s.predicates[static_cast<std::size_t>(item.first)] = FuzzyValue{};
    defs_.evaluate(*pool_, s, s.predicates.data());
  }
  /// The 2009 engine's predicate-action step: results join the predicate
  /// list, so an entry evaluated earlier in the cycle is only replaced by a
  /// stored result (an entry <0, 1> is not stored and removes nothing).
  void evaluate_joining(EvalState& s) const {
    for (const auto& [target, root] : defs_.items()) {
      const FuzzyValue v = pool_->evaluate(root, s);
      if (v.stored()) s.predicates[static_cast<std::size_t>(target)] = v;
    }
  }
  const DefinitionList& definitions() const { return defs_; }

 private:
  const ExpressionPool* pool_ = nullptr;
  DefinitionList defs_;
};

}  // namespace mrt::brian
