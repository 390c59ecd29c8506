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
            << p << ".preprocessing: " << pre_ms << " ms\n";
}

void bench_map(const std::string& map_file, const std::string& scen_file, const std::vector<int>& given,
               int every, double radius, int max_leaf, bool refine,
               const std::string& vertices) {
  const std::string name = fs::path(map_file).stem().string();
  const OccupancyGrid grid = inflate(load_movingai_map(map_file), radius);
  const auto scen = load_scenario(scen_file);
  std::vector<int> idx = given;
  if (idx.empty())
    for (size_t i = 0; i < scen.size(); i += static_cast<size_t>(every)) idx.push_back(static_cast<int>(i));
  auto t0 = std::chrono::steady_clock::now();
  SpikeOptions opts;
  opts.quadtree.max_leaf_size = max_leaf;
  opts.refine = refine;
  opts.quadtree.centre_only = vertices == "centre";
  SpikePlanner spike(grid, opts);
  const double pre_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  GridAstar astar(grid);
  const auto so = run_queries(grid, scen, idx, [&](const Cell& s, const Cell& g) { return spike.plan(s, g); });
  const auto ao = run_queries(grid, scen, idx, [&](const Cell& s, const Cell& g) { return astar.plan(s, g); });
  const RunStats ss = summarize(so), as = summarize(ao);
  std::cout << name << ".width: " << grid.width() << " cells\n"
            << name << ".height: " << grid.height() << " cells\n"
            << name << ".leaves: " << spike.quadtree().leaves().size() << " count\n"
            << name << ".free_cells: " << grid.count_free() << " count\n";
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
  int every = 10, max_leaf = 64;
  double radius = 0.0;
  bool refine = true;
  std::string vertices = "centre";
  auto* o_map = app.add_option("--map", map_file, "Moving AI .map file");
  app.add_option("--scen", scen_file, ".scen file (default: MAP.scen)");
  app.add_option("--queries", idx_file, "file of query indices, one a line");
  app.add_option("--dir", dir, "run every *.map with its *.map.scen in this directory")->excludes(o_map);
  app.add_option("--every", every, "run every N-th query (when no --queries)")->check(CLI::PositiveNumber);
  app.add_option("--radius", radius, "inflation in cells");
  app.add_option("--max-leaf", max_leaf, "largest quadtree leaf side")->check(CLI::PositiveNumber);
  app.add_option("--refine", refine, "SPIKE: octile A* in the corridor of the coarse path (1) or not (0)");
  app.add_option("--vertices", vertices, "SPIKE: one vertex per leaf (centre) or corners + centre")
      ->check(CLI::IsMember({"centre", "corners"}));
  CLI11_PARSE(app, argc, argv);
  try {
    const std::vector<int> idx = idx_file.empty() ? std::vector<int>{} : load_indices(idx_file);
    if (!dir.empty()) {
      std::vector<std::string> maps;
      for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".map" && fs::exists(e.path().string() + ".scen"))
          maps.push_back(e.path().string());
      std::sort(maps.begin(), maps.end());
      for (const auto& m : maps) bench_map(m, m + ".scen", idx, every, radius, max_leaf, refine, vertices);
      return 0;
    }
    if (map_file.empty()) {  // no arguments (scripts/bench.sh): the Moving AI set, else the test maps
      const char* env = std::getenv("MRT_SPIKE_BENCH_DIR");
      const std::string d = env ? env : fs::exists("../shared/bench/movingai") ? "../shared/bench/movingai"
                                                                            : MRT_SPIKE_DATA;
      std::cout << "# maps from " << d << "\n";
      for (const auto& e : fs::directory_iterator(d))
        if (e.path().extension() == ".map" && fs::exists(e.path().string() + ".scen"))
          bench_map(e.path().string(), e.path().string() + ".scen", idx, every, radius, max_leaf, refine, vertices);
      return 0;
    }
    bench_map(map_file, scen_file.empty() ? map_file + ".scen" : scen_file, idx, every, radius, max_leaf, refine, vertices);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "spike_bench: " << e.what() << "\n";
    return 2;
  }
}
