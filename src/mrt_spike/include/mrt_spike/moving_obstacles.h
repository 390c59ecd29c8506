// Moving obstacles (people, robots, the ball) over the static map, added,
// moved and removed incrementally, and re-planning that reuses the static
// structure (ROS-free).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mrt_spike/grid.h"
#include "mrt_spike/jump_point_search.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

/// A moving object, in cells (and cells per second).
struct MovingObstacle {
  double x = 0.0;
  double y = 0.0;
  double radius = 0.0;  ///< its own size
  double vx = 0.0;
  double vy = 0.0;
};

/// The static (inflated) grid plus the footprints of the moving obstacles.
/// A footprint is the capsule swept by the obstacle's disc over `horizon`
/// seconds at its velocity, widened by `inflation` (robot radius + safety
/// distance): its size and its speed. Each cell counts the footprints over
/// it, so overlapping obstacles come and go independently; updating one
/// obstacle touches only its old and new footprint cells.
class ObstacleLayer {
 public:
  ObstacleLayer(const OccupancyGrid& base, double inflation, double horizon);
  void set(int id, const MovingObstacle& o);  ///< add or move
  void remove(int id);
  void clear();
  size_t size() const { return footprints_.size(); }
  /// The static grid with every footprint blocked.
  const OccupancyGrid& grid() const { return combined_; }
  const OccupancyGrid& base() const { return base_; }
  /// Cells covered by the footprint of `o` (clipped to the map).
  std::vector<Cell> footprint(const MovingObstacle& o) const;

 private:
  void stamp(const std::vector<Cell>& cells, int delta);
  OccupancyGrid base_;
  OccupancyGrid combined_;
  double inflation_;
  double horizon_;
  std::vector<std::uint16_t> count_;
  std::map<int, std::vector<Cell>> footprints_;
};

/// A planner among moving obstacles: the obstacle layer over the static
/// grid and an algorithm planning on the layer's grid (make_dynamic_planner
/// in planner_factory.h makes one by name).
class DynamicPlanner : public GridPlanner {
 public:
  virtual ObstacleLayer& obstacles() = 0;
  virtual const ObstacleLayer& obstacles() const = 0;
  /// True while every segment of the path is valid with the current footprints.
  bool still_valid(const std::vector<Cell>& path) const;
};

/// SPIKE with moving obstacles: the static SpikePlanner (quadtree, subgoal
/// graph) is built once; a query first plans on the static structure and
/// keeps that path when no footprint blocks it; otherwise it searches the
/// grid with the footprints (jump point search: octile-optimal, nothing to
/// rebuild) and pulls the string on it.
class DynamicSpike final : public DynamicPlanner {
 public:
  DynamicSpike(const OccupancyGrid& static_grid, double inflation, double horizon, SpikeOptions options = {});
  ObstacleLayer& obstacles() override { return layer_; }
  const ObstacleLayer& obstacles() const override { return layer_; }
  const SpikePlanner& static_planner() const { return *static_; }
  PlanResult plan(const Cell& start, const Cell& goal) override;
  std::string name() const override { return "spike"; }
  PlannerCapabilities capabilities() const override { return kCapabilities; }
  static constexpr PlannerCapabilities kCapabilities{true, true};

 private:
  OccupancyGrid static_grid_;
  ObstacleLayer layer_;
  std::unique_ptr<SpikePlanner> static_;
  std::unique_ptr<JumpPointSearch> search_;
};

}  // namespace mrt::spike
