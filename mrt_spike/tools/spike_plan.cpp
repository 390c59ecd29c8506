// spike_plan: SPIKE (or the octile A* baseline) on a Moving AI map.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "mrt_spike/line_of_sight.h"
#include "mrt_spike/movingai.h"
#include "mrt_spike/planner.h"
#include "mrt_spike/scenario_run.h"

using namespace mrt::spike;

int main(int argc, char** argv) {
  CLI::App app{"SPIKE planner on a Moving AI .map (cell coordinates: column x, row y)"};
  std::string map_file, scen_file, idx_file, out_file, algo = "spike";
  std::vector<int> start, goal;
  double radius = 0.0;
  bool refine = true;
  std::string vertices = "centre";
  int max_leaf = 64;
  app.add_option("--map", map_file, "Moving AI .map file")->required();
  auto* o_start = app.add_option("--start", start, "start X Y")->expected(2);
  auto* o_goal = app.add_option("--goal", goal, "goal X Y")->expected(2);
  auto* o_scen = app.add_option("--scen", scen_file, ".scen file");
  app.add_option("--queries", idx_file, "file of query indices, one a line")->needs(o_scen);
  app.add_option("--algo", algo, "spike | astar")->check(CLI::IsMember({"spike", "astar"}));
  app.add_option("--out", out_file, "write the output here instead of stdout");
  app.add_option("--radius", radius, "inflation: robot radius + safety distance, in cells");
  app.add_option("--max-leaf", max_leaf, "largest quadtree leaf side, cells")->check(CLI::PositiveNumber);
  o_start->needs(o_goal);
  o_goal->needs(o_start);
  o_scen->excludes(o_start);
  app.add_option("--refine", refine, "SPIKE: octile A* in the corridor of the coarse path (1) or not (0)");
  app.add_option("--vertices", vertices, "SPIKE: one vertex per leaf (centre) or corners + centre")
      ->check(CLI::IsMember({"centre", "corners"}));
  CLI11_PARSE(app, argc, argv);
  if (scen_file.empty() && start.empty()) {
    std::cerr << "spike_plan: give --start X Y --goal X Y or --scen FILE\n";
    return 2;
  }
  try {
    const OccupancyGrid raw = load_movingai_map(map_file);
    const OccupancyGrid grid = inflate(raw, radius);
    std::ofstream file;
    if (!out_file.empty()) {
      file.open(out_file);
      if (!file) throw std::runtime_error(out_file + ": cannot write");
    }
    std::ostream& out = out_file.empty() ? std::cout : file;
    const auto t0 = std::chrono::steady_clock::now();
    SpikeOptions opts;
    opts.quadtree.max_leaf_size = max_leaf;
  opts.refine = refine;
  opts.quadtree.centre_only = vertices == "centre";
    std::unique_ptr<SpikePlanner> spike;
    std::unique_ptr<GridAstar> astar;
    if (algo == "spike") spike = std::make_unique<SpikePlanner>(grid, opts);
    else astar = std::make_unique<GridAstar>(grid);
    const double pre_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::cerr << "preprocessing_ms: " << pre_ms << " ms\n";
    PlanFn plan = [&](const Cell& s, const Cell& g) { return spike ? spike->plan(s, g) : astar->plan(s, g); };
    if (!scen_file.empty()) {
      const auto scen = load_scenario(scen_file);
      const std::vector<int> idx = idx_file.empty() ? std::vector<int>{} : load_indices(idx_file);
      for (const auto& o : run_queries(grid, scen, idx, plan)) print_outcome(out, o);
      return 0;
    }
    QueryOutcome o;
    const Cell s{start[0], start[1]}, g{goal[0], goal[1]};
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
  } catch (const std::exception& e) {
    std::cerr << "spike_plan: " << e.what() << "\n";
    return 2;
  }
}
