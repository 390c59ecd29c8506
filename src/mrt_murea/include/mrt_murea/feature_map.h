// The map MUREA localizes in: the features of a world (mrt_world) grouped by
// the percept class that sees them, each with a distance function that is
// O(1) to query (ROS-free).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mrt_common/pose2d.h"
#include "mrt_world/world.h"

namespace mrt::murea {

using mrt::common::Point2D;
using mrt::common::Pose2D;

/// The percept classes MUREA matches, named as the simulator's vision
/// ontology names them (mrt_common/ontology/mrt.yaml): Line = a field-line point,
/// Goal = the centre of a goal's mouth, GoalPost = a goal post, Landmark =
/// a post of class Landmark, Wall = a point on a wall or a goal wall.
enum class FeatureClass { Line, Goal, GoalPost, Landmark, Wall };
constexpr int kFeatureClassCount = 5;

/// "Line" -> FeatureClass::Line, ...; nullopt for any other name.
std::optional<FeatureClass> parse_feature_class(const std::string& name);
const char* to_string(FeatureClass c);

/// Distances from points of the plane to a set of segments, tabulated at
/// the centres of square pixels of side `resolution` over a rectangle.
/// Inside the rectangle, at(p) is the exact Euclidean distance from the
/// centre of the pixel containing p to the nearest segment; outside it,
/// the exact distance from p. Hence |at(p) - d(p)| <= slack() / 2 and
/// |at(p) - at(q)| <= |p - q| + slack() for all p, q, where d is the true
/// distance and slack() = resolution * sqrt(2) (the pixel diagonal).
class DistanceGrid {
 public:
  DistanceGrid() = default;
  DistanceGrid(std::vector<mrt::world::Segment> segments, double min_x, double min_y, double max_x,
               double max_y, double resolution);
  double at(double x, double y) const;
  double exact(double x, double y) const;
  /// The point closest to (x, y) of the segment nearest to the centre of
  /// the pixel containing (x, y) (of the nearest segment, outside the
  /// grid), and in *nx, *ny that segment's unit normal, or, when the
  /// closest point is an end of the segment (and not (x, y) itself), the
  /// unit vector from it to (x, y). Requires !empty().
  Point2D nearest(double x, double y, double* nx, double* ny) const;
  double slack() const { return slack_; }
  bool empty() const { return segments_.empty(); }
  int width() const { return nx_; }
  int height() const { return ny_; }

 private:
  std::vector<mrt::world::Segment> segments_;
  std::vector<float> cells_;
  std::vector<std::uint32_t> nearest_;  // index of the nearest segment, per pixel
  double min_x_ = 0, min_y_ = 0, res_ = 1, inv_res_ = 1, slack_ = 0;
  int nx_ = 0, ny_ = 0;
};

/// One coloured point feature (a goal mouth centre, a goal post, a post).
struct PointFeature {
  std::string name;
  std::string color;
  Point2D position;
};

/// What one percept is matched against: either a segment layer (Line,
/// Wall; colour ignored) or the point features of its class whose colour
/// equals the percept's (all of the class when the percept's colour is
/// empty). An empty layer never matches.
struct Layer {
  const DistanceGrid* grid = nullptr;  // segment layer
  std::vector<Point2D> points;         // point layer
  /// Distance function of the layer (the grid's, or the exact distance to
  /// the nearest point); +infinity for an empty layer.
  double distance(double x, double y) const;
  /// The nearest feature point to (x, y): the closest point of the nearest
  /// segment (a segment layer; *line true, (*nx, *ny) its unit normal) or
  /// the nearest point (*line false). Requires !empty().
  Point2D nearest(double x, double y, bool* line, double* nx, double* ny) const;
  /// The Lipschitz slack of distance(): the grid's, 0 for points.
  double slack() const { return grid ? grid->slack() : 0.0; }
  bool empty() const { return grid ? grid->empty() : points.empty(); }
};

struct MapOptions {
  double resolution = 0.025;  // m, pixel side of the distance grids
  double padding = 2.0;       // m, grids extend this far beyond the bounds
};

class FeatureMap {
 public:
  /// Builds the map from a world: field lines (arcs already split into
  /// segments by the world loader) -> Line; walls and goal walls -> Wall;
  /// goal mouth centres -> Goal; goal posts (goal's colour) -> GoalPost;
  /// posts of class Landmark -> Landmark. Bounds are the world's.
  explicit FeatureMap(const mrt::world::World& world, const MapOptions& options = {});

  /// The layer a percept of class `c` and colour `color` is matched against.
  Layer layer(FeatureClass c, const std::string& color) const;

  const std::vector<PointFeature>& points(FeatureClass c) const;
  double min_x() const { return min_x_; }
  double min_y() const { return min_y_; }
  double max_x() const { return max_x_; }
  double max_y() const { return max_y_; }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  double min_x_, min_y_, max_x_, max_y_;
  DistanceGrid lines_, walls_;
  std::vector<PointFeature> goals_, goal_posts_, landmarks_, none_;
};

}  // namespace mrt::murea
