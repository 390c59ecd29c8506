// The coordination figures of issue 18, on a synthetic team of 5 robots and
// 20 activities (12 jobs, 8 schemata with 2-3 roles):
//   cycle time of an allocation; mean utility of the exact allocator, of
//   greedy + local search and of plain greedy against an exhaustive
//   branch-and-bound optimum; re-assignments under 5 cm noise in
//   quasi-static scenes; consistency of five coordinators with 20 % message
//   loss and up to 100 ms delay in a simulated game, and coverage after a
//   drop-out.
#include "coordination_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include <time.h>

#include "mrt_common/cli.h"
#include "mrt_scare/situation.h"

namespace mrt::scare::bench {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kRobots = 5;

/// CPU time of the calling thread, ms: what the cycle costs on its core,
/// without the time the scheduler gives to other processes (wall time on
/// this shared machine also counts those).
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

void print_distribution(const char* name, std::vector<double> v) {
  double sum = 0.0;
  for (double x : v) sum += x;
  std::sort(v.begin(), v.end());
  std::printf("%s_mean: %.3f ms\n", name, sum / static_cast<double>(v.size()));
  std::printf("%s_median: %.3f ms\n", name, v[v.size() / 2]);
  std::printf("%s_p99: %.3f ms\n", name, v[v.size() * 99 / 100]);
  std::printf("%s_max: %.3f ms\n", name, v.back());
}

/// 20 activities over six crisp data (ball, four "need" degrees).
std::string synthetic_yaml() {
  std::ostringstream y;
  y << "fuzzy:\n  shapes: |\n    (UNIT (TOR (HIGH 0 1)) (TOL (LOW 0 1)))\n"
       "    (FIELDX (TOL (OWN -6 6)) (TOR (OPP -6 6)))\n"
       "  data: \"(BallX FIELDX) (N0 UNIT) (N1 UNIT) (N2 UNIT) (N3 UNIT)\"\nactivities:\n";
  const char* side[] = {"OWN", "OPP"};
  for (int j = 0; j < 12; ++j) {
    y << "  - {name: Job" << j << ", opportunity: (AND (D N" << j % 4 << " HIGH) (D BallX " << side[j % 2]
      << ")), priority: " << 1.0 + 0.1 * (j % 3) << ", max: " << 1 + (j % 4 == 3);
    if (j % 3 == 0)
      y << ", target: [BallX, BallY]}\n";
    else
      y << ", target: [" << -8 + 1.5 * j << ", " << ((j % 2) ? 3 : -3) << "]}\n";
  }
  for (int s = 0; s < 8; ++s) {
    y << "  - name: Schema" << s << "\n    opportunity: (AND (D N" << s % 4 << " HIGH) (NOT (D N" << (s + 1) % 4
      << " HIGH)))\n    roles:\n      - {name: a, target: [BallX, BallY]}\n      - {name: b, target: ["
      << -6 + 1.7 * s << ", " << ((s % 2) ? -2 : 2) << "]}\n";
    if (s % 2 == 1) y << "      - {name: c, target: [" << 5 - s << ", 0]}\n";
  }
  y << "robots:\n";
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> att(0.2, 1.0);
  for (int r = 0; r < kRobots; ++r) {
    y << "  - id: robot" << r << "\n    max_speed: " << 1.0 + 0.2 * r << "\n    attitude: {";
    for (int j = 0; j < 12; ++j) y << (j ? ", " : "") << "Job" << j << ": " << att(rng);
    for (int s = 0; s < 8; ++s) y << ", Schema" << s << ": " << att(rng);
    y << "}\n";
  }
  return y.str();
}

Situation random_situation(std::mt19937& rng) {
  std::uniform_real_distribution<double> x(-9, 9), yy(-6, 6), u(0, 1);
  Situation s;
  s.world = {{"BallX", {x(rng), 1}}, {"BallY", {yy(rng), 1}}};
  for (int k = 0; k < 4; ++k) s.world["N" + std::to_string(k)] = {u(rng), 1};
  for (int r = 0; r < kRobots; ++r) s.robots.push_back({"robot" + std::to_string(r), Pose2D(x(rng), yy(rng), 0), "", 0});
  return s;
}

/// Exhaustive optimum: depth-first over every robot's choice (a slot or
/// none), pruned by the cardinality maxima and by an upper bound (the sum
/// of the remaining robots' best utilities); feasibility at the leaves.
struct Exhaustive {
  const Allocator& al;
  const TeamInput& in;
  std::vector<std::vector<double>> u;
  std::vector<double> best_rest;
  std::vector<int> slot, count;
  std::vector<char> on;
  double best = 0.0;

  Exhaustive(const Allocator& a, const TeamInput& t) : al(a), in(t) {
    const auto agenda = al.agenda(in);
    on.assign(al.set().activities.size(), 0);
    for (const auto& e : agenda) on[static_cast<std::size_t>(e.activity)] = 1;
    const auto slots = al.set().slots();
    u.assign(in.robots.size(), std::vector<double>(slots.size(), -1.0));
    best_rest.assign(in.robots.size() + 1, 0.0);
    for (std::size_t i = 0; i < in.robots.size(); ++i)
      for (std::size_t s = 0; s < slots.size(); ++s)
        if (on[static_cast<std::size_t>(slots[s].activity)]) u[i][s] = al.utility(in, in.robots[i], static_cast<int>(s));
    for (std::size_t i = in.robots.size(); i-- > 0;)
      best_rest[i] = best_rest[i + 1] + std::max(0.0, *std::max_element(u[i].begin(), u[i].end()));
    slot.assign(in.robots.size(), -1);
    count.assign(slots.size(), 0);
  }
  void search(std::size_t i, double acc) {
    if (acc + best_rest[i] <= best) return;
    if (i == in.robots.size()) {
      if (al.feasible(slot, on)) best = acc;
      return;
    }
    const auto slots = al.set().slots();
    for (std::size_t s = 0; s < u[i].size(); ++s) {
      const Slot& sl = slots[s];
      if (u[i][s] < 0.0 ||
          count[s] >= al.set().activities[static_cast<std::size_t>(sl.activity)].roles[static_cast<std::size_t>(sl.role)].max)
        continue;
      slot[i] = static_cast<int>(s);
      ++count[s];
      search(i + 1, acc + u[i][s]);
      --count[s];
    }
    slot[i] = -1;
    search(i + 1, acc);
  }
};

void utility_figures(const ActivitySet& set, int n) {
  const Allocator al(set);
  std::mt19937 rng(1);
  double sum_opt = 0, sum_exact = 0, sum_local = 0, sum_greedy = 0, t_alloc = 0, t_exh = 0;
  std::vector<double> times, cpu_times;
  mrt::cli::Progress progress("scare_bench situations", n);
  for (int k = 0; k < n; ++k) {
    progress.update(k);
    const TeamInput in = team_input(set, random_situation(rng));
    const double cpu0 = thread_cpu_ms();
    auto t0 = Clock::now();
    const double exact = al.allocate(in).utility;  // kAuto: exact for 5 robots
    const double dt = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    cpu_times.push_back(thread_cpu_ms() - cpu0);
    t_alloc += dt;
    times.push_back(dt);
    sum_exact += exact;
    sum_local += al.allocate(in, Allocator::Method::kGreedyLocal).utility;
    sum_greedy += al.allocate(in, Allocator::Method::kGreedy).utility;
    t0 = Clock::now();
    Exhaustive ex(al, in);
    ex.search(0, 0.0);
    t_exh += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    sum_opt += ex.best;
  }
  progress.finish();
  // Wall time (includes preemption by other processes) and the thread's CPU
  // time of the same calls (CLOCK_THREAD_CPUTIME_ID).
  print_distribution("coordination_allocation_cycle", times);
  print_distribution("coordination_allocation_cycle_cpu", cpu_times);
  std::printf("coordination_exhaustive_search_mean: %.3f ms\n", t_exh / n);
  std::printf("coordination_allocation_over_exhaustive_time: %.3f ratio\n", t_alloc / t_exh);
  std::printf("coordination_utility_exact_vs_optimum: %.2f %%\n", 100.0 * sum_exact / sum_opt);
  std::printf("coordination_utility_greedy_local_vs_optimum: %.2f %%\n", 100.0 * sum_local / sum_opt);
  std::printf("coordination_utility_greedy_vs_optimum: %.2f %%\n", 100.0 * sum_greedy / sum_opt);
  std::printf("coordination_situations: %d count\n", n);
}

/// Re-assignments over `cycles` allocations of quasi-static scenes (a new
/// random scene every 100 cycles; the first allocation of a scene is not
/// counted), 5 cm Gaussian noise on every position, incumbents fed back.
int reassignments(const ActivitySet& set, int cycles) {
  const Allocator al(set);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.05);
  int changes = 0;
  Situation scene;
  std::vector<int> prev;
  for (int k = 0; k < cycles; ++k) {
    const bool fresh = k % 100 == 0;
    if (fresh) scene = random_situation(rng);
    Situation s = scene;
    for (auto& r : s.robots) r.pose = Pose2D(r.pose.x + noise(rng), r.pose.y + noise(rng), 0);
    s.world["BallX"].first += noise(rng);
    s.world["BallY"].first += noise(rng);
    if (!fresh)
      for (std::size_t i = 0; i < s.robots.size(); ++i)
        s.robots[i].incumbent = prev[i] >= 0 ? set.slot_name(set.slots()[static_cast<std::size_t>(prev[i])]) : "";
    const Allocation a = al.allocate(team_input(set, s));
    if (!fresh)
      for (std::size_t i = 0; i < a.slot.size(); ++i) changes += a.slot[i] != prev[i];
    prev = a.slot;
  }
  return changes;
}

}  // namespace

void run_game(const ActivitySet& set, const char* name, bool dropouts);  // coordination_game.cpp

void run_coordination(int situations, int stability_cycles) {
  const ActivitySet set = parse_activities(synthetic_yaml(), "synthetic.yaml");
  std::printf("coordination_activities: %zu count\n", set.activities.size());
  utility_figures(set, situations);
  std::printf("coordination_quasi_static_reassignments: %d count\n", reassignments(set, stability_cycles));
  ActivitySet loose = set;
  loose.options.hysteresis = 0.0;
  std::printf("coordination_quasi_static_reassignments_without_hysteresis: %d count\n",
              reassignments(loose, stability_cycles));
  // The game with a 10 s dwell (README), then without it for comparison.
  ActivitySet dwell = set;
  dwell.options.dwell = 10.0;
  std::printf("coordination_game_dwell: %.1f s\n", dwell.options.dwell);
  run_game(dwell, "coordination_game", true);
  run_game(set, "coordination_game_without_dwell", false);
}

}  // namespace mrt::scare::bench
