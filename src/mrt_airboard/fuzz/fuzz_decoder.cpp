// libFuzzer target: the frame decoder and the typed parsers must accept any
// byte stream without crashing, reading out of bounds or growing memory.
#include <cstddef>
#include <cstdint>

#include "mrt_airboard/protocol.h"

using namespace mrt::airboard;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FrameDecoder dec;
  // Feed in two chunks to exercise the resynchronisation across calls.
  const size_t cut = size ? data[0] % (size + 1) : 0;
  auto on_frame = [](const Frame& f) {
    std::vector<double> v;
    Gains g;
    uint16_t p;
    uint8_t fmt;
    BoardState s;
    ShortState ss;
    BoardCounters c;
    BoardInfo i;
    uint8_t a, b;
    parse_set_speed(f, &v);
    parse_set_pwm(f, &v);
    parse_set_gains(f, &g);
    parse_set_stream(f, &p);
    parse_set_stream(f, &p, &fmt);
    parse_short_state(f, &ss);
    parse_counters(f, &c);
    parse_state(f, &s);
    parse_info(f, &i);
    parse_nack(f, &a, &b);
    // Re-encoding a decoded frame gives a frame that decodes to itself.
    auto bytes = encode_frame(f);
    FrameDecoder again;
    int n = 0;
    again.feed(bytes.data(), bytes.size(), [&](const Frame& g2) {
      if (g2.payload != f.payload || g2.type != f.type || g2.seq != f.seq) __builtin_trap();
      ++n;
    });
    if (n != 1) __builtin_trap();
  };
  dec.feed(data, cut, on_frame);
  dec.feed(data + cut, size - cut, on_frame);
  return 0;
}
