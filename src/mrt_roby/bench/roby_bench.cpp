// roby_bench: Roby's closed-loop speed without ROS, printed as
// `name: value unit` (scripts/bench.sh).
#include <chrono>
#include <cstdio>
#include <string>

#include "mrt_roby/roby_loop.h"

using Clock = std::chrono::steady_clock;

int main() {
  using namespace mrt::roby;
  RobyLoopOptions o;
  const std::string root = MRT_ROBY_ROOT;
  o.world = root + "/test/data/roby_route.yaml";
  o.map = root + "/test/data/roby_route_map.yaml";
  o.tasks = root + "/config/tasks.yaml";
  o.brian = root + "/config/brian";
  const auto t0 = Clock::now();
  const auto r = run_roby_loop(o);
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("roby_loop_sim_seconds: %.1f s\n", r.time);
  std::printf("roby_loop_real_time_factor: %.1f ratio\n", r.time / wall);
  std::printf("roby_loop_min_clearance: %.3f m\n", r.min_clearance);
  return 0;
}
