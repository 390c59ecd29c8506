// spike_bench: SPIKE against the octile A* baseline on the same queries of
// Moving AI scenarios; prints `name: value unit` lines.
#include "mrt_common/cli.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <iostream>

#include "mrt_spike/movingai.h"
#include "mrt_spike/ompl_planner.h"
#include "mrt_spike/planner.h"
#include "mrt_spike/planner_factory.h"
#include "mrt_spike/scenario_run.h"
#include "building_route.h"
#include "msl_replan.h"
#include "smoothing_bench.h"

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
            << p << ".median_cpu_time: " << s.median_cpu_us << " us\n"
            << p << ".p95_cpu_time: " << s.p95_cpu_us << " us\n"
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
  int landmarks = 16;       ///< differential heuristic over the subgoal graph (0: octile only)
  int ompl = 0;             ///< OMPL's RRT* and PRM* on the first N queries (0: not run)
  double ompl_time = 1.0;   ///< s per OMPL query
  std::string algo = "spike";           ///< the algorithm measured against the A* (spike_plan's --algo)
  std::string ompl_planner = "rrtstar";  ///< for --algo ompl
  std::string out_file;                 ///< the measured algorithm's outcomes, spike_plan's format
};

void bench_ompl(const std::string& name, const OccupancyGrid& grid, const std::vector<ScenarioQuery>& scen,
                const std::vector<int>& idx, const BenchOptions& b) {
  const std::vector<int> first(idx.begin(), idx.begin() + std::min<size_t>(idx.size(), b.ompl));
  for (const char* planner : {"rrtstar", "prmstar"}) {
    OmplPlanner op(grid, {planner, b.ompl_time, 1});
    auto oo = run_queries(grid, scen, first, [&](const Cell& s, const Cell& g) { return op.plan(s, g); });
    if (b.scale > 1) {  // optimal length from the A* on the upscaled map
      GridAstar a(grid);
      for (auto& o : oo) o.optimal = a.plan(scen[o.index].start, scen[o.index].goal).length;
    }
    const RunStats st = summarize(oo);
    const std::string p = name + ".ompl_" + planner;
    std::cout << p << ".queries: " << st.queries << " count\n"
              << p << ".time_limit: " << b.ompl_time << " s\n"
              << p << ".solved: " << st.solved_pct << " %\n"
              << p << ".valid: " << st.valid_pct << " %\n"
              << p << ".max_length_ratio: " << st.max_ratio << " ratio\n"
              << p << ".mean_length_ratio: " << st.mean_ratio << " ratio\n";
  }
}

// Each cell becomes a scale x scale block (a 512 x 512 map becomes 1024 x 1024).
OccupancyGrid upscale(const OccupancyGrid& g, int k) {
  if (k == 1) return g;
  OccupancyGrid out(g.width() * k, g.height() * k);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) out.set_blocked(x, y, g.blocked(x / k, y / k));
  return out;
}

// The scenario's queries as the benchmark runs them: scaled with the map,
// every `every`-th one unless the indices are given.
std::vector<int> scale_queries(std::vector<ScenarioQuery>* scen, const std::vector<int>& given,
                               const BenchOptions& b) {
  for (auto& q : *scen) {
    q.start = {q.start.x * b.scale, q.start.y * b.scale};
    q.goal = {q.goal.x * b.scale, q.goal.y * b.scale};
  }
  std::vector<int> idx = given;
  if (idx.empty())
    for (size_t i = 0; i < scen->size(); i += static_cast<size_t>(b.every)) idx.push_back(static_cast<int>(i));
  return idx;
}

// The measured algorithm (`--algo`, SPIKE by default) against the octile A*
// on the same queries; `astar_optimal`: the A*'s lengths are the optimal
// ones (an upscaled map, or a query with no scenario behind it). With
// `--out`, the measured algorithm's outcomes in spike_plan's format.
void bench_queries(const std::string& name, const OccupancyGrid& grid, const std::vector<ScenarioQuery>& scen,
                   const std::vector<int>& idx, bool astar_optimal, const BenchOptions& b) {
  auto t0 = std::chrono::steady_clock::now();
  PlannerOptions opts;
  opts.spike.quadtree.max_leaf_size = b.max_leaf;
  opts.spike.refine = b.refine;
  opts.spike.quadtree.centre_only = b.vertices == "centre";
  opts.spike.graph = b.graph == "subgoal" ? SpikeOptions::Graph::subgoal : SpikeOptions::Graph::quadtree;
  opts.spike.landmarks = b.landmarks;
  opts.ompl = OmplOptions{b.ompl_planner, b.ompl_time, 1};
  std::unique_ptr<SpikePlanner> spike;  // SPIKE itself, for its own figures
  std::unique_ptr<GridPlanner> other;
  if (b.algo == "spike") spike = std::make_unique<SpikePlanner>(grid, opts.spike);
  else other = make_planner(b.algo, grid, opts);
  const double pre_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  GridAstar astar(grid);
  auto so = run_queries(grid, scen, idx, [&](const Cell& s, const Cell& g) {
    return spike ? spike->plan(s, g) : other->plan(s, g);
  });
  auto ao = run_queries(grid, scen, idx, [&](const Cell& s, const Cell& g) { return astar.plan(s, g); });
  if (astar_optimal)
    for (size_t i = 0; i < so.size(); ++i) so[i].optimal = ao[i].optimal = ao[i].result.length;
  if (!b.out_file.empty()) {
    std::ofstream out(b.out_file);
    for (const auto& o : so) print_outcome(out, o);
    if (!out) throw std::runtime_error(b.out_file + ": cannot write");
  }
  const RunStats ss = summarize(so), as = summarize(ao);
  std::cout << name << ".width: " << grid.width() << " cells\n"
            << name << ".height: " << grid.height() << " cells\n";
  if (spike) {
    std::cout << name << ".leaves: " << spike->quadtree().leaves().size() << " count\n";
  }
  std::cout << name << ".free_cells: " << grid.count_free() << " count\n";
  if (spike && spike->subgoal_graph())
    std::cout << name << ".subgoals: " << spike->subgoal_graph()->subgoals().size() << " count\n"
              << name << ".subgoal_edges: " << spike->subgoal_graph()->edge_count() << " count\n";
  print_stats(name + "." + b.algo, ss, pre_ms);
  if (spike) std::cout << name << ".spike.fallbacks: " << ss.fallbacks << " count\n";
  print_stats(name + ".astar", as, 0.0);
  std::cout << name << ".speedup_median: " << (ss.median_us > 0 ? as.median_us / ss.median_us : 0.0)
            << " ratio\n"
            << name << ".speedup_median_cpu: " << (ss.median_cpu_us > 0 ? as.median_cpu_us / ss.median_cpu_us : 0.0)
            << " ratio\n";
  if (b.ompl > 0) bench_ompl(name, grid, scen, idx, b);
}

void bench_map(const std::string& map_file, const std::string& scen_file, const std::vector<int>& given,
               const BenchOptions& b) {
  const std::string name = fs::path(map_file).stem().string() + (b.scale > 1 ? "_x" + std::to_string(b.scale) : "");
  const OccupancyGrid grid = inflate(upscale(load_movingai_map(map_file), b.scale), b.radius);
  auto scen = load_scenario(scen_file);
  const std::vector<int> idx = scale_queries(&scen, given, b);
  bench_queries(name, grid, scen, idx, b.scale > 1, b);
}

// One query given by --start and --goal (cell coordinates of the map as
// given, scaled with it).
void bench_query(const std::string& map_file, const std::vector<int>& start, const std::vector<int>& goal,
                 const BenchOptions& b) {
  const std::string name = fs::path(map_file).stem().string() + (b.scale > 1 ? "_x" + std::to_string(b.scale) : "");
  const OccupancyGrid grid = inflate(upscale(load_movingai_map(map_file), b.scale), b.radius);
  std::vector<ScenarioQuery> scen(1);
  scen[0].start = {start[0], start[1]};
  scen[0].goal = {goal[0], goal[1]};
  const std::vector<int> idx = scale_queries(&scen, {}, b);
  bench_queries(name, grid, scen, idx, true, b);
}

struct MainArgs {
  std::string map_file, scen_file, idx_file, dir;
  std::vector<int> start, goal;
  int msl_steps = 0, msl_robots = 10;
  bool building = false;
  std::string smoothing;  ///< --smoothing: dubins | reeds_shepp (then exit)
  SmoothingBenchOptions smooth{"dubins", 0.3, MRT_WORLDS_DIR "/museum.yaml"};
};

// spike_plan's options (issue 16: "spike_bench with the same options"),
// then the benchmark's own.
void add_options(CLI::App& app, MainArgs& m, BenchOptions& b) {
  auto* o_map = app.add_option("--map", m.map_file, "Moving AI .map file");
  auto* o_start = app.add_option("--start", m.start, "start X Y (one query, with --goal)")->expected(2)->needs(o_map);
  auto* o_goal = app.add_option("--goal", m.goal, "goal X Y")->expected(2)->needs(o_start);
  o_start->needs(o_goal);
  app.add_option("--scen", m.scen_file, ".scen file (default: MAP.scen)")->excludes(o_start);
  app.add_option("--algo", b.algo, "the algorithm measured against the octile A*: spike | astar | jps | ompl")
      ->check(CLI::IsMember(planner_names()));
  app.add_option("--ompl-planner", b.ompl_planner, "OMPL planner for --algo ompl")
      ->check(CLI::IsMember({"rrtstar", "prmstar"}));
  app.add_option("--out", b.out_file, "write the measured algorithm's outcomes here (spike_plan's format)");
  app.add_option("--queries", m.idx_file, "file of query indices, one a line");
  app.add_option("--dir", m.dir, "run every *.map with its *.map.scen in this directory")->excludes(o_map);
  app.add_option("--every", b.every, "run every N-th query (when no --queries)")->check(CLI::PositiveNumber);
  app.add_option("--radius", b.radius, "inflation in cells");
  app.add_option("--max-leaf", b.max_leaf, "largest quadtree leaf side")->check(CLI::PositiveNumber);
  app.add_option("--refine", b.refine, "SPIKE on the quadtree: octile A* in the corridor of the coarse path (1) or not (0)");
  app.add_option("--vertices", b.vertices, "SPIKE on the quadtree: one vertex per leaf (centre) or corners + centre")
      ->check(CLI::IsMember({"centre", "corners"}));
  app.add_option("--graph", b.graph, "SPIKE: search the subgoal graph or the quadtree's leaves")
      ->check(CLI::IsMember({"subgoal", "quadtree"}));
  app.add_option("--landmarks", b.landmarks, "SPIKE: landmarks of the differential heuristic (0: octile only)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--scale", b.scale, "upscale each map by this factor (cells become N x N blocks)")
      ->check(CLI::PositiveNumber);
  app.add_option("--msl", m.msl_steps, "MSL field re-planning: this many 50 ms steps (then exit)");
  app.add_option("--msl-robots", m.msl_robots, "moving robots on the MSL field")->check(CLI::PositiveNumber);
  app.add_option("--ompl", b.ompl, "also run OMPL's RRT* and PRM* on the first N queries of each map");
  app.add_option("--ompl-time", b.ompl_time, "OMPL time limit per query, s")->check(CLI::PositiveNumber);
  app.add_flag("--building", m.building, "the long route on an office floor (then exit)");
  app.add_option("--smoothing", m.smoothing, "SPIKE's paths against their Dubins or Reeds-Shepp smoothing (then exit)")
      ->check(CLI::IsMember({"dubins", "reeds_shepp"}));
  app.add_option("--turning-radius", m.smooth.turning_radius, "--smoothing: minimum turning radius, m")
      ->check(CLI::PositiveNumber);
  app.add_option("--world", m.smooth.world, "--smoothing: world or map_server YAML (default: mrt_world's museum)");
  app.add_option("--world-resolution", m.smooth.resolution, "--smoothing: cell size for a world file, m")
      ->check(CLI::PositiveNumber);
  app.add_option("--world-queries", m.smooth.queries, "--smoothing: random queries between free cells")
      ->check(CLI::PositiveNumber);
}

void run_dir(const std::string& dir, const std::vector<int>& idx, const BenchOptions& b) {
  std::vector<std::string> maps;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".map" && fs::exists(e.path().string() + ".scen")) maps.push_back(e.path().string());
  std::sort(maps.begin(), maps.end());
  mrt::cli::Progress progress("spike_bench maps", static_cast<double>(maps.size()));
  for (std::size_t i = 0; i < maps.size(); ++i) {
    progress.update(static_cast<double>(i));
    progress.finish();  // the map's figures follow on their own lines
    bench_map(maps[i], maps[i] + ".scen", idx, b);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"SPIKE vs octile A* on Moving AI maps, the MSL field, a building", "spike_bench"};
  MainArgs m;
  BenchOptions b;
  add_options(app, m, b);
  const int rc = mrt::cli::parse_cli(app, argc, argv);
  if (rc >= 0) return rc;
  try {
    if (m.building) {
      bench_building();
      return 0;
    }
    if (!m.smoothing.empty()) {
      m.smooth.model = m.smoothing;
      bench_smoothing(m.smooth);
      return 0;
    }
    if (m.msl_steps > 0) {
      bench_msl(m.msl_steps, m.msl_robots, 16);
      return 0;
    }
    const std::vector<int> idx = m.idx_file.empty() ? std::vector<int>{} : load_indices(m.idx_file);
    if (!m.dir.empty()) {
      run_dir(m.dir, idx, b);
    } else if (m.map_file.empty()) {  // no arguments (scripts/bench.sh): everything
      const char* env = std::getenv("MRT_SPIKE_BENCH_DIR");
      const std::string d = env ? env : fs::exists("../shared/bench/movingai") ? "../shared/bench/movingai"
                                                                            : MRT_SPIKE_DATA;
      std::cout << "# maps from " << d << "\n";
      run_dir(d, idx, b);
      bench_msl(1000, 10, 16);
      bench_building();
    } else if (!m.start.empty()) {
      bench_query(m.map_file, m.start, m.goal, b);
    } else {
      bench_map(m.map_file, m.scen_file.empty() ? m.map_file + ".scen" : m.scen_file, idx, b);
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "spike_bench: " << e.what() << "\n";
    return 2;
  }
}
