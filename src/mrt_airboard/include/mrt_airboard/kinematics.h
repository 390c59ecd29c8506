// Kinematics of the AIRLab robot bases: the processing sub-module of
// AIRBoard (manual chapter 5, section 2.1). ROS-free. The inverse and
// forward kinematics, the saturation and the preset geometries live once in
// mrt_common/base_kinematics.h (shared with mrt_sim); this header adds the
// board's own limits (acceleration, dead-band, encoder resolution) and the
// parameter validation.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrt_common/base_kinematics.h"

namespace mrt::airboard {

/// Body-frame velocity (REP-103): vx forward, vy left (m/s), omega
/// counter-clockwise (rad/s).
using Twist2D = mrt::common::Twist2D;

using BaseType = mrt::common::BaseType;

using BaseGeometry = mrt::common::BaseGeometry;

/// Geometry and limits of one base, validated by validate(). The geometry
/// (type, wheel_radius, track, wheel_distance, wheel_angles) is the one
/// geometry type of the stack, mrt::common::BaseGeometry, shared with
/// mrt_sim; the board adds its limits.
///
/// Differential: wheels [left, right], `track` apart; positive wheel speed
/// drives the robot forward.
/// Omni: wheel i sits at `wheel_angles[i]` (rad, from the body x axis) at
/// `wheel_distance` from the centre and drives along (-sin a, cos a): its
/// angular speed is w_i = (-sin(a) vx + cos(a) vy + L omega) / r (the
/// convention of mrt_common/base_kinematics.h, mrt_sim and
/// mrt_msgs/WheelCommand).
struct BaseParams : BaseGeometry {
  std::string name = "ianus3";
  double max_wheel_speed = 24.0;       // rad/s, saturation (0 = none)
  double max_wheel_accel = 0.0;        // rad/s^2, acceleration limit (0 = none)
  double deadband_linear = 0.0;        // m/s: |v| below it is zeroed
  double deadband_angular = 0.0;       // rad/s: |omega| below it is zeroed
  int counts_per_rev = 8192;           // encoder counts per wheel revolution

  /// Throws std::invalid_argument naming the offending parameter.
  void validate() const;
};

/// The presets of the manual's robots, from mrt::common::base_presets():
/// "ianus3" (differential, r 0.05 m, track 0.38 m, 1.2 m/s), "p3at"
/// (differential, r 0.11 m, track 0.40 m), "triskar" (three omni wheels at
/// 90/210/330 deg), "omni4" (four omni wheels at 45/135/225/315 deg); the
/// board's own limits keep their defaults. Throws std::invalid_argument for
/// an unknown name.
BaseParams base_preset(const std::string& name);

/// Parses "differential" / "omni".
BaseType parse_base_type(const std::string& s);

/// Inverse (twist -> wheel angular speeds) and forward (wheel speeds ->
/// twist) kinematics of one base.
class BaseKinematics {
 public:
  virtual ~BaseKinematics() = default;
  virtual std::size_t wheel_count() const = 0;
  /// Wheel angular speeds (rad/s) realising `t`.
  virtual std::vector<double> inverse(const Twist2D& t) const = 0;
  /// Body twist from wheel angular speeds (rad/s); least squares when the
  /// base has more wheels than degrees of freedom. Throws
  /// std::invalid_argument on a size mismatch.
  virtual Twist2D forward(const std::vector<double>& w) const = 0;
  /// Whether the base can move sideways (vy).
  virtual bool holonomic() const = 0;
};

class DifferentialKinematics : public BaseKinematics {
 public:
  DifferentialKinematics(double wheel_radius, double track);
  std::size_t wheel_count() const override { return 2; }
  std::vector<double> inverse(const Twist2D& t) const override;  // ignores vy
  Twist2D forward(const std::vector<double>& w) const override;
  bool holonomic() const override { return false; }

 private:
  double r_, track_;
};

class OmniKinematics : public BaseKinematics {
 public:
  /// Needs at least three wheels whose directions span the plane.
  OmniKinematics(double wheel_radius, double wheel_distance, std::vector<double> wheel_angles);
  std::size_t wheel_count() const override { return angles_.size(); }
  std::vector<double> inverse(const Twist2D& t) const override;
  Twist2D forward(const std::vector<double>& w) const override;
  bool holonomic() const override { return true; }

 private:
  double r_, dist_;
  std::vector<double> angles_;
};

std::unique_ptr<BaseKinematics> make_kinematics(const BaseParams& p);

/// Scales the whole vector so that no |w_i| exceeds `max_abs` (0 = no
/// limit), keeping the direction of motion. Returns the scale applied (1 when
/// nothing changed).
using mrt::common::saturate_preserving_direction;

/// Turns a requested twist into wheel set-points: dead-band on the twist,
/// inverse kinematics, saturation that preserves the direction of motion,
/// and an acceleration limit that also scales the whole change vector (so a
/// ramp keeps the direction of motion too).
class VelocityLimiter {
 public:
  explicit VelocityLimiter(const BaseParams& p);

  struct Result {
    std::vector<double> wheels;  // set-points, rad/s
    bool saturated = false;      // the speed limit scaled the request
    bool accel_limited = false;  // the acceleration limit scaled the change
  };

  /// `dt` is the time since the previous call (s); ignored when the
  /// acceleration limit is 0. The first call (or the first after reset())
  /// ramps from rest: its step is at most max_wheel_accel * dt. A
  /// non-finite request is treated as a stop (callers drop such input
  /// before; this only keeps NaN off the wire).
  Result update(const Twist2D& requested, double dt);
  /// Forgets the previous set-points (e.g. after the link was lost: the
  /// motors are considered stopped) and clears set_board_stopped().
  void reset();
  /// Sets the previous set-points (after wheel speeds were commanded
  /// directly), so the next ramp starts from them.
  void hold(const std::vector<double>& wheels) { last_ = wheels; }
  /// The board reports (status bit WATCHDOG) that it zeroed its set-points
  /// on its own. While `stopped` is true every update() ramps from rest: the
  /// board applied none of the commands sent since, so whichever it applies
  /// first is a single step from 0. Once a state without the bit arrives (a
  /// command was applied), call it with false: the ramp goes on from the
  /// last set-points returned.
  void set_board_stopped(bool stopped);
  bool board_stopped() const { return board_stopped_; }
  /// New speed and acceleration limits (rad/s, rad/s^2; 0 = none, as in
  /// BaseParams) from the next update(); the ramp goes on from the last
  /// set-points. Throws std::invalid_argument naming the parameter, with
  /// nothing changed.
  void set_limits(double max_wheel_speed, double max_wheel_accel);
  const BaseParams& params() const { return p_; }
  const BaseKinematics& kinematics() const { return *kin_; }

 private:
  BaseParams p_;
  std::unique_ptr<BaseKinematics> kin_;
  std::vector<double> last_;
  bool board_stopped_ = false;
};

}  // namespace mrt::airboard
