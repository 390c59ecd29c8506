// Roby's pose from the differential GPS and the wheel encoders (manual
// §2.3.1: "the Differential GPS provides already a good estimation of robot
// position"). ROS-free.
#pragma once

#include "mrt_common/pose2d.h"

namespace mrt::scare {

struct DgpsLocalizerOptions {
  double position_gain = 0.5;   // fraction of the fix's innovation applied
  double heading_gain = 0.3;    // fraction of the course innovation applied
  double course_min_travel = 0.4;  // m between fixes before the course is trusted
  double course_max_turn = 0.1;    // rad of odometry turn allowed over that travel
};

/// Dead reckoning from the body twist (encoders), corrected by each DGPS fix:
/// position towards the fix, heading towards the course over ground between
/// two fixes when the robot drove nearly straight.
class DgpsLocalizer {
 public:
  DgpsLocalizer(const common::Pose2D& initial, DgpsLocalizerOptions o = {});
  /// Integrates a body twist (m/s, rad/s) over dt seconds (exact arc).
  void predict(double vx, double omega, double dt);
  /// A fix in the same frame (m).
  void correct(double x, double y);
  const common::Pose2D& pose() const { return pose_; }
  int fixes() const { return fixes_; }

 private:
  DgpsLocalizerOptions o_;
  common::Pose2D pose_;
  bool have_fix_ = false;
  common::Point2D last_fix_;
  common::Pose2D pose_at_last_fix_;
  int fixes_ = 0;
};

}  // namespace mrt::scare
