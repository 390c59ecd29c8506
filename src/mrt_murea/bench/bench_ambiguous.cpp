// murea_bench, part 4: the cost of staying ambiguous on the symmetric MSL
// field. The robot drives at 0.5 m/s from (-6, -2, 0.5 rad) for 10 s, 30
// frames a second of the simulator's percepts (2 %, 0.01 rad, 6 m, 10
// spurious points) without colours: field-line points and unnamed goals,
// which cannot tell a pose from its half-turn mirror. From no prior, with
// murea_node's search budget (0.05 s of CPU time), the tracker searches
// globally at every frame (ambiguous_global_period 0, "before") or carries
// the two modes with odometry and searches globally once a second (30,
// "after"). A second run sees the colours (the blue goal 5 m away) from
// frame 150 on: the frames until the tracker commits to the truth.
#include <iostream>

#include "bench_common.h"

namespace mrt::murea::bench {

namespace {

struct AmbiguousRun {
  std::vector<double> cpu_ms;  // per frame: predict + update
  int globals = 0;
  int commit_frames = -1;  // frames after the colours appear until tracking the truth (-1: never)
};

AmbiguousRun drive(const mrt::sim::World& world, const FeatureMap& map, int period, int colours_from) {
  std::mt19937_64 rng(35);
  TrackerOptions o;
  o.search.timeout = 0.05;
  o.search.timeout_cpu = true;
  o.ambiguous_global_period = period;
  Tracker t(map, o);
  AmbiguousRun run;
  const double dt = 1.0 / 30.0;
  const Pose2D step(0.5 * dt, 0.0, 0.0);
  Pose2D truth(-6.0, -2.0, 0.5);
  for (int i = 0; i < 300; ++i) {
    if (i > 0) truth = truth * step;
    const bool colours = colours_from >= 0 && i >= colours_from;
    const std::vector<Percept> ps = simulate(world, truth, Noise{6.0, 0.0, 0.02, 0.01, 10, colours}, rng);
    const double c0 = thread_cpu_ms();
    if (i > 0) t.predict(step, {1e-6, 0, 0, 0, 1e-6, 0, 0, 0, 1e-6});
    const TrackResult r = t.update(ps);
    run.cpu_ms.push_back(thread_cpu_ms() - c0);
    run.globals += r.mode == TrackMode::Global ? 1 : 0;
    if (colours && run.commit_frames < 0 && !r.lost && near(r.pose, truth)) run.commit_frames = i - colours_from + 1;
  }
  return run;
}

}  // namespace

void ambiguous_benchmarks(const mrt::sim::World& world, const FeatureMap& map) {
  for (const auto& [name, period] : {std::pair{"before", 0}, std::pair{"after", 30}}) {
    const AmbiguousRun a = drive(world, map, period, -1), c = drive(world, map, period, 150);
    const std::string p = std::string("ambiguous_") + name;
    std::cout << p << "_global_period: " << period << " frames\n"
              << p << "_cpu_per_frame_mean: " << mean(a.cpu_ms) << " ms\n"
              << p << "_cpu_per_frame_median: " << percentile(a.cpu_ms, 0.5) << " ms\n"
              << p << "_cpu_per_frame_p95: " << percentile(a.cpu_ms, 0.95) << " ms\n"
              << p << "_cpu_per_frame_max: " << percentile(a.cpu_ms, 1.0) << " ms\n"
              << p << "_core_at_30hz: " << 100.0 * mean(a.cpu_ms) * 30.0 / 1000.0 << " %\n"
              << p << "_global_searches: " << a.globals << " count\n"
              << p << "_frames_to_commit_after_colours: " << c.commit_frames << " frames\n";
  }
}

}  // namespace mrt::murea::bench
