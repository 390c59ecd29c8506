// Private: the per-cycle utility tables the allocation searches share.
#pragma once

#include <limits>
#include <vector>

#include "mrt_scare/allocator.h"

namespace mrt::scare {

constexpr double kNone = -std::numeric_limits<double>::infinity();

struct Allocator::Tables {
  int n = 0;
  std::vector<std::vector<double>> u;  // [robot][slot]: utility + tie-break term, kNone if not on the agenda
  std::vector<char> on_agenda;         // per activity
};

}  // namespace mrt::scare
