// Jump point search (Harabor & Grastien), the variant without corner
// cutting: octile-optimal paths on a grid that changes between queries,
// with no preprocessing (SPIKE's search once moving obstacles block the
// static plan).
#pragma once

#include <string>
#include <vector>

#include "mrt_spike/grid.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

class JumpPointSearch final : public GridPlanner {
 public:
  /// Reads `grid` at every query (it may change between queries).
  explicit JumpPointSearch(const OccupancyGrid& grid);
  /// Same contract as GridAstar::plan: octile-optimal length; the path's
  /// waypoints are the jump points (each segment a straight or diagonal run).
  PlanResult plan(const Cell& start, const Cell& goal) override;
  std::string name() const override { return "jps"; }
  PlannerCapabilities capabilities() const override { return kCapabilities; }
  static constexpr PlannerCapabilities kCapabilities{true, true};

 private:
  bool move_ok(int x, int y, int dx, int dy) const;
  bool jump(int x, int y, int dx, int dy, const Cell& goal, Cell& out) const;
  bool forced(int x, int y, int dx, int dy) const;
  const OccupancyGrid& grid_;
  std::vector<double> g_;
  std::vector<int> parent_;
  std::vector<unsigned> stamp_;
  std::vector<unsigned char> closed_;
  unsigned run_ = 0;
};

}  // namespace mrt::spike
