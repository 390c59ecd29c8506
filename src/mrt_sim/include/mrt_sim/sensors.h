// Sensor models of the simulator, usable on their own (ROS-free).
#pragma once

#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mrt_common/percept.h"
#include "mrt_sim/mouse_model.h"  // MouseModel, mouse_displacement (kept here for old includes)
#include "mrt_sim/world.h"

namespace mrt::sim {

/// A circle in the world frame (another robot's footprint).
struct Circle {
  Point2D center;
  double radius;
};

/// Distance from `origin` along the direction `angle` (world frame, rad) to
/// the first hit with the world's walls, goal walls, posts, the ball, movers
/// and the `extra` circles (other robots), or nullopt beyond max_range; 0
/// when the origin is inside a circle.
std::optional<double> ray_cast(const World& w, const std::vector<Circle>& extra, Point2D origin,
                               double angle, double max_range);

/// A sonar reading without noise: the distance from the transducer to the
/// nearest point of any wall, goal wall, post, ball, mover or `extra` circle
/// inside the cone of full angle s.fov around the beam axis (the nearest
/// echo), clamped to [min_range, max_range]; max_range means no echo.
/// Computed exactly, not by sampling rays, so thin posts between rays are
/// not missed; fov = 0 is a single ray (ray_cast).
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

/// Everything within cfg.vision_range of the robot centre and not occluded
/// (the line of sight to the object centre crosses no wall, goal wall or
/// cylinder other than the object's own), without noise, in this order:
/// posts (their class), goals ("Goal" at the mouth centre) and their posts
/// ("GoalPost", named <goal>_left / <goal>_right looking into the goal), the
/// ball ("Ball"), movers (their class), other robots ("Robot"), and field
/// lines as points ("Line", name "line", colour "white") at the middles of
/// equal pieces about cfg.line_point_spacing long.
/// `others` are the other robots (name, position, radius, colour).
struct OtherRobot {
  std::string name;
  Point2D center;
  double radius;
  std::string color = "black";
};
std::vector<SeenObject> vision_percepts(const World& w, const std::vector<OtherRobot>& others,
                                        const Pose2D& robot, const SensorsConfig& cfg);

/// A seen object as an object of the stack's percept type (mrt_common/
/// percept.h), with the vision model's deviations: distance and bearing
/// (sigma cfg.vision_distance_noise * distance, cfg.vision_bearing_noise),
/// x and y (sigma hypot of the two), the colour when it has one.
mrt::common::PerceptObject to_percept_object(const SeenObject& s, const SensorsConfig& cfg);

/// What a real vision system reports instead of the ideal percepts
/// (world file `vision: {model: realistic}`), drawn from `rng`: class and
/// colour only (no names); each object missed with a probability growing
/// linearly from cfg.vision_miss_near at the robot to cfg.vision_miss_far
/// at cfg.vision_range; distance noise growing with distance, 1 sigma =
/// distance_noise * d * (1 + d / range); bearing noise as configured;
/// plus a Poisson number (mean cfg.vision_false_positives) of false
/// objects (a Ball, Robot, GoalPost or Obstacle in a plausible colour,
/// uniform in distance over [0.5, range] and in bearing). Occlusion is that
/// of `ideal` (vision_percepts).
std::vector<SeenObject> realistic_percepts(const std::vector<SeenObject>& ideal, const SensorsConfig& cfg,
                                           std::mt19937_64& rng);

}  // namespace mrt::sim
