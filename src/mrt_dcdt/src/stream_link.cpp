// StreamLink: see stream_link.h and doc/protocol.md "Wire protocol".
#include "stream_link.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace mrt::dcdt::link {

namespace {
constexpr size_t kLossyWindow = 64;          // guaranteed messages in flight on a serial line
constexpr size_t kMaxWriteBatch = 4u << 20;  // bytes queued for one write

void append(std::vector<uint8_t>& wbuf, const std::vector<uint8_t>& bytes) {
  wbuf.insert(wbuf.end(), bytes.begin(), bytes.end());
}
}  // namespace

void StreamLink::stop() {
  stop_ = true;
  waker_.wake();
  if (thread_.joinable()) thread_.join();
}

bool StreamLink::send(const MsgPtr& m) {
  OutQueue::Result r;
  {
    std::lock_guard<std::mutex> l(mu_);
    r = outq_.push(m, unacked_bytes_, o_.max_queue_bytes, c);
  }
  // The thread drains the whole queue: only the first message needs a wake-up.
  if (r == OutQueue::kQueuedFirst) waker_.wake();
  return r != OutQueue::kRefused;
}

uint64_t StreamLink::pending() const {
  std::lock_guard<std::mutex> l(mu_);
  return outq_.size() + unacked_.size();
}

void StreamLink::loop() {
  while (!stop_) {
    std::vector<uint8_t> prefix;
    int fd = connect_(stop_, &prefix);
    if (fd == kGiveUp) break;
    if (fd < 0) {
      sleep(o_.reconnect_ms);
      continue;
    }
    ++c.reconnects;
    c.connected = true;
    session(fd, prefix);
    c.connected = false;
    ::close(fd);
  }
  dead_ = true;
}

void StreamLink::sleep(int ms) {
  pollfd p{waker_.fd(), POLLIN, 0};
  ::poll(&p, 1, ms);
  waker_.drain();
}

std::vector<uint8_t> StreamLink::my_hello(bool reply) const {
  return encode_hello(Hello{o_.agora_id, o_.incarnation, peer_inc_, last_rx_, reply});
}

void StreamLink::ack_up_to(uint64_t s) {
  bool progress = false;
  while (!unacked_.empty() && unacked_.front().seq <= s) {
    unacked_bytes_ -= cost(*unacked_.front().msg);
    unacked_.pop_front();
    progress = true;
  }
  if (progress) front_since_ = Clock::now();
}

void StreamLink::resend_all(std::vector<uint8_t>& wbuf) {
  for (auto& u : unacked_) {
    append(wbuf, u.bytes);
    ++c.resent;
  }
  front_since_ = Clock::now();
}

void StreamLink::on_hello(const Hello& h, bool* ready, std::vector<uint8_t>& wbuf) {
  std::lock_guard<std::mutex> l(mu_);
  if (h.agora_id != c.peer_agora || h.incarnation != peer_inc_) {
    // A new peer process (even with the same agora id): its link seqs
    // restart, and what we still owe it is renumbered from 1.
    c.peer_agora = h.agora_id;
    peer_inc_ = h.incarnation;
    last_rx_ = 0;
    uint64_t seq = 0;
    for (auto& u : unacked_) {
      u.seq = ++seq;
      u.bytes = encode_msg(*u.msg, u.seq);
    }
    next_seq_ = seq + 1;
    *ready = false;
  }
  const bool was_ready = *ready;
  if (h.peer_incarnation == o_.incarnation) *ready = true;  // it knows this run of us
  if (h.reply) append(wbuf, my_hello(!*ready));
  if (!*ready) return;
  ack_up_to(h.last_rx);
  if (!was_ready) resend_all(wbuf);  // a new session: whatever it has not acknowledged
}

namespace {
bool flush(int fd, std::vector<uint8_t>& wbuf) {
  if (wbuf.empty()) return true;
  const bool ok = net::write_all(fd, wbuf.data(), wbuf.size());
  wbuf.clear();
  return ok;
}
}  // namespace

void StreamLink::session(int fd, const std::vector<uint8_t>& prefix) {
  SessionState s;
  std::vector<uint8_t> rbuf(65536);
  if (!prefix.empty()) handle_bytes(prefix.data(), prefix.size(), s);
  while (!stop_) {
    if (replaced_ && replaced_()) return;  // a newer connection to the same peer is waiting
    const auto now = Clock::now();
    if (!s.peer_ready && now - s.last_hello > std::chrono::milliseconds(300)) {
      std::lock_guard<std::mutex> l(mu_);
      append(s.wbuf, my_hello(true));
      s.last_hello = now;
    }
    if (s.send_ack) append(s.wbuf, encode_ack(last_rx_));
    s.send_ack = false;
    if (!flush(fd, s.wbuf)) return;
    pollfd p[2] = {{fd, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
    if (::poll(p, 2, 50) < 0 && errno != EINTR) return;
    if (p[1].revents) waker_.drain();
    if (p[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      const ReadResult r = read_frames(fd, rbuf, s);
      if (r == ReadResult::kEnded) return;  // EOF or error: reconnect
      if (r == ReadResult::kRetry) continue;
    }
    if (s.send_ack) append(s.wbuf, encode_ack(last_rx_));
    s.send_ack = false;
    if (s.peer_ready) fill_outbound(s.wbuf);
    if (!flush(fd, s.wbuf)) return;
  }
}

void StreamLink::handle_bytes(const uint8_t* data, size_t n, SessionState& s) {
  s.dec.feed(data, n);
  while (auto f = s.dec.next()) on_frame(*f, s);
  c.errors += s.dec.errors() - s.counted_errors;  // the decoder counts per session
  s.counted_errors = s.dec.errors();
}

StreamLink::ReadResult StreamLink::read_frames(int fd, std::vector<uint8_t>& rbuf, SessionState& s) {
  ssize_t r = ::read(fd, rbuf.data(), rbuf.size());
  if (r <= 0) return r < 0 && (errno == EINTR || errno == EAGAIN) ? ReadResult::kRetry : ReadResult::kEnded;
  handle_bytes(rbuf.data(), static_cast<size_t>(r), s);
  return ReadResult::kDone;
}

void StreamLink::on_frame(const Frame& f, SessionState& s) {
  if (f.kind == FrameKind::HELLO) {
    Hello h;
    if (!decode_hello_body(f.body, &h)) {
      ++c.errors;
      return;
    }
    on_hello(h, &s.peer_ready, s.wbuf);
  } else if (f.kind == FrameKind::MSG) {
    MsgFrame mf;
    if (!decode_msg_body(f.body, &mf)) {
      ++c.errors;
      return;
    }
    on_msg(std::move(mf), s);
  } else if (f.kind == FrameKind::ACK || f.kind == FrameKind::NACK) {
    uint64_t seq;
    if (!decode_ack_body(f.body, &seq)) {
      ++c.errors;
      return;
    }
    if (!s.peer_ready) return;  // it refers to a run of us the peer has not confirmed
    std::lock_guard<std::mutex> l(mu_);
    ack_up_to(seq);
    if (f.kind == FrameKind::NACK) resend_all(s.wbuf);  // go back N
  }
}

void StreamLink::on_msg(MsgFrame mf, SessionState& s) {
  if (mf.link_seq != 0) {
    // Numbered for a run of us the peer has not yet named in this session
    // (bytes an earlier run left in the line): it resends them once it has.
    if (!s.peer_ready) return;
    s.send_ack = true;
    if (mf.link_seq <= last_rx_) return;  // already delivered (a resend)
    if (mf.link_seq != last_rx_ + 1) {
      // A gap: an earlier frame was lost. Do not deliver out of order nor
      // acknowledge past the gap; ask for a resend.
      ++c.gaps;
      if (s.nack_for != last_rx_ || Clock::now() - s.nack_at > std::chrono::milliseconds(100)) {
        append(s.wbuf, encode_nack(last_rx_));
        s.nack_for = last_rx_;
        s.nack_at = Clock::now();
      }
      return;
    }
    last_rx_ = mf.link_seq;
  }
  ++c.received;
  rx_(std::make_shared<Msg>(std::move(mf.msg)), owner_);
}

void StreamLink::fill_outbound(std::vector<uint8_t>& wbuf) {
  std::lock_guard<std::mutex> l(mu_);
  // A lossy line can also lose the last frame or an ACK/NACK: resend what
  // stays unacknowledged for too long.
  if (lossy_ && !unacked_.empty() && Clock::now() - front_since_ > std::chrono::milliseconds(o_.stream_resend_ms))
    resend_all(wbuf);
  // At most `window` guaranteed messages in flight; the rest wait in the
  // (bounded) queue, so the link sequence never has holes. On a lossy line a
  // small window bounds what one go-back resends.
  const size_t window = lossy_ ? std::min<size_t>(o_.max_unacked, kLossyWindow) : o_.max_unacked;
  while (!outq_.empty() && wbuf.size() < kMaxWriteBatch && unacked_.size() < window) {
    MsgPtr m = outq_.pop();
    if (m->delivery_warranty() == DCDT_DW_GUARANTEED) {
      unacked_bytes_ += cost(*m);
      const uint64_t seq = next_seq_++;
      auto bytes = encode_msg(*m, seq);
      append(wbuf, bytes);
      if (unacked_.empty()) front_since_ = Clock::now();
      unacked_.push_back(Unacked{seq, std::move(m), std::move(bytes)});
    } else {
      append(wbuf, encode_msg(*m, 0));
    }
    ++c.sent;
  }
  if (!outq_.empty() && unacked_.size() < window) waker_.wake();
}

}  // namespace mrt::dcdt::link
