// OMPL's sampling planners (RRT*, PRM*) as SPIKE's continuous option and
// baseline: the plane of the map, a state valid when its cell is free.
#pragma once

#include <memory>
#include <string>

#include "mrt_spike/grid.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

struct OmplOptions {
  std::string planner = "rrtstar";  ///< rrtstar | prmstar
  double time_limit = 1.0;           ///< s per query (both planners use all of it to improve)
  unsigned seed = 1;                 ///< OMPL's RNG seed (repeatable runs)
};

/// Plans in the continuous plane [-0.5, w - 0.5] x [-0.5, h - 0.5], states
/// checked every half cell along motions, then simplifies the path. The
/// waypoints are rounded to cells (the first the start, the last the goal);
/// `solved` only for an exact solution. Validity by the rule is
/// checked by the caller (the bench reports it): its paths are not valid by
/// construction. It reads the grid at every query.
class OmplPlanner final : public GridPlanner {
 public:
  OmplPlanner(const OccupancyGrid& grid, OmplOptions options = {});
  ~OmplPlanner() override;
  PlanResult plan(const Cell& start, const Cell& goal) override;
  std::string name() const override { return "ompl"; }
  PlannerCapabilities capabilities() const override { return kCapabilities; }
  static constexpr PlannerCapabilities kCapabilities{true, false};

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mrt::spike
