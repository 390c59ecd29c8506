#include "mrt_spike/scenario_run.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <iomanip>
#include <stdexcept>

#include "mrt_spike/line_of_sight.h"

namespace mrt::spike {

namespace {
// CPU time of this thread, µs (what preemption on a shared machine does not inflate)
double thread_cpu_us() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e6 + t.tv_nsec * 1e-3;
}
}  // namespace

std::vector<QueryOutcome> run_queries(const OccupancyGrid& grid, const std::vector<ScenarioQuery>& scen,
                                      const std::vector<int>& indices, const PlanFn& plan) {
  std::vector<int> idx = indices;
  if (idx.empty())
    for (size_t i = 0; i < scen.size(); ++i) idx.push_back(static_cast<int>(i));
  std::vector<QueryOutcome> out;
  out.reserve(idx.size());
  for (int i : idx) {
    if (i < 0 || static_cast<size_t>(i) >= scen.size())
      throw std::out_of_range("query index " + std::to_string(i) + " out of range (scenario has " +
                              std::to_string(scen.size()) + " queries)");
    const ScenarioQuery& q = scen[i];
    QueryOutcome o;
    o.index = i;
    o.optimal = q.optimal_length;
    const double c0 = thread_cpu_us();
    const auto t0 = std::chrono::steady_clock::now();
    o.result = plan(q.start, q.goal);
    const auto t1 = std::chrono::steady_clock::now();
    o.cpu_us = thread_cpu_us() - c0;
    o.time_us = std::chrono::duration<double, std::micro>(t1 - t0).count();
    o.valid = o.result.solved && path_valid(grid, o.result.path, q.start, q.goal);
    out.push_back(std::move(o));
  }
  return out;
}

void print_outcome(std::ostream& out, const QueryOutcome& q) {
  out << "query " << q.index << " solved " << (q.result.solved ? 1 : 0) << " length " << std::fixed
      << std::setprecision(6) << (q.result.solved ? q.result.length : 0.0) << " time_us "
      << std::setprecision(1) << q.time_us << "\n";
  if (!q.result.solved) return;
  out << "path " << q.index;
  for (const Cell& c : q.result.path) out << " " << c.x << " " << c.y;
  out << "\n";
}

RunStats summarize(const std::vector<QueryOutcome>& outcomes) {
  RunStats s;
  s.queries = static_cast<int>(outcomes.size());
  if (outcomes.empty()) return s;
  std::vector<double> times, cpu;
  int solved = 0, valid = 0, rated = 0;
  double sum_ratio = 0.0;
  for (const auto& o : outcomes) {
    times.push_back(o.time_us);
    cpu.push_back(o.cpu_us);
    s.mean_expansions += o.result.expansions / static_cast<double>(outcomes.size());
    if (o.result.fallback) ++s.fallbacks;
    if (!o.result.solved) continue;
    ++solved;
    if (o.valid) ++valid;
    if (o.optimal > 0.0) {
      const double r = o.result.length / o.optimal;
      s.max_ratio = std::max(s.max_ratio, r);
      sum_ratio += r;
      ++rated;
    }
  }
  s.solved_pct = 100.0 * solved / s.queries;
  s.valid_pct = 100.0 * valid / s.queries;
  s.mean_ratio = rated ? sum_ratio / rated : 0.0;
  std::sort(times.begin(), times.end());
  s.median_us = times[times.size() / 2];
  s.p95_us = times[std::min(times.size() - 1, static_cast<size_t>(0.95 * times.size()))];
  std::sort(cpu.begin(), cpu.end());
  s.median_cpu_us = cpu[cpu.size() / 2];
  s.p95_cpu_us = cpu[std::min(cpu.size() - 1, static_cast<size_t>(0.95 * cpu.size()))];
  return s;
}

}  // namespace mrt::spike
