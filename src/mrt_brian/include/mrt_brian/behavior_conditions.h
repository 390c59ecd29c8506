// The condition of each behaviour, one `Behaviour = expr;` per behaviour:
// what Candoer (CANDO, §10.3.4) and Wanter (WANT, §10.3.5) both evaluate.
#pragma once

#include <algorithm>
#include <vector>

#include "mrt_brian/preacher.h"

namespace mrt::brian {

class BehaviorConditions {
 public:
  BehaviorConditions() = default;
  BehaviorConditions(const ExpressionPool* pool, DefinitionList defs) : pool_(pool), defs_(std::move(defs)) {}
  /// out[behaviour] = value of its condition; behaviours without one read <0, 1>.
  void evaluate(const EvalState& s, std::vector<FuzzyValue>& out) const {
    std::fill(out.begin(), out.end(), FuzzyValue{});
    defs_.evaluate(*pool_, s, out.data());
  }

 private:
  const ExpressionPool* pool_ = nullptr;
  DefinitionList defs_;
};

}  // namespace mrt::brian
