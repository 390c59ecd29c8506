// The abstract behaviour (manual §10.3.6): any mapping from predicates and
// lower-level proposals to proposed actions can be plugged into the
// BehaviorEngine by deriving from Behavior.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_brian/expression.h"
#include "mrt_brian/types.h"

namespace mrt::brian {

/// A rule that fired in a cycle (for the trace).
struct RuleFiring {
  int behavior = 0;
  int line = 0;
  double mu = 0.0;
};

/// What a running behaviour reads and writes.
class BehaviorContext {
 public:
  const ExpressionPool* pool = nullptr;
  const EvalState* state = nullptr;
  ProposalList* proposals = nullptr;
  Profile profile = Profile::kManual;
  int owner = 0;  // id of the running behaviour
  int level = 0;  // its level
  std::vector<RuleFiring>* fired = nullptr;  // optional trace

  FuzzyValue evaluate(int root) const { return pool->evaluate(root, *state); }
  FuzzyValue predicate(int id) const { return state->predicates[static_cast<std::size_t>(id)]; }

  /// Whether a rule with this precondition fires and the value its actions
  /// get: manual: value * reliability, when both are non-zero; legacy: the
  /// value, when both are non-zero and the reliability is at least 0.1.
  bool fires(const FuzzyValue& pre, double* value) const {
    if (pre.value == 0.0 || pre.reliability == 0.0) return false;
    if (profile == Profile::kLegacy) {
      if (pre.reliability < 0.1) return false;
      *value = pre.value;
    } else {
      *value = pre.value * pre.reliability;
    }
    return true;
  }
  void propose(int action, int label, double value, double reliability) {
    proposals->push_back({action, label, owner, level, value, reliability});
  }
  /// &DEL: removes the proposals for `action` whose label is selected by
  /// `label_mask` (nullptr: any label). Manual: proposals of lower levels;
  /// legacy: proposals of every other behaviour.
  void remove(int action, const std::vector<std::uint8_t>* label_mask);
  void record(int line, double mu) {
    if (fired) fired->push_back({owner, line, mu});
  }
};

class Behavior {
 public:
  Behavior(std::string name, int level) : name_(std::move(name)), level_(level) {}
  virtual ~Behavior() = default;
  const std::string& name() const { return name_; }
  int level() const { return level_; }
  /// Adds this cycle's proposals (and deletions) through `ctx`.
  virtual void run(BehaviorContext& ctx) const = 0;
  /// Upper bound of the proposals one run adds (to preallocate).
  virtual std::size_t max_proposals() const { return 64; }
  /// Whether the behaviour deletes lower-level proposals (&DEL).
  virtual bool deletes() const { return false; }

 private:
  std::string name_;
  int level_;
};

}  // namespace mrt::brian
