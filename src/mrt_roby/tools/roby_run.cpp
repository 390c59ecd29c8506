// roby_run: Roby in closed loop without ROS (mrt_sim + SCARE + Mr. BRIAN).
#include <cstdio>
#include <iostream>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_roby/roby_loop.h"
#include "mrt_common/cli.h"

int main(int argc, char** argv) {
  mrt::roby::RobyLoopOptions o;
  bool trace = false;
  CLI::App app{"Roby in closed loop without ROS (mrt_sim + SCARE + Mr. BRIAN); exit 0 when the\n"
               "route was completed, 1 when not, 2 on usage or file errors.",
               "roby_run"};
  app.add_option("--world", o.world, "mrt_sim world file (YAML)")->required();
  app.add_option("--map", o.map, "Roby map file (YAML)")->required();
  app.add_option("--tasks", o.tasks, "SCARE task file (YAML)")->required();
  app.add_option("--brian", o.brian, "Mr. BRIAN configuration directory")->required();
  app.add_option("--robot", o.robot, "robot name in the world")->capture_default_str();
  app.add_option("--duration", o.duration, "simulated time limit (s, > 0)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_flag("--truth", o.use_ground_truth, "localize with the simulator's ground truth");
  app.add_flag("--trace", trace, "print every route event: time, type, #index, point, pose (s, m)");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    std::size_t shown = 0;
    mrt::cli::Progress progress("roby_run", o.duration);
    const auto res = mrt::roby::run_roby_loop(o, [&](double t, const mrt::roby::RobyLoopResult& r) {
      progress.update(t);
      for (; trace && shown < r.events.size(); ++shown) {
        const auto& e = r.events[shown];
        std::printf("%8.2f %-16s #%zu (%.2f, %.2f) at (%.2f, %.2f)\n", e.time, to_string(e.type),
                    e.index, e.point.x, e.point.y, e.pose.x, e.pose.y);
      }
    });
    progress.finish();
    std::printf("path points reached: %zu of %zu\n", res.reached, res.route_points);
    std::printf("failed: %zu, re-plans: %zu, completed: %s\n", res.failed, res.replans,
                res.completed ? "yes" : "no");
    std::printf("time: %.2f s\n", res.time);
    std::printf("minimum clearance: %.3f m (%s)\n", res.min_clearance, res.nearest.c_str());
    std::printf("max localization error: %.3f m\n", res.max_pose_error);
    return res.completed ? 0 : 1;
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
