// Running scenario queries with a planner and printing the format.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "mrt_spike/movingai.h"
#include "mrt_spike/planner.h"

namespace mrt::spike {

struct QueryOutcome {
  int index = 0;
  PlanResult result;
  double time_us = 0.0;        ///< wall clock
  double cpu_us = 0.0;         ///< CPU time of the calling thread (not inflated by preemption)
  bool valid = false;         ///< by the issue's rule (checked after timing)
  double optimal = 0.0;       ///< scenario's optimal octile length
};

using PlanFn = std::function<PlanResult(const Cell&, const Cell&)>;

/// Runs the queries of `scen` with the given indices (all when empty), times
/// each plan call alone, then checks the path. Throws std::out_of_range for
/// an index past the end.
std::vector<QueryOutcome> run_queries(const OccupancyGrid& grid, const std::vector<ScenarioQuery>& scen,
                                      const std::vector<int>& indices, const PlanFn& plan);

/// `query <index> solved <0|1> length <L> time_us <t>` and, when solved,
/// `path <index> x0 y0 ... xn yn`.
void print_outcome(std::ostream& out, const QueryOutcome& q);

/// Summary over outcomes.
struct RunStats {
  int queries = 0;
  double solved_pct = 0.0;
  double valid_pct = 0.0;
  double max_ratio = 0.0;
  double mean_ratio = 0.0;
  double median_us = 0.0;
  double p95_us = 0.0;
  double median_cpu_us = 0.0;  ///< thread CPU time
  double p95_cpu_us = 0.0;
  int fallbacks = 0;
  double mean_expansions = 0.0;
};
RunStats summarize(const std::vector<QueryOutcome>& outcomes);

}  // namespace mrt::spike
