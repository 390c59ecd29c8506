#include "mrt_dcdt/frame.h"

#include <cstring>

#include <boost/crc.hpp>

namespace mrt::dcdt {

namespace {

void put8(std::vector<uint8_t>& b, uint8_t v) { b.push_back(v); }
void put32(std::vector<uint8_t>& b, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<uint8_t>(v >> s));
}
void put64(std::vector<uint8_t>& b, uint64_t v) {
  for (int s = 56; s >= 0; s -= 8) b.push_back(static_cast<uint8_t>(v >> s));
}
uint32_t get32(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}
uint64_t get64(const uint8_t* p) { return (uint64_t(get32(p)) << 32) | get32(p + 4); }

// Frame = header + body + CRC; `body` is written by the caller after Begin.
std::vector<uint8_t> begin_frame(FrameKind kind, size_t body_size) {
  std::vector<uint8_t> b;
  b.reserve(kFrameOverhead + body_size);
  put8(b, kMagic0);
  put8(b, kMagic1);
  put8(b, kVersion);
  put8(b, static_cast<uint8_t>(kind));
  put32(b, static_cast<uint32_t>(body_size));
  put32(b, crc32_ieee(b.data(), 8));
  return b;
}
std::vector<uint8_t> finish_frame(std::vector<uint8_t> b) {
  put32(b, crc32_ieee(b.data(), b.size()));
  return b;
}
bool known_kind(uint8_t k) { return k >= 1 && k <= 5; }
// Magic, version, kind and the header CRC over bytes [0, 8) (p has >= 12 bytes).
bool header_ok(const uint8_t* p) {
  return p[0] == kMagic0 && p[1] == kMagic1 && p[2] == kVersion && known_kind(p[3]) && crc32_ieee(p, 8) == get32(p + 8);
}

}  // namespace

uint32_t crc32_ieee(const uint8_t* data, size_t n) {
  boost::crc_32_type c;  // CRC-32/IEEE 802.3, as zlib's crc32 and Ethernet
  c.process_bytes(data, n);
  return c.checksum();
}

std::vector<uint8_t> encode_msg(const Msg& m, uint64_t link_seq) {
  const auto& h = m.header();
  const uint32_t len = static_cast<uint32_t>(m.payload_len());
  auto b = begin_frame(FrameKind::MSG, kMsgBodyFixed + len);
  put32(b, static_cast<uint32_t>(h.type));
  put32(b, static_cast<uint32_t>(h.member_id));
  put32(b, static_cast<uint32_t>(h.agora_id));
  put8(b, h.priority);
  put8(b, h.warranty);
  put8(b, h.hops);
  put8(b, h.remote ? 1 : 0);
  put64(b, static_cast<uint64_t>(h.creation_time));
  put64(b, h.incarnation);
  put64(b, h.seq);
  put64(b, link_seq);
  put32(b, len);
  const auto* p = static_cast<const uint8_t*>(m.payload());
  b.insert(b.end(), p, p + len);
  return finish_frame(std::move(b));
}

std::vector<uint8_t> encode_ack(uint64_t seq) {
  auto b = begin_frame(FrameKind::ACK, 8);
  put64(b, seq);
  return finish_frame(std::move(b));
}

std::vector<uint8_t> encode_nack(uint64_t seq) {
  auto b = begin_frame(FrameKind::NACK, 8);
  put64(b, seq);
  return finish_frame(std::move(b));
}

std::vector<uint8_t> encode_hello(const Hello& h) {
  auto b = begin_frame(FrameKind::HELLO, 29);
  put32(b, static_cast<uint32_t>(h.agora_id));
  put64(b, h.incarnation);
  put64(b, h.peer_incarnation);
  put64(b, h.last_rx);
  put8(b, h.reply ? 1 : 0);
  return finish_frame(std::move(b));
}

std::vector<uint8_t> encode_beacon(const Beacon& bc) {
  const size_t k = std::min<size_t>(bc.host_key.size(), 255), a = std::min<size_t>(bc.tcp_addr.size(), 255);
  auto b = begin_frame(FrameKind::BEACON, 4 + 2 + 1 + k + 1 + a);
  put32(b, static_cast<uint32_t>(bc.agora_id));
  put8(b, static_cast<uint8_t>(bc.tcp_port >> 8));
  put8(b, static_cast<uint8_t>(bc.tcp_port));
  put8(b, static_cast<uint8_t>(k));
  b.insert(b.end(), bc.host_key.begin(), bc.host_key.begin() + k);
  put8(b, static_cast<uint8_t>(a));
  b.insert(b.end(), bc.tcp_addr.begin(), bc.tcp_addr.begin() + a);
  return finish_frame(std::move(b));
}

bool decode_msg_body(const std::vector<uint8_t>& body, MsgFrame* out) {
  if (body.size() < kMsgBodyFixed) return false;
  const uint8_t* p = body.data();
  const uint32_t len = get32(p + 48);
  if (len > kMaxPayload || body.size() != kMsgBodyFixed + len) return false;
  const uint8_t flags = p[15];
  if (p[13] > DCDT_DW_GUARANTEED || (flags & ~1u) != 0) return false;
  auto& h = out->msg.mutable_header();
  h.type = static_cast<int32_t>(get32(p));
  h.member_id = static_cast<int32_t>(get32(p + 4));
  h.agora_id = static_cast<int32_t>(get32(p + 8));
  h.priority = p[12];
  h.warranty = p[13];
  h.hops = p[14];
  h.remote = flags & 1;
  h.creation_time = static_cast<int64_t>(get64(p + 16));
  h.incarnation = get64(p + 24);
  h.seq = get64(p + 32);
  out->link_seq = get64(p + 40);
  out->msg.set_payload(p + kMsgBodyFixed, static_cast<int>(len));
  return true;
}

bool decode_ack_body(const std::vector<uint8_t>& body, uint64_t* seq) {
  if (body.size() != 8) return false;
  *seq = get64(body.data());
  return true;
}

bool decode_hello_body(const std::vector<uint8_t>& body, Hello* out) {
  if (body.size() != 29 || (body[28] & ~1u) != 0) return false;
  out->agora_id = static_cast<int32_t>(get32(body.data()));
  out->incarnation = get64(body.data() + 4);
  out->peer_incarnation = get64(body.data() + 12);
  out->last_rx = get64(body.data() + 20);
  out->reply = body[28] & 1;
  return true;
}

bool decode_beacon_body(const std::vector<uint8_t>& body, Beacon* out) {
  if (body.size() < 8) return false;
  const uint8_t* p = body.data();
  out->agora_id = static_cast<int32_t>(get32(p));
  out->tcp_port = static_cast<uint16_t>((p[4] << 8) | p[5]);
  size_t k = p[6];
  if (body.size() < 7 + k + 1) return false;
  out->host_key.assign(reinterpret_cast<const char*>(p + 7), k);
  size_t a = p[7 + k];
  if (body.size() != 8 + k + a) return false;
  out->tcp_addr.assign(reinterpret_cast<const char*>(p + 8 + k), a);
  return true;
}

bool decode_datagram(const uint8_t* data, size_t n, Frame* out) {
  if (n < kFrameOverhead || !header_ok(data)) return false;
  const uint32_t len = get32(data + 4);
  if (len > kMaxBody || n != kFrameOverhead + len) return false;
  if (crc32_ieee(data, kFrameHeader + len) != get32(data + kFrameHeader + len)) return false;
  out->kind = static_cast<FrameKind>(data[3]);
  out->body.assign(data + kFrameHeader, data + kFrameHeader + len);
  return true;
}

void FrameDecoder::feed(const uint8_t* data, size_t n) {
  if (pos_ > 0 && pos_ >= buf_.size() / 2) {
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<long>(pos_));
    pos_ = 0;
  }
  buf_.insert(buf_.end(), data, data + n);
}

std::optional<Frame> FrameDecoder::next() {
  while (true) {
    const size_t avail = buf_.size() - pos_;
    if (avail < kFrameHeader) return std::nullopt;
    const uint8_t* p = buf_.data() + pos_;
    if (!header_ok(p)) {
      ++errors_;
      // Resync: skip to the next possible magic.
      size_t skip = 1;
      while (skip < avail && buf_[pos_ + skip] != kMagic0) ++skip;
      pos_ += skip;
      continue;
    }
    const uint32_t len = get32(p + 4);
    if (len > kMaxBody) {
      ++errors_;
      pos_ += 1;
      continue;
    }
    if (avail < kFrameOverhead + len) return std::nullopt;
    if (crc32_ieee(p, kFrameHeader + len) != get32(p + kFrameHeader + len)) {
      ++errors_;
      pos_ += 1;
      continue;
    }
    Frame f{static_cast<FrameKind>(p[3]), std::vector<uint8_t>(p + kFrameHeader, p + kFrameHeader + len)};
    pos_ += kFrameOverhead + len;
    return f;
  }
}

}  // namespace mrt::dcdt
