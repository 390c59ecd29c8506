// The optical mouse of the simulator, usable on its own (ROS-free): the
// ideal model (the exact inverse of mrt_mice's estimator) and the physical
// one (surface-dependent resolution, height and lift-off, speed and
// acceleration limits, reports on the mouse's own clock).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "mrt_sim/world.h"

namespace mrt::sim {

/// Exact displacement of a mouse, in metres in its own frame, while the body
/// moves with the constant twist `t` for `dt` seconds. A rigid body's point
/// has constant velocity in the body's rotating frame, so the integral a
/// mouse measures is dt * R(-phi) * (vx - omega*y_m, vy + omega*x_m).
Point2D mouse_displacement(const Pose2D& mount, const Twist2D& t, double dt);

/// The floor under a point: the last surface of `surfaces` containing `p`
/// (borders included), or resolution 1, clearance 0.
struct FloorUnder {
  double resolution = 1.0;
  double clearance = 0.0;  // m
};
FloorUnder floor_under(const std::vector<Surface>& surfaces, const Point2D& p);

/// One report of a physical mouse: its counts since its previous report,
/// stamped with the simulation time at which it was sampled.
struct MouseReport {
  double t = 0.0;
  int dx = 0, dy = 0;
};

/// Steps of the physical model in which the counts were lost, by cause.
struct MouseLosses {
  std::uint64_t lifted = 0;     // higher than the lift-off height
  std::uint64_t too_fast = 0;   // above max_speed
  std::uint64_t too_hard = 0;   // above max_accel
};

/// An optical mouse producing integer counts: keeps the sub-count remainder
/// between reports as a real sensor does: the counts read so far are the
/// floor of the total displacement * counts_per_m, so each report is off by
/// less than one count per axis whatever the motion.
class MouseModel {
 public:
  explicit MouseModel(MouseConfig cfg);
  const MouseConfig& config() const { return cfg_; }
  /// The ideal model: advances by one step of body twist `t` over `dt`;
  /// accumulates counts. Noise and faults (manual §4.2: the mouse
  /// under-reads length, never direction) are drawn from `rng`; returns
  /// true if a fault was injected.
  bool step(const Twist2D& t, double dt, std::mt19937_64& rng);
  /// The physical model (ideal when config().physics.enabled is false): the
  /// same step, with `body` the body's world pose at the end of the step,
  /// `time` the simulation time then and `surfaces` the world's floor. The
  /// resolution is scaled by the floor's and by 1 - height_gain * h (h the
  /// height above focus, physics.height + the floor's clearance); the counts
  /// of the step are lost when h > liftoff, when the mouse moves faster than
  /// max_speed or accelerates harder than max_accel (from its world
  /// velocity in this step and the previous one). Whole counts are
  /// reported on the mouse's own clock. Returns true if counts were lost
  /// (a fault or a limit).
  bool step(const Twist2D& t, const Pose2D& body, double time, double dt, const std::vector<Surface>& surfaces,
            std::mt19937_64& rng);
  /// Returns the counts reported since the last read and clears them (the
  /// ideal model reports every step); the reports themselves, in order, go
  /// to `reports` when given (physical model; none for the ideal one).
  void read(int& dx, int& dy, std::vector<MouseReport>* reports = nullptr);
  /// Simulation time of the last report (physical), or of the last step (ideal).
  double last_report_time() const { return last_report_; }
  const MouseLosses& losses() const { return losses_; }

 private:
  void accumulate(double dx_counts, double dy_counts);

  MouseConfig cfg_;
  double acc_x_ = 0.0, acc_y_ = 0.0;  // counts, fractional
  int out_x_ = 0, out_y_ = 0;         // whole counts not yet reported (physical) or read (ideal)
  std::vector<MouseReport> pending_;  // reports not yet read
  std::uint64_t next_report_ = 0;     // index of the next report on the mouse's clock
  double last_report_ = 0.0;
  double vx_ = 0.0, vy_ = 0.0;        // world velocity in the previous step, m/s
  MouseLosses losses_;
};

}  // namespace mrt::sim
