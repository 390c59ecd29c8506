// Composer (manual §10.3.8, §10.4.9): weights each behaviour's proposals
// with its WANT value (weight composer), then merges the proposals of one
// <action, label> into one value (float composer).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "mrt_brian/expression.h"

namespace mrt::brian {

enum class WeightComposerKind { kMult, kMax, kMin };
/// kSelectBest: manual eq. 10.5, the actions of the behaviour with the
/// largest CANDO x WANT only (as proposed, not weighted).
enum class FloatComposerKind { kAverage, kMax, kMin, kSelectBest };

class WeightComposer {
 public:
  virtual ~WeightComposer() = default;
  virtual double compose(double value, double weight) const = 0;
  static std::unique_ptr<WeightComposer> make(WeightComposerKind kind);
};
/// mult_weight_composer: value * weight.
class MultWeightComposer : public WeightComposer {
 public:
  double compose(double v, double w) const override { return v * w; }
};
/// max_weight_composer: max(value, weight).
class MaxWeightComposer : public WeightComposer {
 public:
  double compose(double v, double w) const override { return v > w ? v : w; }
};
/// min_weight_composer: min(value, weight).
class MinWeightComposer : public WeightComposer {
 public:
  double compose(double v, double w) const override { return v < w ? v : w; }
};

class FloatComposer {
 public:
  virtual ~FloatComposer() = default;
  /// Folds the next value into the accumulator (first value: acc = v).
  virtual double combine(double acc, double v) const = 0;
  /// The composed value of `n` folded values.
  virtual double finish(double acc, int /*n*/) const { return acc; }
  static std::unique_ptr<FloatComposer> make(FloatComposerKind kind);
};
/// average_float_composer: the mean.
class AverageFloatComposer : public FloatComposer {
 public:
  double combine(double acc, double v) const override { return acc + v; }
  double finish(double acc, int n) const override { return acc / n; }
};
/// max_float_composer.
class MaxFloatComposer : public FloatComposer {
 public:
  double combine(double acc, double v) const override { return v > acc ? v : acc; }
};
/// min_float_composer.
class MinFloatComposer : public FloatComposer {
 public:
  double combine(double acc, double v) const override { return v < acc ? v : acc; }
};

/// The composed actions: one value per <action, label> slot, with a flag
/// telling whether any proposal contributed.
struct ComposedActions {
  std::vector<int> first;  // first slot of each action
  std::vector<double> value;
  std::vector<int> count;
  double get(int action, int label) const { return value[static_cast<std::size_t>(first[static_cast<std::size_t>(action)] + label)]; }
  bool present(int action, int label) const { return count[static_cast<std::size_t>(first[static_cast<std::size_t>(action)] + label)] > 0; }
};

class Composer {
 public:
  Composer() : Composer(WeightComposerKind::kMult, FloatComposerKind::kAverage, {}) {}
  /// `labels_per_action[a]`: number of labels of action a's output shape.
  Composer(WeightComposerKind w, FloatComposerKind f, const std::vector<int>& labels_per_action);
  /// Manual profile: with `weights`, a behaviour whose weight is 0 (WANT 0)
  /// contributes nothing, instead of a 0 counted in the average.
  void set_skip_zero_weight(bool skip) { skip_zero_weight_ = skip; }
  bool selects_best() const { return select_best_; }

  /// Applies the weight composer to each proposal, with the weight of its
  /// owner behaviour, in place.
  void weight_in_place(ProposalList& proposals, const std::vector<double>& weights) const;
  /// The weight composer applied to one value.
  double weight(double value, double w) const { return weight_->compose(value, w); }
  /// Composes `proposals` into `out`; with `weights`, each proposal is first
  /// weighted (without changing the list).
  /// With select-best, `scores` (CANDO x WANT per behaviour) choose the one
  /// behaviour whose proposals are kept (the first of equal scores; none
  /// when `scores` is null or every score is 0).
  void compose(const ProposalList& proposals, const std::vector<double>* weights,
               ComposedActions& out, const std::vector<double>* scores = nullptr) const;
  /// An empty ComposedActions sized for this composer.
  ComposedActions make_output() const;

 private:
  std::unique_ptr<WeightComposer> weight_;
  std::unique_ptr<FloatComposer> float_;
  std::vector<int> first_;
  int slots_ = 0;
  bool skip_zero_weight_ = false;
  bool select_best_ = false;
};

}  // namespace mrt::brian
