// robocup_run: the team session (README "Team session") for one seed:
// prints the score, possession, passes and role changes per minute, and
// the real-time factor. Exit 0 on success, 2 on bad usage or bad files.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "mrt_common/cli.h"
#include "mrt_robocup/session_files.h"

int main(int argc, char** argv) {
  using namespace mrt::robocup;
  TeamSessionOptions o = default_session_options(MRT_ROBOCUP_ROOT, MRT_SIM_WORLDS);
  CLI::App app{"Runs the Milan RoboCup team (4 robots: MAP, SCARE, Mr. BRIAN) in mrt_sim's match"};
  app.add_option("--world", o.world, "mrt_sim world (the field), or a match file (then the field beside it)");
  app.add_option("--match", o.match, "mrt_sim match file");
  app.add_option("--team", o.team, "team file (robots, bases, kick-off poses)");
  app.add_option("--brian", o.rule_bases, "rule-base directory (differential/, omni/)");
  app.add_option("--activities", o.activities, "SCARE activity file");
  app.add_option("--map", o.map_model, "MAP conceptual model");
  app.add_option("--seed", o.seed, "seed of the percept noise and of the world");
  app.add_option("--duration", o.duration, "simulated seconds")->check(CLI::PositiveNumber);
  app.add_option("--rate", o.rate, "Hz of MAP, SCARE and the players")->check(CLI::PositiveNumber);
  app.add_option("--dt", o.dt, "simulator step, s")->check(CLI::PositiveNumber);
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    resolve_world_or_match(o);
    TeamSession s(o);
    const auto t0 = std::chrono::steady_clock::now();
    s.run();
    const double cpu = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const TeamStats& st = s.stats();
    std::printf("score: %d - %d\n", st.score[0], st.score[1]);
    std::printf("first_goal: %.1f s\n", st.first_goal_time);
    std::printf("possession: %.1f %%\n", 100.0 * st.possession);
    std::printf("kicks: %d\n", st.kicks);
    std::printf("passes: %d\n", st.passes);
    std::printf("role_changes_per_minute: %.2f\n", st.role_changes_per_minute());
    std::printf("simulated: %.1f s\n", st.sim_time);
    std::printf("real_time_factor: %.1f\n", cpu > 0 ? st.sim_time / cpu : 0.0);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "robocup_run: " << e.what() << "\n";
    return 2;
  }
}
