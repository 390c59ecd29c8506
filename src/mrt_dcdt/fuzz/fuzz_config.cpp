// libFuzzer entry point (built with clang++, see fuzz/fuzz_targets.cmake): see fuzz_targets.h.
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return dcdt_fuzz::FuzzConfig(data, size); }
