// Roby's external path planner: a pre-compiled map of buildings and a route
// between two points; the legs of a re-plan are planned by SPIKE
// (mrt_spike) on the buildings' map. ROS-free.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrt_common/pose2d.h"

namespace mrt::roby {

using common::Point2D;

/// A building of the map: an axis-aligned rectangle.
struct Building {
  std::string name;
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

struct RoadMap {
  std::string frame = "map";
  std::vector<Building> buildings;
  std::vector<Point2D> route;   // the path points, start excluded
  double clearance = 0.5;       // m a route leg must keep from buildings
};

/// Parses a map file (format in the README); throws ParseError.
RoadMap parse_road_map(const std::string& yaml_text, const std::string& file);
RoadMap load_road_map(const std::string& path);

/// Distance from segment [a, b] to a rectangle (0 when they intersect).
double segment_rect_distance(const Point2D& a, const Point2D& b, const Building& r);

/// Plans over a RoadMap. Re-planning: the failed path point is marked
/// unreachable and the new plan goes from the current pose through the
/// remaining reachable path points after it; when the leg from the current
/// pose to the first of them passes a building, SPIKE plans the way round on
/// a 0.1 m grid of the buildings inflated by the clearance (plus a margin of
/// one cell diagonal, so that every leg between its waypoints keeps the
/// clearance).
class RoutePlanner {
 public:
  explicit RoutePlanner(RoadMap map);
  /// The full route. Throws std::invalid_argument when a leg (start -> p1 ->
  /// ...) passes closer than `clearance` to a building.
  std::vector<Point2D> plan(const Point2D& start);
  /// A new plan from `from` after path point `failed` (nearest route point)
  /// could not be reached: detour points (if any) then the remaining route.
  std::vector<Point2D> replan(const Point2D& from, const Point2D& failed);
  /// SPIKE's collision-free polyline from `a` to `b` keeping the clearance
  /// from the buildings: the intermediate points only (empty when the
  /// straight leg is free). A robot inside a building's clearance first backs
  /// out to the nearest point outside it. Throws std::runtime_error when there
  /// is no way (the goal within the clearance, or enclosed).
  std::vector<Point2D> detour(const Point2D& a, const Point2D& b) const;
  const RoadMap& map() const { return map_; }
  const std::vector<bool>& unreachable() const { return unreachable_; }

 private:
  bool leg_free(const Point2D& a, const Point2D& b) const;
  struct Spike;  // the grid of the buildings and SPIKE over it (built once)
  RoadMap map_;
  std::vector<bool> unreachable_;
  std::shared_ptr<Spike> spike_;
};

}  // namespace mrt::roby
