// The MSL-field re-planning benchmark of spike_bench.
#pragma once

namespace mrt::spike {

/// `steps` steps of 50 ms with `robots` robots moving at up to 2 m/s on the
/// 18 x 12 m field at 5 cm; each step stamps every robot again and re-plans.
/// Prints `msl_field.*: value unit` lines.
void bench_msl(int steps, int robots, unsigned seed);

}  // namespace mrt::spike
