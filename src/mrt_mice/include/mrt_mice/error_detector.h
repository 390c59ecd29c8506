// Error detection from the rigid-body constraint (manual §4.2).
#pragma once

#include "mrt_mice/arc_model.h"

namespace mrt::mice {

struct Detection {
  double residual = 0.0;   // m, along the joining line, right minus left
  double threshold = 0.0;  // m
  bool flagged = false;
};

/// The two mice must move equally along the line that joins them. Counts
/// are quantised: each reported count differs from the true displacement by
/// less than one count per axis, so the mismatch of consistent readings
/// stays below sqrt(2) (1/c_l + 1/c_r) metres, the quantisation bound. A
/// sample is flagged when |residual| exceeds
///   detection_factor * bound + detection_relative * (l_l + l_r) / 2.
class ErrorDetector {
 public:
  explicit ErrorDetector(const MiceParams& params);
  double quantisation_bound() const { return bound_; }
  Detection check(const ArcSolution& s) const;

 private:
  double bound_;
  double factor_;
  double relative_;
};

}  // namespace mrt::mice
