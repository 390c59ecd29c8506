// The DCDT wire protocol (README "Wire protocol"): a versioned,
// length-prefixed, CRC-protected frame.
//   offset size
//   0      2   magic 0x44 0x43 ("DC")
//   2      1   version (1)
//   3      1   kind (FrameKind)
//   4      4   body length N, big-endian (<= kMaxBody)
//   8      N   body
//   8+N    4   CRC-32 (IEEE) of bytes [0, 8+N), big-endian
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mrt_dcdt_bridge/msg.h"

namespace mrt::dcdt {

constexpr uint8_t kMagic0 = 0x44, kMagic1 = 0x43, kVersion = 1;
constexpr size_t kFrameOverhead = 12;
constexpr size_t kMsgBodyFixed = 44;
constexpr uint32_t kMaxBody = kMaxPayload + kMsgBodyFixed;

enum class FrameKind : uint8_t {
  MSG = 1,     ///< a DCDT message (MsgFrame)
  ACK = 2,     ///< link sequence acknowledged (8 bytes)
  HELLO = 3,   ///< stream start: agora id (4) + last link seq received from the peer (8)
  BEACON = 4,  ///< Finder announcement (BeaconFrame)
};

/// A message plus the per-channel link sequence number (0 = not acknowledged).
struct MsgFrame {
  Msg msg;
  uint64_t link_seq = 0;
};

struct Hello {
  int32_t agora_id = 0;
  uint64_t last_rx = 0;
};

struct Beacon {
  int32_t agora_id = 0;
  std::string host_key;  ///< agoras with the same key reach each other by inner links
  std::string tcp_addr;
  uint16_t tcp_port = 0;
};

uint32_t Crc32(const uint8_t* data, size_t n);

std::vector<uint8_t> EncodeMsg(const Msg& m, uint64_t link_seq = 0);
std::vector<uint8_t> EncodeAck(uint64_t seq);
std::vector<uint8_t> EncodeHello(const Hello& h);
std::vector<uint8_t> EncodeBeacon(const Beacon& b);

/// A decoded frame: kind and body (already length- and CRC-checked).
struct Frame {
  FrameKind kind;
  std::vector<uint8_t> body;
};

/// Body decoders: false on a malformed body.
bool DecodeMsgBody(const std::vector<uint8_t>& body, MsgFrame* out);
bool DecodeAckBody(const std::vector<uint8_t>& body, uint64_t* seq);
bool DecodeHelloBody(const std::vector<uint8_t>& body, Hello* out);
bool DecodeBeaconBody(const std::vector<uint8_t>& body, Beacon* out);

/// Decodes exactly one frame from a datagram; false when invalid.
bool DecodeDatagram(const uint8_t* data, size_t n, Frame* out);

/// Incremental stream decoder: feed bytes, pop frames. Garbage, bad
/// versions, oversize lengths and CRC mismatches are skipped (resync on the
/// next magic) and counted in errors().
class FrameDecoder {
 public:
  void Feed(const uint8_t* data, size_t n);
  std::optional<Frame> Next();
  uint64_t errors() const { return errors_; }
  size_t buffered() const { return buf_.size() - pos_; }

 private:
  std::vector<uint8_t> buf_;
  size_t pos_ = 0;
  uint64_t errors_ = 0;
};

}  // namespace mrt::dcdt
