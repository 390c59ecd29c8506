// Helpers of the mrt_mice tests: exact motions turned into quantised counts.
#pragma once

#include <cmath>

#include "mrt_mice/arc_model.h"

namespace mrt::mice::test {

/// An ideal mouse pair: accumulates exact real-valued counts and reports
/// whole counts, keeping the remainder, as a real mouse does. Optional
/// under-read factors (1 = no fault) scale the length of one sample.
class QuantisedMice {
 public:
  explicit QuantisedMice(const MiceParams& truth) : model_(truth) {}
  MiceCounts step(double vx, double vy, double omega, double dt, double left_factor = 1.0,
                  double right_factor = 1.0) {
    double a, b, c, d;
    model_.predict_counts(vx, vy, omega, dt, &a, &b, &c, &d);
    acc_[0] += a * left_factor;
    acc_[1] += b * left_factor;
    acc_[2] += c * right_factor;
    acc_[3] += d * right_factor;
    long long out[4];
    for (int i = 0; i < 4; ++i) {
      out[i] = std::llround(acc_[i]);
      acc_[i] -= static_cast<double>(out[i]);
    }
    MiceCounts m;
    m.left_dx = out[0];
    m.left_dy = out[1];
    m.right_dx = out[2];
    m.right_dy = out[3];
    return m;
  }

 private:
  ArcModel model_;
  double acc_[4] = {0, 0, 0, 0};
};

/// A general, asymmetric placement: mice ahead of and behind the wheel axle,
/// turned differently, with different resolutions.
inline MiceParams general_placement() {
  MiceParams p;
  p.left.mount = Pose2D(0.12, 0.08, 10.0 * M_PI / 180.0);
  p.left.counts_per_m = 15748.0;
  p.right.mount = Pose2D(-0.06, -0.10, -25.0 * M_PI / 180.0);
  p.right.counts_per_m = 31496.0;
  return p;
}

}  // namespace mrt::mice::test
