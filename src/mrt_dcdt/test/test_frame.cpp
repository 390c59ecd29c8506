// Wire protocol: golden bytes, round trips, resynchronisation, rejection.
#include <gtest/gtest.h>

#include <zlib.h>

#include <cstring>

#include "mrt_dcdt/frame.h"

using namespace mrt::dcdt;

namespace {

Msg Sample() {
  Msg m(MSG_FROM_VISION, 3, 0x01020304, DCDT_DW_RETRANSMIT);
  auto& h = m.mutable_header();
  h.priority = 5;
  h.hops = 2;
  h.remote = true;
  h.creation_time = 0x0102030405060708LL;
  h.incarnation = 0x1112131415161718ULL;
  h.seq = 42;
  m.set_payload("hi", 2);
  return m;
}

TEST(Frame, Crc32MatchesTheIeeeCheckValue) {
  const char* s = "123456789";  // the standard CRC-32 check value
  EXPECT_EQ(crc32_ieee(reinterpret_cast<const uint8_t*>(s), 9), 0xCBF43926u);
}

// CRC-32 by zlib: an implementation independent of the one under test.
uint32_t ZCrc(const std::vector<uint8_t>& b, size_t from, size_t n) {
  return static_cast<uint32_t>(crc32(0L, b.data() + from, static_cast<uInt>(n)));
}

uint32_t Be32(const std::vector<uint8_t>& b, size_t at) {
  return (uint32_t(b[at]) << 24) | (uint32_t(b[at + 1]) << 16) | (uint32_t(b[at + 2]) << 8) | b[at + 3];
}

TEST(Frame, MsgGoldenBytes) {
  auto b = encode_msg(Sample(), 9);
  // Written by hand from the doc/protocol.md tables (version 2).
  const std::vector<uint8_t> header = {
      0x44, 0x43, 0x02, 0x01,  // magic "DC", version 2, kind MSG
      0x00, 0x00, 0x00, 54};   // body length 52 + 2
  const std::vector<uint8_t> body = {
      0x00, 0x00, 0x00, 18,                            // type MSG_FROM_VISION
      0x00, 0x00, 0x00, 3,                             // member id
      0x01, 0x02, 0x03, 0x04,                          // agora id
      5, 1, 2, 1,                                      // priority, warranty, hops, flags(remote)
      0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08,  // creation time
      0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17, 0x18,  // origin incarnation
      0, 0, 0, 0, 0, 0, 0, 42,                         // origin seq
      0, 0, 0, 0, 0, 0, 0, 9,                          // link seq
      0, 0, 0, 2,                                      // payload length
      'h', 'i'};
  ASSERT_EQ(b.size(), 8u + 4u + body.size() + 4u);
  EXPECT_TRUE(std::equal(header.begin(), header.end(), b.begin()));
  EXPECT_EQ(Be32(b, 8), ZCrc(header, 0, 8));  // header CRC
  EXPECT_TRUE(std::equal(body.begin(), body.end(), b.begin() + 12));
  EXPECT_EQ(Be32(b, 12 + body.size()), ZCrc(b, 0, 12 + body.size()));  // frame CRC
}

TEST(Frame, HelloAndNackGoldenBytes) {
  auto h = encode_hello(Hello{0x0A0B0C0D, 0x0102030405060708ULL, 0x1112131415161718ULL, 300, true});
  const std::vector<uint8_t> head = {0x44, 0x43, 0x02, 0x03, 0, 0, 0, 29};  // HELLO, 29-byte body
  const std::vector<uint8_t> body = {
      0x0A, 0x0B, 0x0C, 0x0D,                          // agora id
      0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08,  // incarnation
      0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17, 0x18,  // peer incarnation
      0, 0, 0, 0, 0, 0, 0x01, 0x2C,                    // last link seq received: 300
      1};                                              // flags: reply requested
  ASSERT_EQ(h.size(), 12u + 29u + 4u);
  EXPECT_TRUE(std::equal(head.begin(), head.end(), h.begin()));
  EXPECT_EQ(Be32(h, 8), ZCrc(head, 0, 8));
  EXPECT_TRUE(std::equal(body.begin(), body.end(), h.begin() + 12));
  EXPECT_EQ(Be32(h, 41), ZCrc(h, 0, 41));
  auto n = encode_nack(7);
  const std::vector<uint8_t> nack = {0x44, 0x43, 0x02, 0x05, 0, 0, 0, 8};
  ASSERT_EQ(n.size(), 24u);
  EXPECT_TRUE(std::equal(nack.begin(), nack.end(), n.begin()));
  EXPECT_EQ(n[19], 7);
  EXPECT_EQ(Be32(n, 20), ZCrc(n, 0, 20));
}

TEST(Frame, MsgRoundTrip) {
  Msg in = Sample();
  auto b = encode_msg(in, 9);
  Frame f;
  ASSERT_TRUE(decode_datagram(b.data(), b.size(), &f));
  ASSERT_EQ(f.kind, FrameKind::MSG);
  MsgFrame out;
  ASSERT_TRUE(decode_msg_body(f.body, &out));
  EXPECT_EQ(out.link_seq, 9u);
  const auto& h = out.msg.header();
  EXPECT_EQ(h.type, 18);
  EXPECT_EQ(h.member_id, 3);
  EXPECT_EQ(h.agora_id, 0x01020304);
  EXPECT_EQ(h.priority, 5);
  EXPECT_EQ(h.warranty, DCDT_DW_RETRANSMIT);
  EXPECT_EQ(h.hops, 2);
  EXPECT_TRUE(h.remote);
  EXPECT_EQ(h.creation_time, 0x0102030405060708LL);
  EXPECT_EQ(h.incarnation, 0x1112131415161718ULL);
  EXPECT_EQ(h.seq, 42u);
  EXPECT_EQ(out.msg.payload_string(), "hi");
  EXPECT_EQ(static_cast<const char*>(out.msg.payload())[2], '\0');  // NUL after the payload
}

TEST(Frame, ControlFramesRoundTrip) {
  Frame f;
  auto a = encode_ack(123456789012345ull);
  ASSERT_TRUE(decode_datagram(a.data(), a.size(), &f));
  uint64_t s;
  ASSERT_TRUE(decode_ack_body(f.body, &s));
  EXPECT_EQ(s, 123456789012345ull);
  auto h = encode_hello(Hello{77, 1234, 5678, 5, false});
  ASSERT_TRUE(decode_datagram(h.data(), h.size(), &f));
  Hello hh;
  ASSERT_TRUE(decode_hello_body(f.body, &hh));
  EXPECT_EQ(hh.agora_id, 77);
  EXPECT_EQ(hh.incarnation, 1234u);
  EXPECT_EQ(hh.peer_incarnation, 5678u);
  EXPECT_EQ(hh.last_rx, 5u);
  EXPECT_FALSE(hh.reply);
  auto b = encode_beacon(Beacon{12, "host:/tmp/x", "127.0.0.1", 4321});
  ASSERT_TRUE(decode_datagram(b.data(), b.size(), &f));
  Beacon bb;
  ASSERT_TRUE(decode_beacon_body(f.body, &bb));
  EXPECT_EQ(bb.agora_id, 12);
  EXPECT_EQ(bb.host_key, "host:/tmp/x");
  EXPECT_EQ(bb.tcp_addr, "127.0.0.1");
  EXPECT_EQ(bb.tcp_port, 4321);
}

TEST(Frame, CorruptedOrTruncatedDatagramsAreRejected) {
  auto b = encode_msg(Sample());
  Frame f;
  for (size_t i = 0; i < b.size(); ++i) {
    auto c = b;
    c[i] ^= 0x10;
    EXPECT_FALSE(decode_datagram(c.data(), c.size(), &f)) << "flipped byte " << i;
  }
  EXPECT_FALSE(decode_datagram(b.data(), b.size() - 1, &f));
  auto v2 = b;
  v2[2] = 3;  // unknown version
  EXPECT_FALSE(decode_datagram(v2.data(), v2.size(), &f));
}

TEST(Frame, OversizeLengthIsRejectedWithoutAllocating) {
  std::vector<uint8_t> b = {0x44, 0x43, 2, 1, 0xFF, 0xFF, 0xFF, 0xFF};
  const uint32_t hc = static_cast<uint32_t>(crc32(0L, b.data(), 8));  // a valid header CRC
  for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<uint8_t>(hc >> s));
  FrameDecoder d;
  d.feed(b.data(), b.size());
  EXPECT_FALSE(d.next().has_value());
  EXPECT_GE(d.errors(), 1u);
  EXPECT_LT(d.buffered(), 12u);
}

TEST(Frame, CorruptedLengthIsCaughtByTheHeaderCrcWithoutWaiting) {
  // A frame whose length field was hit (1 MiB instead of 54) followed by a
  // good frame: the good one comes out at once, nothing waits for 1 MiB.
  auto bad = encode_msg(Sample(), 1);
  bad[5] ^= 0x10;
  auto good = encode_msg(Sample(), 2);
  FrameDecoder d;
  d.feed(bad.data(), bad.size());
  d.feed(good.data(), good.size());
  auto f = d.next();
  ASSERT_TRUE(f.has_value());
  MsgFrame mf;
  ASSERT_TRUE(decode_msg_body(f->body, &mf));
  EXPECT_EQ(mf.link_seq, 2u);
  EXPECT_GE(d.errors(), 1u);
  EXPECT_EQ(d.buffered(), 0u);
}

TEST(Frame, StreamDecoderResynchronisesAfterGarbageAndSplits) {
  std::vector<uint8_t> stream = {'x', 'y', 0x44, 0x00};  // garbage, including a false magic start
  auto m1 = encode_msg(Sample(), 1);
  auto m2 = encode_msg(Sample(), 2);
  auto bad = encode_msg(Sample(), 3);
  bad[20] ^= 1;  // CRC mismatch
  stream.insert(stream.end(), m1.begin(), m1.end());
  stream.insert(stream.end(), bad.begin(), bad.end());
  stream.insert(stream.end(), m2.begin(), m2.end());
  FrameDecoder d;
  std::vector<uint64_t> seqs;
  for (size_t i = 0; i < stream.size(); i += 7) {  // fed in odd-sized pieces
    d.feed(stream.data() + i, std::min<size_t>(7, stream.size() - i));
    while (auto f = d.next()) {
      MsgFrame mf;
      ASSERT_TRUE(decode_msg_body(f->body, &mf));
      seqs.push_back(mf.link_seq);
    }
  }
  EXPECT_EQ(seqs, (std::vector<uint64_t>{1, 2}));
  EXPECT_GE(d.errors(), 2u);
}

TEST(Frame, BodyWithWrongPayloadLengthIsRejected) {
  auto b = encode_msg(Sample());
  Frame f;
  ASSERT_TRUE(decode_datagram(b.data(), b.size(), &f));
  f.body[51] = 3;  // payload length 3 but 2 bytes present
  MsgFrame mf;
  EXPECT_FALSE(decode_msg_body(f.body, &mf));
}

TEST(Frame, LegacyTypeNumbers) {
  EXPECT_EQ(msg_type_from_name("MSG_FROM_VISION"), 18);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_VISION_OMNIDIR"), 19);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_VISION_FRONTAL"), 20);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_MOTION"), 21);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_MONITOR"), 22);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_MAP"), 23);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_SCARE"), 24);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_BRIAN"), 25);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_ANCHORER"), 27);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_REFBOX"), 28);
  EXPECT_EQ(msg_type_from_name("MSG_TO_BRIAN"), 31);
  EXPECT_EQ(msg_type_from_name("MSG_TO_MOTION"), 32);
  EXPECT_EQ(msg_type_from_name("MSG_TO_ANCHORER"), 34);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_JOYPAD_BRIEF"), 43);
  EXPECT_EQ(msg_type_from_name("MSG_FROM_SONAR_QUALITY"), 44);
  EXPECT_EQ(msg_type_from_name("77"), 77);
  EXPECT_EQ(msg_type_from_name("MSG_NOPE"), -1);
  EXPECT_STREQ(msg_type_name(25), "MSG_FROM_BRIAN");
}

}  // namespace
