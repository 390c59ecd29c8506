// Fuzz target bodies, shared by the libFuzzer entry points (fuzz/*.cpp, built
// with clang when -DDCDT_FUZZ=ON) and by the deterministic fuzz smoke test
// that runs in the normal suite. Each must never crash, hang or allocate
// without bound, whatever the input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_dcdt/config.h"
#include "mrt_dcdt/frame.h"
#include "mrt_dcdt/xml_message.h"

namespace dcdt_fuzz {

inline int FuzzFrame(const uint8_t* data, size_t size) {
  using namespace mrt::dcdt;
  Frame f;
  if (decode_datagram(data, size, &f)) {
    MsgFrame mf;
    Hello h;
    Beacon b;
    uint64_t s;
    if (decode_msg_body(f.body, &mf)) {
      // Re-encoding a decoded message gives a frame that decodes to the same.
      auto again = encode_msg(mf.msg, mf.link_seq);
      Frame g;
      if (!decode_datagram(again.data(), again.size(), &g)) __builtin_trap();
    }
    decode_hello_body(f.body, &h);
    decode_beacon_body(f.body, &b);
    decode_ack_body(f.body, &s);
  }
  FrameDecoder d;
  for (size_t i = 0; i < size; i += 7) {
    d.feed(data + i, size - i < 7 ? size - i : 7);
    while (auto fr = d.next()) {
      MsgFrame mf;
      decode_msg_body(fr->body, &mf);
    }
  }
  return 0;
}

inline int FuzzConfig(const uint8_t* data, size_t size) {
  try {
    auto c = mrt::dcdt::parse_agora_config(std::string(reinterpret_cast<const char*>(data), size), "fuzz.cfg");
    // What parses formats to a text that parses to the same.
    auto text = mrt::dcdt::format_agora_config(c);
    if (mrt::dcdt::format_agora_config(mrt::dcdt::parse_agora_config(text, "again.cfg")) != text) __builtin_trap();
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}

inline int FuzzXml(const uint8_t* data, size_t size) {
  try {
    auto m = mrt::dcdt::decode_xml(std::string(reinterpret_cast<const char*>(data), size));
    // Whatever decodes must encode and decode again.
    auto again = mrt::dcdt::decode_xml(mrt::dcdt::encode_xml(m));
    if (again.objects.size() != m.objects.size()) __builtin_trap();
  } catch (const mrt::dcdt::XmlError&) {
  }
  return 0;
}

}  // namespace dcdt_fuzz
