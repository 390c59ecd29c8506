// robocup_bench: the team session's simulated-to-CPU time ratio (the
// real-time factor), four robots, 60 simulated s per seed, three seeds;
// prints `name: value unit` lines (scripts/bench.sh). The baseline in the
// same run is the match alone (no MAP, SCARE or players), so that
// the ratio between the two is stable on a shared machine.
#include <chrono>
#include <cstdio>

#include "mrt_robocup/match.h"
#include "mrt_robocup/session_files.h"
#include "mrt_sim/simulator.h"

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main() {
  using namespace mrt::robocup;
  const double sim_seconds = 60.0;
  double team_cpu = 0.0, team_sim = 0.0;
  int goals = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    TeamSessionOptions o = default_session_options(MRT_ROBOCUP_ROOT, MRT_WORLDS_DIR);
    o.seed = seed;
    o.duration = sim_seconds;
    TeamSession s(o);
    const auto t0 = std::chrono::steady_clock::now();
    s.run();
    team_cpu += seconds_since(t0);
    team_sim += s.time();
    goals += s.stats().score[0];
  }
  // Baseline: the same match and world with the robots standing still.
  TeamSessionOptions o = default_session_options(MRT_ROBOCUP_ROOT, MRT_WORLDS_DIR);
  mrt::sim::World w = mrt::sim::load_world(o.world);
  MatchConfig mc = load_match_config(o.match);
  setup_match_world(mc, w);
  mrt::sim::Simulator sim(std::move(w), o.dt);
  Match match(mc, sim);
  const auto t0 = std::chrono::steady_clock::now();
  while (sim.time() < sim_seconds) match.step();
  const double base_cpu = seconds_since(t0);
  std::printf("robocup_real_time_factor: %.1f x\n", team_sim / team_cpu);
  std::printf("robocup_cpu_per_sim_second: %.2f ms\n", 1000.0 * team_cpu / team_sim);
  std::printf("match_alone_real_time_factor: %.1f x\n", sim_seconds / base_cpu);
  std::printf("robocup_vs_match_alone: %.2f ratio\n", (team_cpu / team_sim) / (base_cpu / sim_seconds));
  std::printf("robocup_goals_in_%.0f_s_x3: %d goals\n", sim_seconds, goals);
  return 0;
}
