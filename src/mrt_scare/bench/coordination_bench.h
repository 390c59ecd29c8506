// scare_bench's coordination part (bench/coordination_bench.cpp).
#pragma once

namespace mrt::scare::bench {

/// Prints the coordination figures as `name: value unit` lines.
void run_coordination(int situations, int stability_cycles);

}  // namespace mrt::scare::bench
