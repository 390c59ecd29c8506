// Fuzz target bodies, shared by the libFuzzer entry points (fuzz/*.cpp, built
// with clang when -DDCDT_FUZZ=ON) and by the deterministic fuzz smoke test
// that runs in the normal suite. Each must never crash, hang or allocate
// without bound, whatever the input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_dcdt_bridge/config.h"
#include "mrt_dcdt_bridge/frame.h"
#include "mrt_dcdt_bridge/xml_message.h"

namespace dcdt_fuzz {

inline int FuzzFrame(const uint8_t* data, size_t size) {
  using namespace mrt::dcdt;
  Frame f;
  if (DecodeDatagram(data, size, &f)) {
    MsgFrame mf;
    Hello h;
    Beacon b;
    uint64_t s;
    if (DecodeMsgBody(f.body, &mf)) {
      // Re-encoding a decoded message gives a frame that decodes to the same.
      auto again = EncodeMsg(mf.msg, mf.link_seq);
      Frame g;
      if (!DecodeDatagram(again.data(), again.size(), &g)) __builtin_trap();
    }
    DecodeHelloBody(f.body, &h);
    DecodeBeaconBody(f.body, &b);
    DecodeAckBody(f.body, &s);
  }
  FrameDecoder d;
  for (size_t i = 0; i < size; i += 7) {
    d.Feed(data + i, size - i < 7 ? size - i : 7);
    while (auto fr = d.Next()) {
      MsgFrame mf;
      DecodeMsgBody(fr->body, &mf);
    }
  }
  return 0;
}

inline int FuzzConfig(const uint8_t* data, size_t size) {
  try {
    auto c = mrt::dcdt::ParseAgoraConfig(std::string(reinterpret_cast<const char*>(data), size), "fuzz.cfg");
    // What parses formats to a text that parses to the same.
    auto text = mrt::dcdt::FormatAgoraConfig(c);
    if (mrt::dcdt::FormatAgoraConfig(mrt::dcdt::ParseAgoraConfig(text, "again.cfg")) != text) __builtin_trap();
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}

inline int FuzzXml(const uint8_t* data, size_t size) {
  try {
    auto m = mrt::dcdt::DecodeXml(std::string(reinterpret_cast<const char*>(data), size));
    // Whatever decodes must encode and decode again.
    auto again = mrt::dcdt::DecodeXml(mrt::dcdt::EncodeXml(m));
    if (again.objects.size() != m.objects.size()) __builtin_trap();
  } catch (const mrt::dcdt::XmlError&) {
  }
  return 0;
}

}  // namespace dcdt_fuzz
