#include "mrt_brian/composer.h"

namespace mrt::brian {

std::unique_ptr<WeightComposer> WeightComposer::make(WeightComposerKind k) {
  switch (k) {
    case WeightComposerKind::kMax: return std::make_unique<MaxWeightComposer>();
    case WeightComposerKind::kMin: return std::make_unique<MinWeightComposer>();
    case WeightComposerKind::kMult: break;
  }
  return std::make_unique<MultWeightComposer>();
}

std::unique_ptr<FloatComposer> FloatComposer::make(FloatComposerKind k) {
  switch (k) {
    case FloatComposerKind::kMax: return std::make_unique<MaxFloatComposer>();
    case FloatComposerKind::kMin: return std::make_unique<MinFloatComposer>();
    case FloatComposerKind::kAverage:
    case FloatComposerKind::kSelectBest: break;
  }
  return std::make_unique<AverageFloatComposer>();
}

Composer::Composer(WeightComposerKind w, FloatComposerKind f, const std::vector<int>& labels)
    : weight_(WeightComposer::make(w)), float_(FloatComposer::make(f)), select_best_(f == FloatComposerKind::kSelectBest) {
  for (int n : labels) {
    first_.push_back(slots_);
    slots_ += n;
  }
}

void Composer::weight_in_place(ProposalList& proposals, const std::vector<double>& weights) const {
  for (Proposal& p : proposals)
    p.value = weight_->compose(p.value, weights[static_cast<std::size_t>(p.owner)]);
}

ComposedActions Composer::make_output() const {
  ComposedActions out;
  out.first = first_;
  out.value.assign(static_cast<std::size_t>(slots_), 0.0);
  out.count.assign(static_cast<std::size_t>(slots_), 0);
  return out;
}

void Composer::compose(const ProposalList& proposals, const std::vector<double>* weights, ComposedActions& out,
                       const std::vector<double>* scores) const {
  if (out.value.size() != static_cast<std::size_t>(slots_)) out = make_output();
  std::fill(out.value.begin(), out.value.end(), 0.0);
  std::fill(out.count.begin(), out.count.end(), 0);
  int best = -1;
  if (select_best_) {
    double best_score = 0.0;
    for (const Proposal& p : proposals) {
      const double sc = scores ? (*scores)[static_cast<std::size_t>(p.owner)] : 0.0;
      if (sc > best_score) { best_score = sc; best = p.owner; }
    }
    if (best < 0) return;
  }
  for (const Proposal& p : proposals) {
    if (select_best_ && p.owner != best) continue;
    const double w = weights ? (*weights)[static_cast<std::size_t>(p.owner)] : 1.0;
    if (skip_zero_weight_ && weights && w == 0.0) continue;
    const double v = select_best_ ? p.value : weights ? weight_->compose(p.value, w) : p.value;
    const std::size_t s = static_cast<std::size_t>(first_[static_cast<std::size_t>(p.action)] + p.label);
    out.value[s] = out.count[s] == 0 ? v : float_->combine(out.value[s], v);
    ++out.count[s];
  }
  for (std::size_t s = 0; s < out.value.size(); ++s)
    if (out.count[s] > 0) out.value[s] = float_->finish(out.value[s], out.count[s]);
}

}  // namespace mrt::brian
