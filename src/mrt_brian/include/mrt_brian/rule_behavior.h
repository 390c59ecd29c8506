// Rules behaviour (manual §10.3.7): a fuzzy rule base read from a .rul file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_brian/behavior.h"
#include "mrt_brian/config_ast.h"
#include "mrt_brian/expression_compiler.h"

namespace mrt::brian {

class RuleBehavior : public Behavior {
 public:
  /// Compiles the rules; throws mrt::common::ParseError naming `file` for an
  /// action or label missing from the Defuzzyfier's files.
  RuleBehavior(std::string name, int level, const std::vector<RuleDef>& rules, const std::string& file,
               const ExpressionCompiler& compiler, const Defuzzyfier& defuzzyfier, ExpressionPool& pool);
  void run(BehaviorContext& ctx) const override;
  std::size_t max_proposals() const override { return max_proposals_; }
  bool deletes() const override { return deletes_; }

 private:
  struct Action {
    bool del = false;
    int action = 0;
    int label = -1;                    // proposals
    bool any = true;                   // deletions: ANY
    std::vector<std::uint8_t> mask;    // deletions: selected labels
  };
  struct Rule {
    int root = 0;
    int line = 0;
    std::vector<Action> actions;
  };
  std::vector<Rule> rules_;
  std::size_t max_proposals_ = 0;
  bool deletes_ = false;
};

}  // namespace mrt::brian
