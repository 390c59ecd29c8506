// spike_plan: SPIKE (or the octile A* baseline, jump point search, or OMPL)
// on a Moving AI map; the algorithm by name (planner_factory.h).
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "mrt_common/cli.h"
#include "mrt_spike/line_of_sight.h"
#include "mrt_spike/movingai.h"
#include "mrt_spike/planner_factory.h"
#include "mrt_spike/scenario_run.h"

using namespace mrt::spike;

namespace {

struct Args {
  std::string map_file, scen_file, idx_file, out_file, algo = "spike";
  std::vector<int> start, goal;
  double radius = 0.0;
  bool refine = true;
  std::string vertices = "centre", graph = "subgoal";
  int max_leaf = 64;
  int landmarks = 16;
  std::string ompl_planner = "rrtstar";
  double ompl_time = 1.0;
};

void add_options(CLI::App& app, Args& a) {
  app.add_option("--map", a.map_file, "Moving AI .map file")->required();
  auto* o_start = app.add_option("--start", a.start, "start X Y")->expected(2);
  auto* o_goal = app.add_option("--goal", a.goal, "goal X Y")->expected(2);
  auto* o_scen = app.add_option("--scen", a.scen_file, ".scen file");
  app.add_option("--queries", a.idx_file, "file of query indices, one a line")->needs(o_scen);
  app.add_option("--algo", a.algo, "spike | astar | jps | ompl")->check(CLI::IsMember(planner_names()));
  app.add_option("--ompl-planner", a.ompl_planner, "OMPL planner for --algo ompl")
      ->check(CLI::IsMember({"rrtstar", "prmstar"}));
  app.add_option("--ompl-time", a.ompl_time, "OMPL time limit per query, s")->check(CLI::PositiveNumber);
  app.add_option("--out", a.out_file, "write the output here instead of stdout");
  app.add_option("--radius", a.radius, "inflation: robot radius + safety distance, in cells");
  app.add_option("--max-leaf", a.max_leaf, "largest quadtree leaf side, cells")->check(CLI::PositiveNumber);
  o_start->needs(o_goal);
  o_goal->needs(o_start);
  o_scen->excludes(o_start);
  app.add_option("--graph", a.graph, "SPIKE: search the subgoal graph or the quadtree's leaves")
      ->check(CLI::IsMember({"subgoal", "quadtree"}));
  app.add_option("--landmarks", a.landmarks, "SPIKE: landmarks of the differential heuristic (0: octile only)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--refine", a.refine, "SPIKE on the quadtree: octile A* in the corridor of the coarse path (1) or not (0)");
  app.add_option("--vertices", a.vertices, "SPIKE on the quadtree: one vertex per leaf (centre) or corners + centre")
      ->check(CLI::IsMember({"centre", "corners"}));
}

int run(const Args& a) {
  const OccupancyGrid grid = inflate(load_movingai_map(a.map_file), a.radius);
  std::ofstream file;
  if (!a.out_file.empty()) {
    file.open(a.out_file);
    if (!file) throw std::runtime_error(a.out_file + ": cannot write");
  }
  std::ostream& out = a.out_file.empty() ? std::cout : file;
  const auto t0 = std::chrono::steady_clock::now();
  PlannerOptions opts;
  opts.spike.quadtree.max_leaf_size = a.max_leaf;
  opts.spike.refine = a.refine;
  opts.spike.quadtree.centre_only = a.vertices == "centre";
  opts.spike.graph = a.graph == "subgoal" ? SpikeOptions::Graph::subgoal : SpikeOptions::Graph::quadtree;
  opts.spike.landmarks = a.landmarks;
  opts.ompl = OmplOptions{a.ompl_planner, a.ompl_time, 1};
  const std::unique_ptr<GridPlanner> planner = make_planner(a.algo, grid, opts);
  const double pre_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << "preprocessing_ms: " << pre_ms << " ms\n";
  PlanFn plan = [&](const Cell& s, const Cell& g) { return planner->plan(s, g); };
  if (!a.scen_file.empty()) {
    const auto scen = load_scenario(a.scen_file);
    const std::vector<int> idx = a.idx_file.empty() ? std::vector<int>{} : load_indices(a.idx_file);
    for (const auto& o : run_queries(grid, scen, idx, plan)) print_outcome(out, o);
    return 0;
  }
  QueryOutcome o;
  const Cell s{a.start[0], a.start[1]}, g{a.goal[0], a.goal[1]};
  const auto t1 = std::chrono::steady_clock::now();
  o.result = plan(s, g);
  o.time_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t1).count();
  if (!o.result.solved) {
    out << "no path: " << o.result.reason << "; nearest reachable point " << o.result.nearest.x << " "
        << o.result.nearest.y << "\n";
    return 1;
  }
  print_outcome(out, o);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"SPIKE planner on a Moving AI .map (cell coordinates: column x, row y)", "spike_plan"};
  Args a;
  add_options(app, a);
  const int rc = mrt::cli::parse_cli(app, argc, argv);
  if (rc >= 0) return rc;
  if (a.scen_file.empty() && a.start.empty()) {
    std::cerr << "spike_plan: give --start X Y --goal X Y or --scen FILE\n";
    return 2;
  }
  try {
    return run(a);
  } catch (const std::exception& e) {
    std::cerr << "spike_plan: " << e.what() << "\n";
    return 2;
  }
}
