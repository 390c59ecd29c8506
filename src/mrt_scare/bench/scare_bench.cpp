// scare_bench: sequencer update cost and the coordination figures
// (bench/coordination_bench.cpp), printed as `name: value unit`, with
// in-run baseline ratios (scripts/bench.sh). `scare_bench --quick` runs
// the coordination part on 500 situations / cycles.
#include <chrono>
#include <cstdio>

#include "coordination_bench.h"

#include "mrt_common/cli.h"
#include "mrt_scare/sequencer.h"

using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  CLI::App app{"scare_bench: the sequencer's update cost and SCARE's coordination figures"};
  bool quick = false;
  app.add_flag("--quick", quick, "coordination on 500 situations / cycles only");
  const int rc = mrt::cli::parse_cli(app, argc, argv);
  if (rc >= 0) return rc;
  using namespace mrt::scare;
  // Sequencer: a 1000-point plan driven through by a pose on the points.
  std::vector<Point2D> plan;
  for (int i = 0; i < 1000; ++i) plan.push_back({static_cast<double>(i), 0.0});
  Sequencer s;
  s.set_plan(plan, 0.0, Pose2D(-1, 0, 0));
  const int n = 2000000;
  auto t0 = Clock::now();
  std::size_t events = 0;
  for (int k = 0; k < n; ++k) {
    const double x = static_cast<double>(k) * 1000.0 / n;
    events += s.update(k * 1e-3, Pose2D(x, 0, 0)).size();
  }
  const double seq_ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / n;
  // Baseline: the distance computation alone, same loop.
  t0 = Clock::now();
  double acc = 0.0;
  for (int k = 0; k < n; ++k) acc += distance(Pose2D(k * 1e-3, 0, 0), plan[k % plan.size()]);
  const double base_ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / n;
  std::printf("sequencer_update: %.1f ns\n", seq_ns);
  std::printf("sequencer_update_over_distance_baseline: %.1f ratio\n", seq_ns / base_ns);
  std::printf("sequencer_events: %zu count\n", events + (acc < 0 ? 1 : 0));
  mrt::scare::bench::run_coordination(quick ? 500 : 10000, quick ? 500 : 10000);
  return 0;
}
