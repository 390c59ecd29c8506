// Calibration of the two-mouse sensor, manual §4.2 (after Bonarini,
// Matteucci and Restelli): straight pushes and turns in place.
#pragma once

#include <string>
#include <vector>

#include "mrt_mice/mice_params.h"

namespace mrt::mice {

/// One calibration run: the counts summed over the run and what the robot
/// really did.
struct CalibrationRun {
  enum class Kind { kPush, kTurn };
  Kind kind = Kind::kPush;
  /// Push: distance travelled straight ahead along the robot heading (m,
  /// 0.5 in the manual's protocol). Turn: angle turned in place about the
  /// rotation centre, counter-clockwise positive (rad, 2 pi).
  double amount = 0.0;
  MiceCounts counts;
  std::string source;  // where it came from ("file:line"), for reports
};

/// How well the fitted model explains one run: the difference between the
/// counts read and the counts the fitted model predicts (counts).
struct RunResidual {
  std::string source;
  CalibrationRun::Kind kind;
  double left = 0.0;   // |measured - predicted| of the left mouse
  double right = 0.0;  // same, right mouse
};

struct CalibrationResult {
  MiceParams params;
  ManualGeometry geometry;
  std::vector<RunResidual> residuals;
  double rms_residual = 0.0;  // counts, over both mice and all runs
  int pushes = 0;
  int turns = 0;
};

/// Pushes along the heading make each mouse read c_i R(-phi_i) (d, 0): the
/// mean reading per metre (least squares over the runs) gives the
/// resolution c_i (its length) and the orientation phi_i = sigma_i (its
/// angle). Turns in place make mouse i read c_i R(-phi_i) theta J p_i: with
/// c_i and phi_i known, the mean reading per radian gives the position p_i
/// relative to the centre of rotation. D, delta follow from p_l, p_r.
/// `base` supplies the detection options copied into the result. Throws
/// std::invalid_argument without at least one push and one turn, or when a
/// mouse read nothing.
CalibrationResult calibrate(const std::vector<CalibrationRun>& runs,
                            const MiceParams& base = MiceParams());

}  // namespace mrt::mice
