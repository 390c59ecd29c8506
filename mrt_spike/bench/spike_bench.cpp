// spike_bench: SPIKE against the octile A* baseline on the same queries of
// Moving AI scenarios; prints `name: value unit` lines.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "mrt_spike/movingai.h"
#include "mrt_spike/planner.h"
#include "mrt_spike/scenario_run.h"
#include "msl_replan.h"

using namespace mrt::spike;
namespace fs = std::filesystem;

namespace {

void print_stats(const std::string& p, const RunStats& s, double pre_ms) {
  std::cout << p << ".queries: " << s.queries << " count\n"
            << p << ".solved: " << s.solved_pct << " %\n"
            << p << ".valid: " << s.valid_pct << " %\n"
            << p << ".max_length_ratio: " << s.max_ratio << " ratio\n"
            << p << ".mean_length_ratio: " << s.mean_ratio << " ratio\n"
            << p << ".median_time: " << s.median_us << " us\n"
            << p << ".p95_time: " << s.p95_us << " us\n"
            << p << ".mean_expansions: " << s.mean_expansions << " count\n"
            << p << ".preprocessing: " << pre_ms << " ms\n";
}

struct BenchOptions {
  int every = 10;
  double radius = 0.0;
  int max_leaf = 64;
  bool refine = true;
  std::string vertices = "centre";
  std::string graph = "subgoal";
  int scale = 1;
};

// Each cell becomes a scale x scale block (a 512 x 512 map becomes 1024 x 1024).
OccupancyGrid upscale(const OccupancyGrid& g, int k) {
  if (k == 1) return g;
  OccupancyGrid out(g.width() * k, g.height() * k);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) out.set_blocked(x, y, g.blocked(x / k, y / k));
  return out;
}

void bench_map(const std::string& map_file, const std::string& scen_file, const std::vector<int>& given,
               const BenchOptions& b) {
  const std::string name = fs::path(map_file).stem().string() + (b.scale > 1 ? "_x" + std::to_string(b.scale) : "");
  const OccupancyGrid grid = inflate(upscale(load_movingai_map(map_file), b.scale), b.radius);
  auto scen = load_scenario(scen_file);
  for (auto& q : scen) {
    q.start = {q.start.x * b.scale, q.start.y * b.scale};
    q.goal = {q.goal.x * b.scale, q.goal.y * b.scale};
  }
  std::vector<int> idx = given;
  if (idx.empty())
    for (size_t i = 0; i < scen.size(); i += static_cast<size_t>(b.every)) idx.push_back(static_cast<int>(i));
  auto t0 = std::chrono::steady_clock::now();
  SpikeOptions opts;
  opts.quadtree.max_leaf_size = b.max_leaf;
  opts.refine = b.refine;
  opts.quadtree.centre_only = b.vertices == "centre";
  opts.graph = b.graph == "subgoal" ? SpikeOptions::Graph::subgoal : SpikeOptions::Graph::quadtree;
  SpikePlanner spike(grid, opts);
  const double pre_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  GridAstar astar(grid);
  auto so = run_queries(grid, scen, idx, [&](const Cell& s, const Cell& g) { return spike.plan(s, g); });
  auto ao = run_queries(grid, scen, idx, [&](const Cell& s, const Cell& g) { return astar.plan(s, g); });
  if (b.scale > 1)  // the scenario's optimal length is for the original map: use the A*'s (optimal) one
    for (size_t i = 0; i < so.size(); ++i) so[i].optimal = ao[i].optimal = ao[i].result.length;
  const RunStats ss = summarize(so), as = summarize(ao);
  std::cout << name << ".width: " << grid.width() << " cells\n"
            << name << ".height: " << grid.height() << " cells\n"
            << name << ".leaves: " << spike.quadtree().leaves().size() << " count\n"
            << name << ".free_cells: " << grid.count_free() << " count\n";
  if (spike.subgoal_graph())
    std::cout << name << ".subgoals: " << spike.subgoal_graph()->subgoals().size() << " count\n"
              << name << ".subgoal_edges: " << spike.subgoal_graph()->edge_count() << " count\n";
  print_stats(name + ".spike", ss, pre_ms);
  std::cout << name << ".spike.fallbacks: " << ss.fallbacks << " count\n";
  print_stats(name + ".astar", as, 0.0);
  std::cout << name << ".speedup_median: " << (ss.median_us > 0 ? as.median_us / ss.median_us : 0.0)
            << " ratio\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"SPIKE vs octile A* on Moving AI maps"};
  std::string map_file, scen_file, idx_file, dir;
  BenchOptions b;
  auto* o_map = app.add_option("--map", map_file, "Moving AI .map file");
  app.add_option("--scen", scen_file, ".scen file (default: MAP.scen)");
  app.add_option("--queries", idx_file, "file of query indices, one a line");
  app.add_option("--dir", dir, "run every *.map with its *.map.scen in this directory")->excludes(o_map);
  app.add_option("--every", b.every, "run every N-th query (when no --queries)")->check(CLI::PositiveNumber);
  app.add_option("--radius", b.radius, "inflation in cells");
  app.add_option("--max-leaf", b.max_leaf, "largest quadtree leaf side")->check(CLI::PositiveNumber);
  app.add_option("--refine", b.refine, "SPIKE: octile A* in the corridor of the coarse path (1) or not (0)");
  app.add_option("--vertices", b.vertices, "SPIKE: one vertex per leaf (centre) or corners + centre")
      ->check(CLI::IsMember({"centre", "corners"}));
  app.add_option("--graph", b.graph, "SPIKE: search the subgoal graph or the quadtree's leaves")
      ->check(CLI::IsMember({"subgoal", "quadtree"}));
  app.add_option("--scale", b.scale, "upscale each map by this factor (cells become N x N blocks)")
      ->check(CLI::PositiveNumber);
  int msl_steps = 0, msl_robots = 10;
  app.add_option("--msl", msl_steps, "MSL field re-planning: this many 50 ms steps (then exit)");
  app.add_option("--msl-robots", msl_robots, "moving robots on the MSL field")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  if (msl_steps > 0) {
    bench_msl(msl_steps, msl_robots, 16);
    return 0;
  }
  try {
    const std::vector<int> idx = idx_file.empty() ? std::vector<int>{} : load_indices(idx_file);
    if (!dir.empty()) {
      std::vector<std::string> maps;
      for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".map" && fs::exists(e.path().string() + ".scen"))
          maps.push_back(e.path().string());
      std::sort(maps.begin(), maps.end());
      for (const auto& m : maps) bench_map(m, m + ".scen", idx, b);
      return 0;
    }
    if (map_file.empty()) {  // no arguments (scripts/bench.sh): the Moving AI set, else the test maps
      const char* env = std::getenv("MRT_SPIKE_BENCH_DIR");
      const std::string d = env ? env : fs::exists("../shared/bench/movingai") ? "../shared/bench/movingai"
                                                                            : MRT_SPIKE_DATA;
      std::cout << "# maps from " << d << "\n";
      for (const auto& e : fs::directory_iterator(d))
        if (e.path().extension() == ".map" && fs::exists(e.path().string() + ".scen"))
          bench_map(e.path().string(), e.path().string() + ".scen", idx, b);
      return 0;
    }
    bench_map(map_file, scen_file.empty() ? map_file + ".scen" : scen_file, idx, b);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "spike_bench: " << e.what() << "\n";
    return 2;
  }
}
