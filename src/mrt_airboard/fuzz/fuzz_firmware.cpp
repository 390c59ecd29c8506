// libFuzzer target: the firmware model fed with well-framed (valid CRC)
// commands of arbitrary type and payload, interleaved with control periods.
// Invariants: no crash, set-points within the speed limit, duties within
// +-100 %, finite wheel speeds.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "mrt_airboard/firmware.h"

using namespace mrt::airboard;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FirmwareConfig c;
  c.motors = 3;
  Firmware fw(c);
  size_t i = 0;
  while (i + 2 <= size) {
    // [type][len][payload...][steps]
    Frame f;
    f.type = data[i];
    const size_t len = data[i + 1] % (proto::kMaxPayload + 1);
    i += 2;
    const size_t take = len < size - i ? len : size - i;
    f.payload.assign(data + i, data + i + take);
    i += take;
    const auto bytes = encode_frame(f);
    fw.receive(bytes.data(), bytes.size());
    const int steps = i < size ? data[i++] % 120 : 1;
    for (int s = 0; s < steps; ++s) fw.step();
    fw.take_output();
    for (int m = 0; m < fw.motors(); ++m) {
      if (std::fabs(fw.setpoint(m)) > c.max_speed) __builtin_trap();
      if (!(std::fabs(fw.duty(m)) <= 1.0)) __builtin_trap();
      if (!std::isfinite(fw.speed(m))) __builtin_trap();
    }
  }
  return 0;
}
