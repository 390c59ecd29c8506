// CANDO filters (manual §10.3.6): which behaviours the engine activates.
#pragma once

#include "mrt_brian/types.h"

namespace mrt::brian {

class CandoFilter {
 public:
  virtual ~CandoFilter() = default;
  virtual bool active(const FuzzyValue& cando) const = 0;
};

/// threshold_filter: active when the value is higher than the threshold
/// (default 0.49, §10.4.4); with `check_reliability` the reliability must be
/// higher too (the 2009 engine's composite filter). With `in_float` the
/// comparisons are made in single precision, as the 2009 engine did (its
/// values and thresholds were `float`): a value of 0.49 read from a file or
/// a message is 0.49f there, not above 0.49f, and the behaviour is dropped.
class ThresholdFilter : public CandoFilter {
 public:
  explicit ThresholdFilter(double threshold = 0.49, bool check_reliability = false, bool in_float = false)
      : threshold_(threshold), check_reliability_(check_reliability), in_float_(in_float) {}
  bool active(const FuzzyValue& c) const override {
    if (in_float_) {
      const float t = static_cast<float>(threshold_);
      return static_cast<float>(c.value) > t && (!check_reliability_ || static_cast<float>(c.reliability) > t);
    }
    return c.value > threshold_ && (!check_reliability_ || c.reliability > threshold_);
  }
  void set_threshold(double t) { threshold_ = t; }
  double threshold() const { return threshold_; }
  bool checks_reliability() const { return check_reliability_; }

 private:
  double threshold_;
  bool check_reliability_;
  bool in_float_;
};

}  // namespace mrt::brian
