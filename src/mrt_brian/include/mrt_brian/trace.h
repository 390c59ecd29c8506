// What happened in one cycle, in the line format of the 2009 engine's
// reference traces (../shared/peer/brian/README.md).
#pragma once

#include <string>
#include <vector>

#include "mrt_brian/types.h"

namespace mrt::brian {

struct CycleTrace {
  struct Fuzzy { std::string datum, label; FuzzyValue v; };
  struct Named { std::string name; FuzzyValue v; };
  struct Rule { std::string behavior; int line; double mu; };
  struct Pact { std::string action, label, behavior; double mu, rel; };
  struct Act { std::string action, label; double mu; };

  CrispDataList crisp;
  std::vector<Fuzzy> fuzzy;
  std::vector<Named> predicates, cando, want;
  std::vector<Rule> rules;
  std::vector<Pact> proposals;
  std::vector<Act> actions;
  CommandList commands;

  /// Empties every list, keeping their storage for the next cycle.
  void clear() {
    crisp.clear();
    fuzzy.clear();
    predicates.clear();
    cando.clear();
    want.clear();
    rules.clear();
    proposals.clear();
    actions.clear();
    commands.clear();
  }
  /// Sorted lines: CMD only, or with `full` also CRISP FUZZY PRED CANDO WANT
  /// RULE PACT ACT.
  std::vector<std::string> lines(bool full) const;
};

}  // namespace mrt::brian
