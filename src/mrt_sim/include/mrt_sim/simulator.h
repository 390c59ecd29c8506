// The deterministic 2D world simulator (ROS-free facade).
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "mrt_sim/sensors.h"
#include "mrt_sim/step_hook.h"
#include "mrt_sim/world.h"

namespace mrt::sim {

/// Outputs of one robot's sensors, filled when the sensor's period elapses
/// (the `*_ready` flag is set for that step only).
struct MiceSample {
  std::string left_id, right_id;
  int left_dx = 0, left_dy = 0, right_dx = 0, right_dy = 0;
  bool left_fault = false, right_fault = false;  // a fault was injected (or, physical model,
                                                 // counts lost) since the last sample
  double time = 0.0;                         // simulation time of this sample
  double left_stamp = 0.0, right_stamp = 0.0;  // simulation time of each mouse's last report
                                               // (= time for the ideal model)
  std::vector<MouseReport> left_reports, right_reports;  // physical model: the reports since
                                                         // the last sample, on each mouse's clock
};

struct RobotState {
  RobotConfig config;
  Pose2D pose;                      // ground truth in the world frame
  Twist2D twist;                    // body twist applied during the last step
  std::vector<double> wheel_setpoint;  // rad/s, as commanded
  std::vector<double> wheel_speed;     // rad/s, after saturation
  std::vector<double> wheel_angle;     // rad, integrated
  std::vector<double> encoder_angle;   // rad, the wheel angle as the encoder measures it (noisy)
  std::vector<std::int64_t> ticks;     // encoder ticks (floor of encoder_angle * ticks_per_rev / 2pi)
  bool saturated = false;
  bool bumped = false;              // the last step was blocked by a collision

  bool mice_ready = false;
  MiceSample mice;
  bool encoders_ready = false;
  bool sonar_ready = false;
  std::vector<double> sonar;        // m, one per sonar
  bool vision_ready = false;
  std::vector<SeenObject> vision;   // noisy
  bool dgps_ready = false;
  Point2D dgps;                     // noisy position in the world frame
  bool camera_ready = false;        // a camera frame is due (render it with CameraRenderer)
};

class Simulator {
 public:
  /// `dt` is the integration step in seconds (default 1 ms).
  explicit Simulator(World world, double dt = 0.001);

  double time() const { return time_; }
  std::uint64_t steps() const { return steps_; }
  double dt() const { return dt_; }
  const World& world() const { return world_; }
  /// The ball and the movers, for step hooks (step_hook.h) and other code
  /// that moves them from outside (pushes, placements, scripted actors).
  Ball& ball() { return world_.ball; }
  std::vector<Mover>& movers() { return world_.movers; }
  std::vector<RobotState>& robots() { return robots_; }
  const std::vector<RobotState>& robots() const { return robots_; }
  /// Index of the robot named `name`; throws std::out_of_range if none.
  std::size_t robot_index(const std::string& name) const;

  /// Sets the wheel speed set-points (rad/s, base wheel order; throws
  /// std::invalid_argument on a size mismatch).
  void set_wheel_speeds(std::size_t robot, const std::vector<double>& w);
  /// Convenience: converts a body twist to wheel set-points.
  void set_twist(std::size_t robot, const Twist2D& t);

  /// Index of the mover named `name`; throws std::out_of_range if none.
  std::size_t mover_index(const std::string& name) const;
  /// Steers mover `index` (a visitor driven by a behaviour model instead of
  /// its script): from where it stands it walks straight to `target` at
  /// `speed` (m/s; <= 0 stands still) and stops there, still waiting rather
  /// than step into a robot. Throws std::out_of_range for a bad index.
  void steer_mover(std::size_t index, const Point2D& target, double speed);
  /// Adds a wall (e.g. a door being closed): it blocks motion, sonar and
  /// vision from the next step on.
  void add_wall(const Segment& wall);

  /// Registers `hook` (not owned: it must stay alive until removed, or
  /// until the simulator goes): every step() calls the hooks' before_step
  /// before its physics and their after_step after it, each in the order
  /// they were added. Adding a registered hook again does nothing; a copy of
  /// the simulator starts without hooks. Not from within a hook.
  void add_hook(StepHook& hook);
  /// Unregisters `hook` (nothing if it is not registered). Not from within
  /// a hook.
  void remove_hook(StepHook& hook);

  /// Advances the world by one step: calls the hooks' before_step, moves
  /// robots along exact constant-twist arcs (wheel speeds saturated
  /// preserving direction), stops a robot whose
  /// step would collide (its footprint would overlap a wall, goal wall, post,
  /// mover, other robot, the bounds or a ball pinned against one of those,
  /// and is not moving out of an existing overlap; its wheels slip, so
  /// encoders count and the mice do not), moves
  /// movers (a mover waits rather than walk into a robot) and the ball, then
  /// updates every sensor whose period has elapsed, then calls the hooks'
  /// after_step.
  void step();

  /// The robots other than `robot`, as its sensors see them (name,
  /// position, body radius, colour).
  std::vector<OtherRobot> other_robots(std::size_t robot) const;

  /// Steps between two firings of a sensor of rate `hz` (0 when off):
  /// max(1, round(1 / (hz * dt))).
  std::uint64_t period(double hz) const;

 private:
  bool blocked(std::size_t robot, const Pose2D& from, const Pose2D& to) const;
  void move_movers();
  void move_ball();
  void update_sensors(std::size_t robot);

  World world_;
  double dt_;
  double time_ = 0.0;
  std::uint64_t steps_ = 0;
  std::vector<RobotState> robots_;
  std::vector<std::vector<MouseModel>> mice_;
  std::vector<std::vector<bool>> mice_fault_;  // a fault since the last sample
  std::vector<Segment> solid_;                 // walls and goal walls
  std::mt19937_64 rng_;
  // The registered hooks (not owned). A copy starts without any: a hook
  // belongs to the simulator it was added to.
  struct Hooks {
    std::vector<StepHook*> list;
    Hooks() = default;
    Hooks(const Hooks&) {}
    Hooks& operator=(const Hooks&) { return *this; }
  };
  Hooks hooks_;
};

}  // namespace mrt::sim
