// Candoer (manual §10.3.4): the activation (CANDO) value of each behaviour.
#pragma once

#include "mrt_brian/behavior_conditions.h"

namespace mrt::brian {

/// out[behaviour] = CANDO value (Cando.ini).
class Candoer : public BehaviorConditions {
 public:
  using BehaviorConditions::BehaviorConditions;
};

}  // namespace mrt::brian
