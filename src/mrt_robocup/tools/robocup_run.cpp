// robocup_run: the team session (README "Team session") for one seed:
// prints the score, possession, passes and role changes per minute, and
// the real-time factor. Exit 0 on success, 2 on bad usage or bad files.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "mrt_common/cli.h"
#include "mrt_robocup/session_files.h"

namespace {

using namespace mrt::robocup;

// The tests' opponents: a goalkeeper at (8.4, 0) and a static defender at (5, 0).
void use_keeper_and_static(TeamSessionOptions& o) {
  o.replace_opponents = true;
  OpponentConfig keeper, back;
  keeper.name = "opp_keeper";
  keeper.role = "goalkeeper";
  keeper.home = {8.4, 0.0};
  keeper.speed = 1.5;
  back.name = "opp_back";
  back.role = "static";
  back.home = {5.0, 0.0};
  o.opponents = {keeper, back};
}

void print_trace(const TeamSession& s, int trace_robot) {
  std::printf("t %6.1f ball %5.2f %5.2f holder %d score %d-%d |", s.time(), s.ball().x, s.ball().y, s.holder(),
              s.stats().score[0], s.stats().score[1]);
  for (const Point2D& p : s.opponents()) std::printf(" opp %5.2f %5.2f", p.x, p.y);
  std::printf(" |");
  for (std::size_t i = 0; i < s.robots(); ++i)
    std::printf(" %s %5.2f %5.2f %4.0f %s v%.2f w%.2f |", s.robot_name(i).c_str(), s.pose(i).x, s.pose(i).y,
                s.pose(i).theta * 57.29578, s.job(i).c_str(), s.command(i).vx, s.command(i).omega);
  std::printf("\n");
  if (trace_robot >= 0 && static_cast<std::size_t>(trace_robot) < s.robots()) {
    const PlayerOutput& out = s.output(static_cast<std::size_t>(trace_robot));
    std::printf("   behaviours: %s\n   shot: aim %.2f %.2f keeper clearance %.2f clear %d\n   crisp:", out.behaviors.c_str(),
                out.situation.aim.x, out.situation.aim.y, out.situation.keeper_clearance, out.situation.shot_clear ? 1 : 0);
    for (const auto& c : out.crisp)
      if (c.value != 0.0) std::printf(" %s=%.0f", c.name.c_str(), c.value);
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mrt::robocup;
  TeamSessionOptions o = default_session_options(MRT_ROBOCUP_ROOT, MRT_WORLDS_DIR);
  CLI::App app{"Runs the Milan RoboCup team (4 robots: MAP, SCARE, Mr. BRIAN) in the simulated match"};
  app.add_option("--world", o.world, "mrt_sim world (the field), or a match file (then that match on the MSL field)");
  app.add_option("--match", o.match, "match file (default: the package's config/msl_match.yaml)");
  app.add_option("--team", o.team, "team file (robots, bases, kick-off poses)");
  app.add_option("--brian", o.rule_bases, "rule-base directory (differential/, omni/)");
  app.add_option("--activities", o.activities, "SCARE activity file");
  app.add_option("--map", o.map_model, "MAP conceptual model");
  app.add_option("--seed", o.seed, "seed of the percept noise and of the world");
  app.add_option("--duration", o.duration, "simulated seconds")->check(CLI::PositiveNumber);
  app.add_option("--rate", o.rate, "Hz of MAP, SCARE and the players")->check(CLI::PositiveNumber);
  app.add_option("--dt", o.dt, "simulator step, s")->check(CLI::PositiveNumber);
  double trace = 0.0;
  int trace_robot = -1;
  app.add_option("--trace-robot", trace_robot, "with --trace: also robot i's behaviours and crisp data");
  app.add_option("--trace", trace, "print the ball, every robot's pose and job every this many s (0: never)");
  bool keeper_and_static = false;
  app.add_flag("--keeper-and-static", keeper_and_static,
               "replace the match's opponents by a goalkeeper at (8.4, 0) and a static defender at (5, 0) (the test)");
  double stop_at = -1.0;
  app.add_option("--stop-at", stop_at, "the operator's referee stop at this time (s)");
  std::string remove;
  double remove_at = -1.0;
  app.add_option("--remove", remove, "take this robot out ...");
  app.add_option("--remove-at", remove_at, "... at this time (s)");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    resolve_world_or_match(o, MRT_WORLDS_DIR "/msl_field.yaml");
    if (keeper_and_static) use_keeper_and_static(o);
    TeamSession s(o);
    const auto t0 = std::chrono::steady_clock::now();
    double next = 0.0;
    while (s.cycle()) {
      if (stop_at >= 0.0 && s.time() >= stop_at) {
        s.referee(Referee::kStop);
        stop_at = -1.0;
      }
      if (remove_at >= 0.0 && s.time() >= remove_at) {
        s.remove_robot(remove);
        remove_at = -1.0;
      }
      if (trace <= 0.0 || s.time() < next) continue;
      next += trace;
      print_trace(s, trace_robot);
    }
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
