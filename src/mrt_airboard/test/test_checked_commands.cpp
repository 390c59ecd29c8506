// Checked set commands: the CRC-32 trailer catches the damage that passes the
// frame's CRC-16, and the board's strict mode refuses a checked command
// damaged into a plain one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mrt_airboard/firmware.h"

using namespace mrt::airboard;

namespace {
// Rewrites the frame's CRC-16 for its (damaged) content: the damage now
// passes the CRC-16, as 1 in 65536 damaged frames do on a noisy line.
void fix_crc16(std::vector<uint8_t>& b) {
  const uint16_t c = crc16_ccitt(b.data() + 1, b.size() - 3);
  b[b.size() - 2] = static_cast<uint8_t>(c & 0xFF);
  b[b.size() - 1] = static_cast<uint8_t>(c >> 8);
}

void receive(Firmware& fw, const std::vector<uint8_t>& b) {
  fw.receive(b.data(), b.size());
  fw.take_output();
}
}  // namespace

// Golden frame, computed with Python's zlib.crc32 (CRC-32/ISO-HDLC) over
// 01 07 02 DC 05 00 00 30 F8 FF FF = 0x9073D911, and doc/protocol.md's bit-by-bit
// CRC-16 over LEN .. trailer = 0x64DA.
TEST(CheckedCommands, GoldenFrameAndRoundTrip) {
  const auto b = encode_frame(make_set_speed(7, {1.5, -2.0}, true));
  const std::vector<uint8_t> want{0xA5, 0x0D, 0x01, 0x07, 0x02, 0xDC, 0x05, 0x00, 0x00, 0x30,
                                  0xF8, 0xFF, 0xFF, 0x11, 0xD9, 0x73, 0x90, 0xDA, 0x64};
  EXPECT_EQ(b, want);
  Frame f = make_set_speed(7, {1.5, -2.0}, true);
  std::vector<double> v;
  bool checked = false;
  ASSERT_TRUE(parse_set_speed(f, &v, &checked));
  EXPECT_TRUE(checked);
  EXPECT_EQ(v, (std::vector<double>{1.5, -2.0}));
  f.payload[2] ^= 0x40;  // 1.5 -> 17.884 rad/s
  EXPECT_FALSE(parse_set_speed(f, &v));
  EXPECT_TRUE(set_check_failed(f));
  Frame p = make_set_pwm(9, {0.5, -0.25}, true);
  ASSERT_TRUE(parse_set_pwm(p, &v, &checked));
  EXPECT_TRUE(checked);
  EXPECT_EQ(p.payload.size(), 1u + 2 * 2 + 4);
}

// One damaged set-point byte plus a rewritten CRC-16: a plain command is
// applied (17.884 rad/s instead of 1.5: what the CRC-16 alone lets through),
// a checked one is refused with NACK 5 and the set-point stays.
TEST(CheckedCommands, DamagePassingTheCrc16IsRefused) {
  Firmware plain{FirmwareConfig{}};
  auto b = encode_frame(make_set_speed(7, {1.5, -2.0}));
  b[4 + 2] ^= 0x40;
  fix_crc16(b);
  receive(plain, b);
  EXPECT_DOUBLE_EQ(plain.setpoint(0), 17.884);

  Firmware fw{FirmwareConfig{}};
  receive(fw, encode_frame(make_set_speed(6, {1.0, 1.0}, true)));
  ASSERT_EQ(fw.setpoint(0), 1.0);
  auto c = encode_frame(make_set_speed(7, {1.5, -2.0}, true));
  c[4 + 2] ^= 0x40;
  fix_crc16(c);
  fw.receive(c.data(), c.size());
  FrameDecoder dec;
  uint8_t type = 0, reason = 0;
  const auto out = fw.take_output();
  dec.feed(out.data(), out.size(), [&](const Frame& f) { parse_nack(f, &type, &reason); });
  EXPECT_EQ(reason, proto::kNackBadCheck);
  EXPECT_EQ(fw.setpoint(0), 1.0);
  EXPECT_EQ(fw.check_failures(), 1u);
}

// Strict mode: after a checked command (or from power-up with
// require_checked) a plain one is refused with NACK 6.
TEST(CheckedCommands, StrictModeRefusesPlainCommands) {
  Firmware fw{FirmwareConfig{}};
  receive(fw, encode_frame(make_set_speed(1, {2.0, 2.0})));
  EXPECT_EQ(fw.setpoint(0), 2.0);  // plain accepted before any checked one
  EXPECT_FALSE(fw.strict());
  receive(fw, encode_frame(make_set_speed(2, {3.0, 3.0}, true)));
  EXPECT_TRUE(fw.strict());
  receive(fw, encode_frame(make_set_speed(3, {4.0, 4.0})));
  receive(fw, encode_frame(make_set_pwm(4, {0.5, 0.5})));
  EXPECT_EQ(fw.setpoint(0), 3.0);
  EXPECT_EQ(fw.commands_rejected(), 2u);
  FirmwareConfig c;
  c.require_checked = true;
  Firmware strict{c};
  receive(strict, encode_frame(make_set_speed(1, {2.0, 2.0})));
  EXPECT_EQ(strict.setpoint(0), 0.0);
  receive(strict, encode_frame(make_set_speed(2, {2.0, 2.0}, true)));
  EXPECT_EQ(strict.setpoint(0), 2.0);
}

// The long corrupted line, made worst-case: 100000 checked SET_SPEEDs with
// random set-points, 10 % of their TYPE, SEQ and payload bytes get a bit
// flipped and EVERY frame's CRC-16 is rewritten, so every damaged frame
// passes the CRC-16 (on a real line 1 in 65536 does). A damaged frame must
// never be applied: after each frame the set-points are the frame's own
// when it came through intact, the previous ones otherwise, and the board
// applied exactly the intact frames (expected 0.9^15 = 20.6 % of them).
// Control: the same with plain commands applies damaged ones.
TEST(CheckedCommands, LongCorruptedLineNeverAppliesAWrongCommand) {
  for (bool checked : {true, false}) {
    Firmware fw{FirmwareConfig{}};
    std::mt19937 rng(19);
    std::uniform_real_distribution<double> u(0, 1), sp(-25.0, 25.0);
    std::vector<double> in_force{0.0, 0.0};
    uint64_t intact = 0, wrong = 0;
    const int n = checked ? 100000 : 10000;
    for (int i = 0; i < n; ++i) {
      const std::vector<double> w{std::round(sp(rng) * 1000) / 1000, std::round(sp(rng) * 1000) / 1000};
      auto b = encode_frame(make_set_speed(static_cast<uint8_t>(i), w, checked));
      bool damaged = false;
      for (std::size_t k = 2; k + 2 < b.size(); ++k)
        if (u(rng) < 0.1) {
          b[k] ^= static_cast<uint8_t>(1u << (rng() % 8));
          damaged = true;
        }
      fix_crc16(b);
      receive(fw, b);
      if (!damaged) {
        ++intact;
        in_force = w;
      }
      for (int m = 0; m < 2; ++m)
        if (fw.setpoint(m) != in_force[m]) {
          ++wrong;
          in_force[m] = fw.setpoint(m);
        }
    }
    if (checked) {
      EXPECT_EQ(wrong, 0u);
      EXPECT_EQ(fw.commands_applied(), intact);
      EXPECT_NEAR(static_cast<double>(intact) / n, 0.206, 0.01);
      // Refused by the CRC-32 itself: TYPE and n intact (0.9^2), some of
      // the other 13 bytes damaged (1 - 0.9^13): 0.81 x 0.746 = 0.604; the
      // rest (TYPE or n damaged) by the type, length or count checks.
      EXPECT_NEAR(static_cast<double>(fw.check_failures()) / n, 0.604, 0.01);
    } else {
      EXPECT_GT(wrong, 1000u);  // most damaged plain frames are applied
    }
  }
}

// The realistic line (no CRC-16 rewriting): 200000 checked commands, 10 % of
// all their bytes (start and LEN included) damaged, split at random: only
// commanded set-points are ever in force.
TEST(CheckedCommands, RealisticCorruptedLine) {
  Firmware fw{FirmwareConfig{}};
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  const std::vector<double> a{4.0, -2.5}, b{-1.0, 7.25};
  uint64_t bad = 0;
  for (int i = 0; i < 200000; ++i) {
    auto bytes = encode_frame(make_set_speed(static_cast<uint8_t>(i), i % 2 ? a : b, true));
    for (auto& x : bytes)
      if (u(rng) < 0.1) x ^= static_cast<uint8_t>(1u << (rng() % 8));
    const std::size_t cut = rng() % bytes.size();
    fw.receive(bytes.data(), cut);
    fw.receive(bytes.data() + cut, bytes.size() - cut);
    fw.take_output();
    for (int m = 0; m < 2; ++m) {
      const double s = fw.setpoint(m);
      if (!(s == a[m] || s == b[m] || s == 0.0)) ++bad;
    }
  }
  EXPECT_EQ(bad, 0u);
  // 0.9^19 = 13.5 % of the frames intact (a few more rebuilt by resync).
  EXPECT_NEAR(fw.commands_applied() / 200000.0, 0.135, 0.01);
}
