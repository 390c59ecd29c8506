// Roby's pose from the differential GPS and the wheel encoders (manual
// §2.3.1: "the Differential GPS provides already a good estimation of robot
// position"). The fix's projection on the local plane and the wheel
// kinematics live here too, so that the node only converts messages. ROS-free.
#pragma once

#include <optional>

#include "mrt_common/base_kinematics.h"
#include "mrt_common/geodesy.h"
#include "mrt_common/pose2d.h"

namespace mrt::roby {

struct DgpsLocalizerOptions {
  double position_gain = 0.5;   // fraction of the fix's innovation applied
  double heading_gain = 0.3;    // fraction of the course innovation applied
  double course_min_travel = 0.4;  // m between fixes before the course is trusted
  double course_max_turn = 0.1;    // rad of odometry turn allowed over that travel
  common::GeoPoint datum{45.478, 9.227};  // origin of the local plane (x east, y north)
  double wheel_radius = 0.11;   // m (P3-AT)
  double track = 0.40;          // m between the wheels

  /// Throws std::invalid_argument naming the first bad field.
  void validate() const;
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
  /// A fix in degrees, projected on the plane around the datum.
  void correct(const common::GeoPoint& fix);
  /// Wheel speeds [left, right] (rad/s, positive forward) measured at
  /// `stamp` (s): the body twist (mrt_common's differential_forward) is
  /// integrated from the previous wheel state's stamp; the first one, or
  /// one not newer than the previous, only sets the twist.
  void wheel_state(double left, double right, double stamp);

  const common::Pose2D& pose() const { return pose_; }
  /// The body twist of the last wheel state that was integrated.
  const common::Twist2D& twist() const { return twist_; }
  const common::LocalTangentPlane& plane() const { return plane_; }
  int fixes() const { return fixes_; }

 private:
  DgpsLocalizerOptions o_;
  common::LocalTangentPlane plane_;
  common::Pose2D pose_;
  common::Twist2D twist_{};
  std::optional<double> last_stamp_;
  bool have_fix_ = false;
  common::Point2D last_fix_;
  common::Pose2D pose_at_last_fix_;
  int fixes_ = 0;
};

}  // namespace mrt::roby
