#include "mrt_mice/error_detector.h"

#include <cmath>

namespace mrt::mice {

ErrorDetector::ErrorDetector(const MiceParams& p)
    : bound_(std::sqrt(2.0) * (1.0 / p.left.counts_per_m + 1.0 / p.right.counts_per_m)),
      factor_(p.detection_factor),
      relative_(p.detection_relative) {}

Detection ErrorDetector::check(const ArcSolution& s) const {
  Detection d;
  d.residual = s.residual;
  d.threshold = factor_ * bound_ + relative_ * 0.5 * (s.length_left + s.length_right);
  d.flagged = std::fabs(s.residual) > d.threshold;
  return d;
}

}  // namespace mrt::mice
