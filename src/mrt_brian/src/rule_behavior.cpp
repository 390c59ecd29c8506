#include "mrt_brian/rule_behavior.h"

#include "mrt_common/parse_error.h"

namespace mrt::brian {

using mrt::common::ParseError;

void BehaviorContext::remove(int action, const std::vector<std::uint8_t>* mask) {
  ProposalList& ps = *proposals;
  std::size_t w = 0;
  for (std::size_t r = 0; r < ps.size(); ++r) {
    const Proposal& p = ps[r];
    const bool victim = p.action == action && p.owner != owner &&
                        (profile == Profile::kLegacy || p.level < level) &&
                        (!mask || (*mask)[static_cast<std::size_t>(p.label)]);
    if (!victim) ps[w++] = p;
  }
  ps.resize(w);
}

RuleBehavior::RuleBehavior(std::string name, int level, const std::vector<RuleDef>& rules,
                           const std::string& file, const ExpressionCompiler& compiler,
                           const Defuzzyfier& defuzzyfier, ExpressionPool& pool)
    : Behavior(std::move(name), level) {
  for (const auto& def : rules) {
    Rule r;
    r.line = def.line;
    r.root = compiler.compile(def.precondition, pool);
    for (const auto& ad : def.actions) {
      Action a;
      a.del = ad.del;
      a.action = defuzzyfier.action_id(ad.action);
      if (a.action < 0)
        throw ParseError(file, ad.line, ad.column, "unknown action '" + ad.action + "' (not in s_ftoc)");
      if (ad.del) {
        deletes_ = true;
        if (ad.label != "ANY") {
          a.any = false;
          const int n = defuzzyfier.label_count(a.action);
          a.mask.assign(static_cast<std::size_t>(n), 0);
          if (ad.label[0] == '*') {
            const std::string sub = ad.label.substr(1);
            for (int l = 0; l < n; ++l)
              if (defuzzyfier.label_name(a.action, l).find(sub) != std::string::npos) a.mask[static_cast<std::size_t>(l)] = 1;
          } else {
            const int l = defuzzyfier.label_id(a.action, ad.label);
            if (l < 0)
              throw ParseError(file, ad.line, ad.column,
                               "unknown label '" + ad.label + "' of action '" + ad.action + "' (not in s_shape)");
            a.mask[static_cast<std::size_t>(l)] = 1;
          }
        }
      } else {
        a.label = defuzzyfier.label_id(a.action, ad.label);
        if (a.label < 0)
          throw ParseError(file, ad.line, ad.column,
                           "unknown label '" + ad.label + "' of action '" + ad.action + "' (not in s_shape)");
        ++max_proposals_;
      }
      r.actions.push_back(std::move(a));
    }
    rules_.push_back(std::move(r));
  }
}

void RuleBehavior::run(BehaviorContext& ctx) const {
  for (const Rule& r : rules_) {
    const FuzzyValue pre = ctx.evaluate(r.root);
    double value = 0.0;
    if (!ctx.fires(pre, &value)) continue;
    ctx.record(r.line, value);
    for (const Action& a : r.actions) {
      if (a.del) ctx.remove(a.action, a.any ? nullptr : &a.mask);
      else ctx.propose(a.action, a.label, value, pre.reliability);
    }
  }
}

}  // namespace mrt::brian
