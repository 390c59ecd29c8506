// Wanter (manual §10.3.5): the motivation (WANT) value of each behaviour,
// the weight the Composer applies to its proposals.
#pragma once

#include <algorithm>
#include <vector>

#include "mrt_brian/preacher.h"

namespace mrt::brian {

class Wanter {
 public:
  Wanter() = default;
  Wanter(const ExpressionPool* pool, DefinitionList defs) : pool_(pool), defs_(std::move(defs)) {}
  /// out[behaviour] = WANT value; behaviours without a condition read <0, 1>.
  void evaluate(const EvalState& s, std::vector<FuzzyValue>& out) const {
    std::fill(out.begin(), out.end(), FuzzyValue{});
    defs_.evaluate(*pool_, s, out.data());
  }

 private:
  const ExpressionPool* pool_ = nullptr;
  DefinitionList defs_;
};

}  // namespace mrt::brian
