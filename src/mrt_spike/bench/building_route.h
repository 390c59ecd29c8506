// The building-route benchmark of spike_bench.
#pragma once

namespace mrt::spike {

/// Plans a long route on an 80 x 50 m office floor at 5 cm with SPIKE and
/// the octile A*; prints `building.*: value unit` lines.
void bench_building();

}  // namespace mrt::spike
