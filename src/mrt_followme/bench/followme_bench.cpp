// followme_bench [ROOT]: FollowMe's closed loop on the museum, timed; the
// baseline is mrt_sim alone stepping the same world for the same simulated
// time in the same run (a ratio, since the machine is shared). Prints
// `name: value unit` lines. ROOT: the repository (default: the source tree).
#include <chrono>
#include <cstdio>
#include <string>

#include "mrt_followme/followme_loop.h"
#include "mrt_sim/simulator.h"
#include "mrt_sim/world.h"

int main(int argc, char** argv) {
  // followme_bench [WORLD [CONFIG_DIR]]: mrt_sim's museum and this package's config by default.
  const std::string config = argc > 2 ? argv[2] : MRT_FOLLOWME_ROOT "/config";
  mrt::followme::FollowMeLoopOptions o;
  o.world = argc > 1 ? argv[1] : MRT_WORLDS_DIR "/museum.yaml";
  o.config = config + "/followme.yaml";
  o.brian = config + "/brian/BrianConfigs.ini";
  o.packages = {{"mrt_roby", MRT_ROBY_DIR}};  // Roby's rule base, by the build
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const auto r = mrt::followme::run_followme_loop(o);
  const double loop_s = std::chrono::duration<double>(Clock::now() - t0).count();

  mrt::sim::Simulator sim(mrt::sim::load_world(o.world), 0.001);
  const auto t1 = Clock::now();
  while (sim.time() < r.time) sim.step();
  const double sim_s = std::chrono::duration<double>(Clock::now() - t1).count();

  std::printf("followme_tour_sim_time: %.1f s\n", r.time);
  std::printf("followme_tour_completed: %d\n", r.completed ? 1 : 0);
  std::printf("followme_tour_realtime_factor: %.1f x\n", r.time / loop_s);
  std::printf("sim_only_realtime_factor: %.1f x\n", r.time / sim_s);
  std::printf("followme_cost_vs_sim_only: %.2f\n", loop_s / sim_s);
  std::printf("followme_max_unseen: %.1f s\n", r.max_unseen);
  std::printf("followme_max_pose_error: %.3f m\n", r.max_pose_error);
  return r.completed ? 0 : 1;
}
