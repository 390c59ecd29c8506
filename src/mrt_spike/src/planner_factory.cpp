#include "mrt_spike/planner_factory.h"

#include <stdexcept>

#include "mrt_spike/jump_point_search.h"

namespace mrt::spike {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

/// Why `info` cannot plan among moving obstacles ("" when it can).
std::string dynamic_problem(const PlannerInfo& info) {
  if (info.name == "spike") return "";  // DynamicSpike
  if (!info.capabilities.follows_grid_changes)
    return "it builds its structure once and would not see the moving obstacles' footprints";
  if (!info.capabilities.valid_paths)
    return "its paths are not valid by the grid's line-of-sight rule, so a plan blocked by a moving obstacle "
           "could not be detected and re-planned";
  return "";
}

/// An algorithm that follows the grid's changes, planning on the grid of an
/// obstacle layer it owns.
class LayeredPlanner final : public DynamicPlanner {
 public:
  LayeredPlanner(const std::string& name, const OccupancyGrid& static_grid, double inflation, double horizon,
                 const PlannerOptions& options)
      : layer_(static_grid, inflation, horizon), planner_(make_planner(name, layer_.grid(), options)) {}
  ObstacleLayer& obstacles() override { return layer_; }
  const ObstacleLayer& obstacles() const override { return layer_; }
  PlanResult plan(const Cell& start, const Cell& goal) override { return planner_->plan(start, goal); }
  std::string name() const override { return planner_->name(); }
  PlannerCapabilities capabilities() const override { return planner_->capabilities(); }

 private:
  ObstacleLayer layer_;
  std::unique_ptr<GridPlanner> planner_;
};

}  // namespace

const std::vector<PlannerInfo>& planners() {
  static const std::vector<PlannerInfo> registry{
      {"spike", "SPIKE: subgoal graph (or quadtree) search, then string pulling", SpikePlanner::kCapabilities},
      {"astar", "octile A* on the grid (the baseline)", GridAstar::kCapabilities},
      {"jps", "jump point search on the grid (octile-optimal, no preprocessing)", JumpPointSearch::kCapabilities},
      {"ompl", "OMPL's RRT* or PRM* in the plane of the grid", OmplPlanner::kCapabilities},
  };
  return registry;
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const PlannerInfo& p : planners()) names.push_back(p.name);
  return names;
}

const PlannerInfo& planner_info(const std::string& name) {
  for (const PlannerInfo& p : planners())
    if (p.name == name) return p;
  throw std::invalid_argument("unknown planner '" + name + "' (known: " + joined(planner_names()) + ")");
}

std::unique_ptr<GridPlanner> make_planner(const std::string& name, const OccupancyGrid& grid,
                                          const PlannerOptions& options) {
  planner_info(name);  // throws for an unknown name
  if (name == "spike") return std::make_unique<SpikePlanner>(grid, options.spike);
  if (name == "astar") return std::make_unique<GridAstar>(grid);
  if (name == "jps") return std::make_unique<JumpPointSearch>(grid);
  return std::make_unique<OmplPlanner>(grid, options.ompl);
}

std::vector<std::string> dynamic_planner_names() {
  std::vector<std::string> names;
  for (const PlannerInfo& p : planners())
    if (dynamic_problem(p).empty()) names.push_back(p.name);
  return names;
}

void check_dynamic_planner(const std::string& name) {
  const std::string why = dynamic_problem(planner_info(name));
  if (!why.empty())
    throw std::invalid_argument("planner '" + name + "' cannot plan among moving obstacles: " + why +
                                " (use one of: " + joined(dynamic_planner_names()) + ")");
}

std::unique_ptr<DynamicPlanner> make_dynamic_planner(const std::string& name, const OccupancyGrid& static_grid,
                                                     double inflation, double horizon,
                                                     const PlannerOptions& options) {
  check_dynamic_planner(name);
  if (name == "spike") return std::make_unique<DynamicSpike>(static_grid, inflation, horizon, options.spike);
  return std::make_unique<LayeredPlanner>(name, static_grid, inflation, horizon, options);
}

}  // namespace mrt::spike
