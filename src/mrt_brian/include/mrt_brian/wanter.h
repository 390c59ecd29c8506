// Wanter (manual §10.3.5): the motivation (WANT) value of each behaviour,
// the weight the Composer applies to its proposals.
#pragma once

#include "mrt_brian/behavior_conditions.h"

namespace mrt::brian {

/// out[behaviour] = WANT value (want.txt).
class Wanter : public BehaviorConditions {
 public:
  using BehaviorConditions::BehaviorConditions;
};

}  // namespace mrt::brian
