// The DCDT wire protocol (doc/protocol.md "Wire protocol"): a versioned,
// length-prefixed, CRC-protected frame.
//   offset size
//   0      2   magic 0x44 0x43 ("DC")
//   2      1   version (2)
//   3      1   kind (FrameKind)
//   4      4   body length N, big-endian (<= kMaxBody)
//   8      4   header CRC-32 (IEEE) of bytes [0, 8), big-endian
//   12     N   body
//   12+N   4   CRC-32 (IEEE) of bytes [0, 12+N), big-endian
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mrt_dcdt/msg.h"

namespace mrt::dcdt {

constexpr uint8_t kMagic0 = 0x44, kMagic1 = 0x43, kVersion = 2;
constexpr size_t kFrameHeader = 12;   ///< magic, version, kind, length, header CRC
constexpr size_t kFrameOverhead = 16; ///< header + trailing CRC
constexpr size_t kMsgBodyFixed = 52;
constexpr uint32_t kMaxBody = kMaxPayload + kMsgBodyFixed;

enum class FrameKind : uint8_t {
  MSG = 1,     ///< a DCDT message (MsgFrame)
  ACK = 2,     ///< link sequence acknowledged (8 bytes)
  HELLO = 3,   ///< stream handshake: agora id, incarnation, peer incarnation known, last link seq received, flags
  BEACON = 4,  ///< Finder announcement (BeaconFrame)
  NACK = 5,    ///< stream gap: link seqs up to this one received (8); resend everything after it
};

/// A message plus the per-channel link sequence number (0 = not acknowledged).
struct MsgFrame {
  Msg msg;
  uint64_t link_seq = 0;
};

struct Hello {
  int32_t agora_id = 0;
  uint64_t incarnation = 0;       ///< random per process: a restarted Agora with the same id differs
  uint64_t peer_incarnation = 0;  ///< the receiver's incarnation as the sender knows it (0 = none yet)
  uint64_t last_rx = 0;           ///< last in-order link seq received from that incarnation
  bool reply = false;             ///< the sender has not heard a HELLO naming its incarnation yet: answer
};

struct Beacon {
  int32_t agora_id = 0;
  std::string host_key;  ///< agoras with the same key reach each other by inner links
  std::string tcp_addr;
  uint16_t tcp_port = 0;
};

uint32_t crc32_ieee(const uint8_t* data, size_t n);

std::vector<uint8_t> encode_msg(const Msg& m, uint64_t link_seq = 0);
std::vector<uint8_t> encode_ack(uint64_t seq);
std::vector<uint8_t> encode_nack(uint64_t seq);
std::vector<uint8_t> encode_hello(const Hello& h);
std::vector<uint8_t> encode_beacon(const Beacon& b);

/// A decoded frame: kind and body (already length- and CRC-checked).
struct Frame {
  FrameKind kind;
  std::vector<uint8_t> body;
};

/// Body decoders: false on a malformed body.
bool decode_msg_body(const std::vector<uint8_t>& body, MsgFrame* out);
bool decode_ack_body(const std::vector<uint8_t>& body, uint64_t* seq);
bool decode_hello_body(const std::vector<uint8_t>& body, Hello* out);
bool decode_beacon_body(const std::vector<uint8_t>& body, Beacon* out);

/// Decodes exactly one frame from a datagram; false when invalid.
bool decode_datagram(const uint8_t* data, size_t n, Frame* out);

/// Incremental stream decoder: feed bytes, pop frames. Garbage, bad
/// versions, header CRC mismatches (so a corrupted length is caught before
/// waiting for its body), oversize lengths and body CRC mismatches are
/// skipped (resync on the next magic) and counted in errors().
class FrameDecoder {
 public:
  void feed(const uint8_t* data, size_t n);
  std::optional<Frame> next();
  uint64_t errors() const { return errors_; }
  size_t buffered() const { return buf_.size() - pos_; }

 private:
  std::vector<uint8_t> buf_;
  size_t pos_ = 0;
  uint64_t errors_ = 0;
};

}  // namespace mrt::dcdt
