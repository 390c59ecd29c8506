// Sensor models of the simulator, usable on their own (ROS-free).
#pragma once

#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mrt_sim/world.h"

namespace mrt::sim {

/// Exact displacement of a mouse, in metres in its own frame, while the body
/// moves with the constant twist `t` for `dt` seconds. A rigid body's point
/// has constant velocity in the body's rotating frame, so the integral a
/// mouse measures is dt * R(-phi) * (vx - omega*y_m, vy + omega*x_m).
Point2D mouse_displacement(const Pose2D& mount, const Twist2D& t, double dt);

/// An optical mouse producing integer counts: keeps the sub-count remainder
/// between reports as a real sensor does, so counts summed over many steps
/// equal round(total displacement * counts_per_m) within one count.
class MouseModel {
 public:
  explicit MouseModel(MouseConfig cfg) : cfg_(std::move(cfg)) {}
  const MouseConfig& config() const { return cfg_; }
  /// Advances by one step of body twist `t` over `dt`; accumulates counts.
  /// Noise and faults (manual §4.2: the mouse under-reads length, never
  /// direction) are drawn from `rng`; returns true if a fault was injected.
  bool step(const Twist2D& t, double dt, std::mt19937_64& rng);
  /// Returns the counts accumulated since the last read and clears them.
  void read(int& dx, int& dy);

 private:
  MouseConfig cfg_;
  double acc_x_ = 0.0, acc_y_ = 0.0;  // counts, fractional
  int out_x_ = 0, out_y_ = 0;         // whole counts not yet read
};

/// Distance from `origin` along unit direction `angle` to the first hit
/// with the world's walls, posts, goals, the ball, movers, and the given
/// extra circles (other robots), or nullopt beyond max_range.
struct Circle {
  Point2D center;
  double radius;
};
std::optional<double> ray_cast(const World& w, const std::vector<Circle>& extra, Point2D origin,
                               double angle, double max_range);

/// A sonar reading: the minimum over rays spread across the cone (the
/// nearest echo), clamped to [min_range, max_range]; max_range means no echo.
double sonar_range(const World& w, const std::vector<Circle>& extra, const Pose2D& robot,
                   const SonarConfig& s);

/// One object seen by the omnidirectional camera, relative to the robot.
struct SeenObject {
  std::string name;
  std::string membership_class;  // Landmark, GoalPost, Goal, Ball, Obstacle, Person, Robot, Line
  std::string color;
  double distance = 0.0;  // m, from the robot centre
  double bearing = 0.0;   // rad, counter-clockwise from the robot's x axis
};

/// Everything within range and not occluded (the line of sight to the object
/// centre does not cross a wall or a nearer cylinder), without noise.
/// `others` are the other robots (name, position, radius).
struct OtherRobot {
  std::string name;
  Point2D center;
  double radius;
  std::string color = "black";
};
std::vector<SeenObject> vision_percepts(const World& w, const std::vector<OtherRobot>& others,
                                        const Pose2D& robot, const SensorsConfig& cfg);

}  // namespace mrt::sim
