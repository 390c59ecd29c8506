// Msg (the manual's DCDT_Msg, §3.3.3; its legacy names are in dcdt.h): a
// header (type, member id, agora id, priority, delivery warranty, creation
// time, payload length) and an opaque payload.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mrt_dcdt/types.h"

namespace mrt::dcdt {

/// Header fields carried on the wire (see doc/protocol.md "Wire protocol").
struct MsgHeader {
  int32_t type = 0;
  int32_t member_id = 0;
  int32_t agora_id = 0;  ///< the Agora where the message was created
  uint8_t priority = 0;
  uint8_t warranty = DCDT_DW_GUARANTEED;
  uint8_t hops = 0;      ///< network channels travelled so far
  bool remote = false;   ///< entered this machine through a `link` channel
  DCDT_TIME creation_time = 0;
  uint64_t incarnation = 0;  ///< random per run of the origin Agora (a restart with the same id differs)
  uint64_t seq = 0;      ///< per-origin-Agora sequence number (loop/duplicate suppression)
};

class Msg {
 public:
  Msg() = default;
  Msg(int type, int member_id, int agora_id, int warranty);

  // --- the header fields and the payload (manual §3.3.3) ---
  int type() const { return header_.type; }
  int member_id() const { return header_.member_id; }
  int agora_id() const { return header_.agora_id; }
  int priority() const { return header_.priority; }
  int delivery_warranty() const { return header_.warranty; }
  DCDT_TIME creation_time() const { return header_.creation_time; }
  int payload_len() const { return static_cast<int>(payload_.size()); }
  /// The payload bytes, followed by a NUL not counted in payload_len().
  void* payload() { return data(); }
  const void* payload() const { return cdata(); }

  // --- setters for producers ---
  /// Copies len bytes (len is clamped to [0, kMaxPayload]).
  void set_payload(const void* data, int len);
  void set_payload(const std::string& s) { set_payload(s.data(), static_cast<int>(s.size())); }
  /// Resizes the payload (zero-filled) and returns it, for in-place filling.
  void* alloc_payload(int len);
  void set_priority(int p) { header_.priority = static_cast<uint8_t>(p); }

  std::string payload_string() const { return payload_; }
  const MsgHeader& header() const { return header_; }
  MsgHeader& mutable_header() { return header_; }

 private:
  void* data() { return payload_.data(); }
  const void* cdata() const { return payload_.c_str(); }
  MsgHeader header_;
  std::string payload_;  // std::string keeps a trailing NUL for C-string legacy readers
};

}  // namespace mrt::dcdt
