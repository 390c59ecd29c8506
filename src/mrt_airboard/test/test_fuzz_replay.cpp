// Replays a fixed corpus through a libFuzzer target's LLVMFuzzerTestOneInput
// so that every build (gcc included) compiles and runs the harness: the
// doc/protocol.md's golden frames, their concatenation, then a deterministic corpus
// of corrupted variants (seeded RNG, bounded size and count). The harness
// checks its own invariants (__builtin_trap on a violation, which fails this
// test); linked once with fuzz/fuzz_decoder.cpp and once with
// fuzz/fuzz_firmware.cpp.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

// The "Example frames" table of doc/protocol.md, typed from it.
const char* const kGolden[] = {
    "A5 00 05 00 69 33",
    "A5 00 07 01 2A 45",
    "A5 09 01 07 02 DC 05 00 00 30 F8 FF FF 10 BB",
    "A5 05 02 09 02 88 13 3C F6 EB 98",
    "A5 02 06 02 0A 00 BD F3",
    "A5 02 8F 03 09 01 B0 AF",
    "A5 03 06 02 03 00 01 6C A9",
    "A5 0B 83 07 70 11 05 70 11 B0 09 FB FF 70 EA AB FC",
    "A5 06 84 07 64 00 03 00 01 00 06 58",
    "A5 1C 81 07 E8 03 00 00 01 07 64 00 03 00 01 00 01 FB FF FF FF FA 00 00 00 00 00 00 00 18 FC 05 D2 88",
};

std::vector<uint8_t> hex(const std::string& s) {
  std::istringstream in(s);
  std::vector<uint8_t> b;
  unsigned x;
  while (in >> std::hex >> x) b.push_back(static_cast<uint8_t>(x));
  return b;
}

int run(const std::vector<uint8_t>& b) { return LLVMFuzzerTestOneInput(b.data(), b.size()); }

}  // namespace

TEST(FuzzReplay, GoldenFramesAndCorruptedCorpus) {
  std::vector<std::vector<uint8_t>> golden;
  std::vector<uint8_t> all;
  for (const char* g : kGolden) {
    golden.push_back(hex(g));
    all.insert(all.end(), golden.back().begin(), golden.back().end());
  }
  ASSERT_EQ(golden.size(), 10u);
  ASSERT_EQ(golden[9].size(), 34u);  // the table was read: 6 + LEN 0x1C
  ASSERT_EQ(all.size(), 6u + 6u + 15u + 11u + 8u + 8u + 9u + 17u + 12u + 34u);
  std::size_t inputs = 0;
  EXPECT_EQ(LLVMFuzzerTestOneInput(nullptr, 0), 0);
  ++inputs;
  for (const auto& g : golden) {
    EXPECT_EQ(run(g), 0);
    ++inputs;
  }
  EXPECT_EQ(run(all), 0);
  ++inputs;
  // Corrupted variants: bit flips, byte overwrites, truncations, insertions
  // of start bytes and garbage, splices of two frames; 4000 inputs of at
  // most 4 x the concatenation.
  std::mt19937 rng(20240611u);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  for (int k = 0; k < 4000; ++k) {
    std::vector<uint8_t> b = pick(4) == 0 ? all : golden[pick(golden.size())];
    const int edits = 1 + static_cast<int>(pick(4));
    for (int e = 0; e < edits && !b.empty(); ++e) {
      switch (pick(6)) {
        case 0: b[pick(b.size())] ^= static_cast<uint8_t>(1u << pick(8)); break;
        case 1: b[pick(b.size())] = static_cast<uint8_t>(rng()); break;
        case 2: b.resize(pick(b.size() + 1)); break;
        case 3: b.insert(b.begin() + static_cast<std::ptrdiff_t>(pick(b.size() + 1)), 0xA5); break;
        case 4: {
          const std::size_t n = 1 + pick(16);
          for (std::size_t i = 0; i < n; ++i) b.insert(b.begin() + static_cast<std::ptrdiff_t>(pick(b.size() + 1)), static_cast<uint8_t>(rng()));
          break;
        }
        default: {
          const auto& o = golden[pick(golden.size())];
          b.insert(b.end(), o.begin(), o.end());
        }
      }
    }
    if (b.size() > 4 * all.size()) b.resize(4 * all.size());
    EXPECT_EQ(run(b), 0);
    ++inputs;
  }
  EXPECT_EQ(inputs, 4012u);
}
