// The whole processing chain of the two-mouse sensor: arc model, error
// detection, error reduction, pose integration, covariance and statistics.
#pragma once

#include <array>
#include <cstdint>

#include "mrt_mice/arc_model.h"
#include "mrt_mice/error_detector.h"
#include "mrt_mice/error_reducer.h"
#include "mrt_mice/pose_integrator.h"

namespace mrt::mice {

struct OdometryOptions {
  bool reduce_errors = true;
  /// Variance growth: position variance per metre travelled (m^2/m),
  /// heading variance per radian turned and per metre (rad^2/rad, rad^2/m).
  double var_xy_per_m = 1e-5;
  double var_theta_per_rad = 1e-5;
  double var_theta_per_m = 1e-5;
  /// A flagged sample adds (residual * flagged_gain)^2 to the position
  /// variance and (residual / D * flagged_gain)^2 to the heading variance.
  double flagged_gain = 3.0;
  void validate() const;
};

/// Counters of the error detector and reducer.
struct ErrorStats {
  std::uint64_t samples = 0;
  std::uint64_t flagged = 0;
  std::uint64_t corrected = 0;      // scaled or rebuilt
  std::uint64_t uncorrectable = 0;
  double last_residual = 0.0;       // m
  double max_abs_residual = 0.0;    // m
  double sum_sq_residual = 0.0;     // m^2
  double rms_residual() const;
};

struct StepResult {
  ArcSolution raw;        // from the readings as they came
  Detection detection;
  Reduction reduction;
  Pose2D delta;           // the displacement actually integrated
};

class MiceOdometry {
 public:
  MiceOdometry(const MiceParams& params, const OdometryOptions& options = OdometryOptions());

  /// Processes one sample and integrates it.
  StepResult update(const MiceCounts& counts);
  void reset(const Pose2D& start = Pose2D());

  const Pose2D& pose() const { return integrator_.pose(); }
  double distance() const { return integrator_.distance(); }
  /// Row-major 3x3 covariance of (x, y, theta) in the odometry frame.
  const std::array<double, 9>& covariance() const { return cov_; }
  const ErrorStats& stats() const { return stats_; }
  const ArcModel& model() const { return model_; }
  const ErrorDetector& detector() const { return detector_; }

 private:
  void grow_covariance(const Pose2D& delta, const Detection& d);

  MiceParams params_;
  OdometryOptions options_;
  ArcModel model_;
  ErrorDetector detector_;
  ErrorReducer reducer_;
  PoseIntegrator integrator_;
  std::array<double, 9> cov_{};
  ErrorStats stats_;
};

}  // namespace mrt::mice
