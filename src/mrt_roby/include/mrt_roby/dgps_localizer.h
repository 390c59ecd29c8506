// Roby's pose from the differential GPS and the wheel encoders (manual
// §2.3.1: "the Differential GPS provides already a good estimation of robot
// position"). The fix's projection on the local plane and the wheel
// kinematics live here too, so that the node only converts messages. ROS-free.
#pragma once

#include <array>
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
  // Uncertainty model (the pose covariance; the filter's gains are fixed).
  double odom_var_per_m = 0.01;     // m^2 of position variance added per m travelled
  double yaw_var_per_rad = 0.01;    // rad^2 of heading variance per rad turned
  double yaw_var_per_m = 0.002;     // rad^2 of heading variance per m travelled
  double initial_var = 1.0;         // m^2 (and rad^2 for the heading) before the first fix
  // Fix standard deviation (m) by NavSatStatus when the fix gives no covariance.
  double sigma_gbas = 0.3;          // STATUS_GBAS_FIX (differential)
  double sigma_sbas = 1.0;          // STATUS_SBAS_FIX
  double sigma_fix = 3.0;           // STATUS_FIX (autonomous)

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
  /// A fix in the same frame (m) of horizontal variance `var` (m^2; <= 0:
  /// the options' sigma_gbas^2).
  void correct(double x, double y, double var = 0.0);
  /// A fix in degrees, projected on the plane around the datum.
  void correct(const common::GeoPoint& fix, double var = 0.0);
  /// The horizontal variance of a fix (m^2) from its NavSatStatus status
  /// (0 fix, 1 SBAS, 2 GBAS) and its covariance: the larger of the east and
  /// north variances when `cov_known`, otherwise the options' sigma for the
  /// status. Negative for "no fix" (status < 0).
  double fix_variance(int status, bool cov_known, double var_east, double var_north) const;
  /// Pose covariance (x, y, theta), row-major 3x3: the position variance
  /// grows with the distance travelled and shrinks with each fix as the
  /// fixed-gain update implies, var' = (1 - g)^2 var + g^2 var_fix.
  std::array<double, 9> covariance() const;
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
  double var_xy_, var_yaw_;
};

}  // namespace mrt::roby
