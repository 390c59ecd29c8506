#include "mrt_dcdt_bridge/frame.h"

#include <array>
#include <cstring>

namespace mrt::dcdt {

namespace {

std::array<uint32_t, 256> MakeCrcTable() {
  std::array<uint32_t, 256> t{};
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[i] = c;
  }
  return t;
}

void Put8(std::vector<uint8_t>& b, uint8_t v) { b.push_back(v); }
void Put32(std::vector<uint8_t>& b, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<uint8_t>(v >> s));
}
void Put64(std::vector<uint8_t>& b, uint64_t v) {
  for (int s = 56; s >= 0; s -= 8) b.push_back(static_cast<uint8_t>(v >> s));
}
uint32_t Get32(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}
uint64_t Get64(const uint8_t* p) { return (uint64_t(Get32(p)) << 32) | Get32(p + 4); }

// Frame = header + body + CRC; `body` is written by the caller after Begin.
std::vector<uint8_t> Begin(FrameKind kind, size_t body_size) {
  std::vector<uint8_t> b;
  b.reserve(kFrameOverhead + body_size);
  Put8(b, kMagic0);
  Put8(b, kMagic1);
  Put8(b, kVersion);
  Put8(b, static_cast<uint8_t>(kind));
  Put32(b, static_cast<uint32_t>(body_size));
  Put32(b, Crc32(b.data(), 8));
  return b;
}
std::vector<uint8_t> Finish(std::vector<uint8_t> b) {
  Put32(b, Crc32(b.data(), b.size()));
  return b;
}
bool KnownKind(uint8_t k) { return k >= 1 && k <= 5; }
// Magic, version, kind and the header CRC over bytes [0, 8) (p has >= 12 bytes).
bool HeaderOk(const uint8_t* p) {
  return p[0] == kMagic0 && p[1] == kMagic1 && p[2] == kVersion && KnownKind(p[3]) && Crc32(p, 8) == Get32(p + 8);
}

}  // namespace

uint32_t Crc32(const uint8_t* data, size_t n) {
  static const auto table = MakeCrcTable();
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::vector<uint8_t> EncodeMsg(const Msg& m, uint64_t link_seq) {
  const auto& h = m.header();
  const uint32_t len = static_cast<uint32_t>(m.ReadPayloadLen());
  auto b = Begin(FrameKind::MSG, kMsgBodyFixed + len);
  Put32(b, static_cast<uint32_t>(h.type));
  Put32(b, static_cast<uint32_t>(h.member_id));
  Put32(b, static_cast<uint32_t>(h.agora_id));
  Put8(b, h.priority);
  Put8(b, h.warranty);
  Put8(b, h.hops);
  Put8(b, h.remote ? 1 : 0);
  Put64(b, static_cast<uint64_t>(h.creation_time));
  Put64(b, h.incarnation);
  Put64(b, h.seq);
  Put64(b, link_seq);
  Put32(b, len);
  const auto* p = static_cast<const uint8_t*>(m.GetPayload());
  b.insert(b.end(), p, p + len);
  return Finish(std::move(b));
}

std::vector<uint8_t> EncodeAck(uint64_t seq) {
  auto b = Begin(FrameKind::ACK, 8);
  Put64(b, seq);
  return Finish(std::move(b));
}

std::vector<uint8_t> EncodeNack(uint64_t seq) {
  auto b = Begin(FrameKind::NACK, 8);
  Put64(b, seq);
  return Finish(std::move(b));
}

std::vector<uint8_t> EncodeHello(const Hello& h) {
  auto b = Begin(FrameKind::HELLO, 29);
  Put32(b, static_cast<uint32_t>(h.agora_id));
  Put64(b, h.incarnation);
  Put64(b, h.peer_incarnation);
  Put64(b, h.last_rx);
  Put8(b, h.reply ? 1 : 0);
  return Finish(std::move(b));
}

std::vector<uint8_t> EncodeBeacon(const Beacon& bc) {
  const size_t k = std::min<size_t>(bc.host_key.size(), 255), a = std::min<size_t>(bc.tcp_addr.size(), 255);
  auto b = Begin(FrameKind::BEACON, 4 + 2 + 1 + k + 1 + a);
  Put32(b, static_cast<uint32_t>(bc.agora_id));
  Put8(b, static_cast<uint8_t>(bc.tcp_port >> 8));
  Put8(b, static_cast<uint8_t>(bc.tcp_port));
  Put8(b, static_cast<uint8_t>(k));
  b.insert(b.end(), bc.host_key.begin(), bc.host_key.begin() + k);
  Put8(b, static_cast<uint8_t>(a));
  b.insert(b.end(), bc.tcp_addr.begin(), bc.tcp_addr.begin() + a);
  return Finish(std::move(b));
}

bool DecodeMsgBody(const std::vector<uint8_t>& body, MsgFrame* out) {
  if (body.size() < kMsgBodyFixed) return false;
  const uint8_t* p = body.data();
  const uint32_t len = Get32(p + 48);
  if (len > kMaxPayload || body.size() != kMsgBodyFixed + len) return false;
  const uint8_t flags = p[15];
  if (p[13] > DCDT_DW_GUARANTEED || (flags & ~1u) != 0) return false;
  auto& h = out->msg.mutable_header();
  h.type = static_cast<int32_t>(Get32(p));
  h.member_id = static_cast<int32_t>(Get32(p + 4));
  h.agora_id = static_cast<int32_t>(Get32(p + 8));
  h.priority = p[12];
  h.warranty = p[13];
  h.hops = p[14];
  h.remote = flags & 1;
  h.creation_time = static_cast<int64_t>(Get64(p + 16));
  h.incarnation = Get64(p + 24);
  h.seq = Get64(p + 32);
  out->link_seq = Get64(p + 40);
  out->msg.SetPayload(p + kMsgBodyFixed, static_cast<int>(len));
  return true;
}

bool DecodeAckBody(const std::vector<uint8_t>& body, uint64_t* seq) {
  if (body.size() != 8) return false;
  *seq = Get64(body.data());
  return true;
}

bool DecodeHelloBody(const std::vector<uint8_t>& body, Hello* out) {
  if (body.size() != 29 || (body[28] & ~1u) != 0) return false;
  out->agora_id = static_cast<int32_t>(Get32(body.data()));
  out->incarnation = Get64(body.data() + 4);
  out->peer_incarnation = Get64(body.data() + 12);
  out->last_rx = Get64(body.data() + 20);
  out->reply = body[28] & 1;
  return true;
}

bool DecodeBeaconBody(const std::vector<uint8_t>& body, Beacon* out) {
  if (body.size() < 8) return false;
  const uint8_t* p = body.data();
  out->agora_id = static_cast<int32_t>(Get32(p));
  out->tcp_port = static_cast<uint16_t>((p[4] << 8) | p[5]);
  size_t k = p[6];
  if (body.size() < 7 + k + 1) return false;
  out->host_key.assign(reinterpret_cast<const char*>(p + 7), k);
  size_t a = p[7 + k];
  if (body.size() != 8 + k + a) return false;
  out->tcp_addr.assign(reinterpret_cast<const char*>(p + 8 + k), a);
  return true;
}

bool DecodeDatagram(const uint8_t* data, size_t n, Frame* out) {
  if (n < kFrameOverhead || !HeaderOk(data)) return false;
  const uint32_t len = Get32(data + 4);
  if (len > kMaxBody || n != kFrameOverhead + len) return false;
  if (Crc32(data, kFrameHeader + len) != Get32(data + kFrameHeader + len)) return false;
  out->kind = static_cast<FrameKind>(data[3]);
  out->body.assign(data + kFrameHeader, data + kFrameHeader + len);
  return true;
}

void FrameDecoder::Feed(const uint8_t* data, size_t n) {
  if (pos_ > 0 && pos_ >= buf_.size() / 2) {
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<long>(pos_));
    pos_ = 0;
  }
  buf_.insert(buf_.end(), data, data + n);
}

std::optional<Frame> FrameDecoder::Next() {
  while (true) {
    const size_t avail = buf_.size() - pos_;
    if (avail < kFrameHeader) return std::nullopt;
    const uint8_t* p = buf_.data() + pos_;
    if (!HeaderOk(p)) {
      ++errors_;
      // Resync: skip to the next possible magic.
      size_t skip = 1;
      while (skip < avail && buf_[pos_ + skip] != kMagic0) ++skip;
      pos_ += skip;
      continue;
    }
    const uint32_t len = Get32(p + 4);
    if (len > kMaxBody) {
      ++errors_;
      pos_ += 1;
      continue;
    }
    if (avail < kFrameOverhead + len) return std::nullopt;
    if (Crc32(p, kFrameHeader + len) != Get32(p + kFrameHeader + len)) {
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
