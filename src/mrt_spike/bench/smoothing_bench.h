// spike_bench --smoothing: SPIKE's any-angle paths against their Dubins or
// Reeds-Shepp smoothing on a world (FollowMe's museum by default).
#pragma once

#include <string>

namespace mrt::spike {

struct SmoothingBenchOptions {
  std::string model = "dubins";  ///< dubins | reeds_shepp
  double turning_radius = 0.3;   ///< m
  std::string world;             ///< world or map_server YAML
  double resolution = 0.05;      ///< m, for a world file (spike.launch's)
  int queries = 100;             ///< random pairs of free cells
  unsigned seed = 1;
};

/// Plans `queries` random queries (robot radius 0.3 m + safety 0.1 m, as
/// spike_node's defaults), smooths each, prints `<map>.unsmoothed.*` and
/// `<map>.<model>.*` lines: mean length, max curvature (the unsmoothed
/// path's is inf at its corners: their count too), time per plan.
void bench_smoothing(const SmoothingBenchOptions& o);

}  // namespace mrt::spike
