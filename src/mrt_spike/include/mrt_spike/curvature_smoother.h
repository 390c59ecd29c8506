// SPIKE's any-angle paths made drivable by a differential base: each
// straight segment replaced by OMPL's shortest Dubins (forward only) or
// Reeds-Shepp (reversing allowed) curve of a minimum turning radius,
// checked cell by cell against the occupancy grid.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrt_spike/grid.h"
#include "mrt_spike/poses.h"

namespace ompl::base {
class StateSpace;
}

namespace mrt::spike {

struct SmoothingOptions {
  enum class Model { none, dubins, reeds_shepp };
  Model model = Model::dubins;
  double turning_radius = 0.3;  ///< m, the minimum
  double step = 0.05;           ///< m of arc length between output poses
  /// Times a colliding curve is split at the middle of its straight
  /// segment (heading along it) and tried again before the straight
  /// segment itself is kept.
  int max_splits = 3;
};

/// `none`, `dubins` or `reeds_shepp`; anything else: std::invalid_argument.
SmoothingOptions::Model smoothing_model(const std::string& name);

struct SmoothedPath {
  std::vector<Pose> poses;     ///< map frame, every `step` at most, both ends included
  double length = 0.0;         ///< m, the curves' and kept segments' lengths
  double max_curvature = 0.0;  ///< 1/m from the poses (inf where a kept segment turns on the spot)
  bool fully_smoothed = true;  ///< false when a straight segment had to be kept
  int kept_segments = 0;       ///< straight segments kept (curves colliding)
};

/// Heading change over distance between consecutive poses, the largest;
/// infinite where the heading changes without motion (a polyline's corner).
double max_curvature(const std::vector<Pose>& poses);

/// Length of a polyline of poses, m.
double polyline_length(const std::vector<Pose>& poses);

/// The corners of a polyline (heading changes of more than 1e-6 rad).
int corner_count(const std::vector<Pose>& poses);

class CurvatureSmoother {
 public:
  /// `grid`: the grid the waypoints were planned on (inflated, with the
  /// moving obstacles); a point is valid when its nearest cell is free, as
  /// the planners' rule. Throws std::invalid_argument for model none or a
  /// turning radius <= 0.
  CurvatureSmoother(const OccupancyGrid& grid, const GridFrame& frame, const SmoothingOptions& options);
  /// `waypoints`: x, y in the map frame (yaw unused), start first. The
  /// heading at the start is `start_yaw` (not finite: the first segment's
  /// direction), at the goal `goal_yaw` or the last
  /// segment's direction, in between the bisector of the two segments.
  /// Fewer than two distinct waypoints: the waypoint alone.
  SmoothedPath smooth(const std::vector<Pose>& waypoints, double start_yaw,
                      std::optional<double> goal_yaw = std::nullopt) const;
  /// True when every pose's cell is free (a moving obstacle may block the
  /// curves while the waypoints' straight segments stay free).
  bool poses_free(const std::vector<Pose>& poses) const;
  /// The curve alone from a to b (their yaws the headings): its poses every
  /// `step` and its length; false when it leaves the free cells.
  bool curve(const Pose& a, const Pose& b, std::vector<Pose>& out, double& length) const;

 private:
  void segment(const Pose& a, const Pose& b, int splits, SmoothedPath& out) const;
  bool free_at(double x, double y) const;

  const OccupancyGrid& grid_;
  GridFrame frame_;
  SmoothingOptions options_;
  std::shared_ptr<ompl::base::StateSpace> space_;  ///< Dubins or Reeds-Shepp
};

/// The corners of a planned path in the map frame (the cells' centres).
std::vector<Pose> waypoint_poses(const std::vector<Cell>& cells, const GridFrame& frame);

}  // namespace mrt::spike
