// The static description of a robot's environment (ROS-free): bounds,
// walls, painted field lines, posts (landmarks, exhibits, obstacles),
// goals, doors and named regions. What moves or senses (robots, the ball,
// people, sensor models) is the simulator's (mrt_sim); this is what the
// localizer matches percepts against and the planner plans around.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mrt_common/pose2d.h"

namespace mrt::world {

using mrt::common::Point2D;
using mrt::common::Pose2D;

/// A straight segment. Walls block motion, sonar and vision; painted field
/// lines block nothing and are seen by vision as line points.
struct Segment {
  Point2D a, b;
};

/// A static cylinder: a coloured landmark post, a goal post, an exhibit on
/// its pedestal, a tree, a parked-car approximation. Blocks motion, sonar
/// and vision.
struct Post {
  std::string name;
  std::string membership_class;  // an ontology class: "Landmark", "Exhibit", "Obstacle", ...
  std::string color;             // symbolic colour seen by vision ("" if none)
  Point2D center;
  double radius = 0.1;
};

/// A goal of the field: seen by vision as one object at its mouth centre;
/// its three sides (back and two sides) are walls.
struct Goal {
  std::string name;
  std::string color;
  Pose2D pose;         // mouth centre, theta pointing into the goal
  double width = 2.0;  // m
  double depth = 0.5;  // m
};

/// An opening in the walls that may be found closed: `span` is the wall
/// that closes it (open, it blocks nothing).
struct Door {
  std::string name;
  Segment span;
};

/// A named area (a room, a penalty area): a simple polygon, counter-
/// clockwise or clockwise, at least 3 corners.
struct Region {
  std::string name;
  std::vector<Point2D> polygon;
};

struct World {
  std::string name;
  std::string file;                     // where it was loaded from
  double min_x = -10, min_y = -10, max_x = 10, max_y = 10;  // bounds, m
  std::vector<Segment> walls;
  std::vector<Segment> field_lines;     // arcs already split into chords
  double line_width = 0.125;            // m, painted width of the field lines (MSL: 12.5 cm)
  std::vector<Post> posts;
  std::vector<Goal> goals;
  std::vector<Door> doors;
  std::vector<Region> regions;

  /// The posts of class `membership_class` (e.g. "Landmark").
  std::vector<Post> posts_of(const std::string& membership_class) const;
  /// The door named `name`; throws std::out_of_range if none.
  const Door& door(const std::string& name) const;
  /// The first region containing `p`, nullptr if none.
  const Region* region_at(const Point2D& p) const;
};

/// The three walls of a goal (back and two sides; the mouth is open), in
/// the world frame.
std::array<Segment, 3> goal_walls(const Goal& g);

/// The two goal posts at the ends of the mouth: [left, right] as seen from
/// the field looking into the goal.
std::array<Point2D, 2> goal_posts(const Goal& g);

/// Every segment that blocks motion, sonar and vision: walls and goal walls
/// (open doors block nothing; a closed one is added as a wall).
std::vector<Segment> solid_segments(const World& w);

/// Distance from `p` to the closest point of `s`; that point in `closest`.
double distance_to_segment(const Point2D& p, const Segment& s, Point2D* closest = nullptr);

/// `p` inside the polygon (even-odd rule; points on an edge may go either way).
bool inside(const std::vector<Point2D>& polygon, const Point2D& p);

}  // namespace mrt::world
