#include "mrt_spike/ompl_planner.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrt_spike/line_of_sight.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mrt::spike {

struct OmplPlanner::Impl {
  const OccupancyGrid& grid;
  OmplOptions options;
};

OmplPlanner::OmplPlanner(const OccupancyGrid& grid, OmplOptions options) : impl_(new Impl{grid, options}) {
  if (options.planner != "rrtstar" && options.planner != "prmstar")
    throw std::invalid_argument("unknown OMPL planner '" + options.planner + "' (expected rrtstar or prmstar)");
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(options.seed);
}

OmplPlanner::~OmplPlanner() = default;

PlanResult OmplPlanner::plan(const Cell& start, const Cell& goal) {
  const OccupancyGrid& g = impl_->grid;
  if (g.blocked(start.x, start.y) || g.blocked(goal.x, goal.y)) return diagnose(g, start, goal);
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds b(2);
  b.setLow(0, -0.5), b.setHigh(0, g.width() - 0.5);
  b.setLow(1, -0.5), b.setHigh(1, g.height() - 0.5);
  space->setBounds(b);
  space->setLongestValidSegmentFraction(0.5 / std::hypot(g.width(), g.height()));  // every half cell
  og::SimpleSetup ss(space);
  ss.setStateValidityChecker([&g](const ob::State* s) {
    const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
    return g.free(static_cast<int>(std::lround(v->values[0])), static_cast<int>(std::lround(v->values[1])));
  });
  if (impl_->options.planner == "rrtstar") ss.setPlanner(std::make_shared<og::RRTstar>(ss.getSpaceInformation()));
  else ss.setPlanner(std::make_shared<og::PRMstar>(ss.getSpaceInformation()));
  ob::ScopedState<> s(space), t(space);
  s[0] = start.x, s[1] = start.y, t[0] = goal.x, t[1] = goal.y;
  ss.setStartAndGoalStates(s, t, 0.5);
  PlanResult r;
  const ob::PlannerStatus st = ss.solve(impl_->options.time_limit);
  if (st != ob::PlannerStatus::EXACT_SOLUTION) {
    r.reason = "OMPL found no exact solution in " + std::to_string(impl_->options.time_limit) + " s";
    r.nearest = start;
    return r;
  }
  ss.simplifySolution();
  for (const ob::State* q : ss.getSolutionPath().getStates()) {
    const auto* v = q->as<ob::RealVectorStateSpace::StateType>();
    const Cell c{static_cast<int>(std::lround(v->values[0])), static_cast<int>(std::lround(v->values[1]))};
    if (r.path.empty() || r.path.back() != c) r.path.push_back(c);
  }
  if (r.path.empty() || r.path.front() != start) r.path.insert(r.path.begin(), start);
  if (r.path.back() != goal) r.path.push_back(goal);
  r.solved = true;
  r.length = path_length(r.path);
  return r;
}

}  // namespace mrt::spike
