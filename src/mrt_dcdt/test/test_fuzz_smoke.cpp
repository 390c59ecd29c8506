// Deterministic fuzz smoke test: the libFuzzer target bodies run on the seed
// inputs and on thousands of seeded random mutations of them, in every build.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "../fuzz/fuzz_targets.h"

namespace {

std::vector<uint8_t> Bytes(const std::string& s) { return {s.begin(), s.end()}; }

std::string File(const std::string& name) {
  std::ifstream f(std::string(DCDT_TEST_DATA) + "/" + name);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

void Mutate(std::vector<uint8_t>& v, std::mt19937& rng) {
  std::uniform_int_distribution<int> op(0, 4), byte(0, 255);
  const int n = 1 + static_cast<int>(rng() % 4);
  for (int k = 0; k < n; ++k) {
    const size_t pos = v.empty() ? 0 : rng() % v.size();
    switch (op(rng)) {
      case 0: if (!v.empty()) v[pos] = static_cast<uint8_t>(byte(rng)); break;
      case 1: v.insert(v.begin() + static_cast<long>(pos), static_cast<uint8_t>(byte(rng))); break;
      case 2: if (!v.empty()) v.erase(v.begin() + static_cast<long>(pos)); break;
      case 3: if (!v.empty()) v[pos] ^= static_cast<uint8_t>(1u << (rng() % 8)); break;
      case 4: if (v.size() > 1) v.resize(pos); break;
    }
  }
}

void RunTarget(int (*target)(const uint8_t*, size_t), const std::vector<std::vector<uint8_t>>& seeds, int iterations) {
  std::mt19937 rng(12345);
  for (const auto& s : seeds) target(s.data(), s.size());
  for (int i = 0; i < iterations; ++i) {
    auto v = seeds[static_cast<size_t>(i) % seeds.size()];
    Mutate(v, rng);
    target(v.data(), v.size());
  }
}

TEST(FuzzSmoke, FrameDecoder) {
  mrt::dcdt::Msg m(18, 1, 2, 1);
  m.set_payload("payload");
  auto f = mrt::dcdt::encode_msg(m, 3);
  auto h = mrt::dcdt::encode_hello({5, 6, 7, 8, true});
  auto b = mrt::dcdt::encode_beacon({1, "k", "127.0.0.1", 9});
  std::vector<uint8_t> two = f;
  two.insert(two.end(), h.begin(), h.end());
  RunTarget(dcdt_fuzz::FuzzFrame, {f, h, b, two, {}}, 20000);
}

TEST(FuzzSmoke, ConfigParser) {
  RunTarget(dcdt_fuzz::FuzzConfig,
      {Bytes(File("agora_link.cfg")), Bytes(File("agora_standalone_net.cfg")),
       Bytes("127.0.0.1 239.1.1.1 1\nPostOffice: SLWSM\nser bridge 3 /dev/ttyS1\n")},
      20000);
}

TEST(FuzzSmoke, XmlCodec) {
  RunTarget(dcdt_fuzz::FuzzXml, {Bytes(File("percept_ball.xml")), Bytes(File("invalid_entity.xml"))}, 3000);
}

}  // namespace
