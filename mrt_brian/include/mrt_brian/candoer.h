// Candoer (manual §10.3.4): the activation (CANDO) value of each behaviour.
#pragma once

#include <algorithm>
#include <vector>

#include "mrt_brian/preacher.h"

namespace mrt::brian {

class Candoer {
 public:
  Candoer() = default;
  Candoer(const ExpressionPool* pool, DefinitionList defs) : pool_(pool), defs_(std::move(defs)) {}
  /// out[behaviour] = CANDO value; behaviours without a condition read <0, 1>.
  void evaluate(const EvalState& s, std::vector<FuzzyValue>& out) const {
    std::fill(out.begin(), out.end(), FuzzyValue{});
    defs_.evaluate(*pool_, s, out.data());
  }

 private:
  const ExpressionPool* pool_ = nullptr;
  DefinitionList defs_;
};

}  // namespace mrt::brian
