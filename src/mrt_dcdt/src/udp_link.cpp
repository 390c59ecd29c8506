// UdpLink: see udp_link.h and doc/protocol.md "Wire protocol".
#include "udp_link.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include "mrt_dcdt/frame.h"

namespace mrt::dcdt::link {

void UdpLink::start() {
  net::make_addr(cfg_.remote_addr, cfg_.remote_port, &remote_);
  thread_ = std::thread([this] { loop(); });
}

void UdpLink::stop() {
  stop_ = true;
  waker_.wake();
  if (thread_.joinable()) thread_.join();
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void UdpLink::send(const MsgPtr& m) {
  OutQueue::Result r;
  {
    std::lock_guard<std::mutex> l(mu_);
    r = outq_.push(m, 0, o_.max_queue_bytes, c);  // never guaranteed: a full queue drops the oldest
  }
  // The thread drains the whole queue: only the first message needs a wake-up.
  if (r == OutQueue::kQueuedFirst) waker_.wake();
}

uint64_t UdpLink::pending() const {
  std::lock_guard<std::mutex> l(mu_);
  return outq_.size() + pending_size_;
}

bool UdpLink::open() {
  sockaddr_in a;
  if (!net::make_addr(cfg_.local_addr, cfg_.local_port, &a)) return false;
  int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return false;
  int one = 1, buf = 4 << 20;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &buf, sizeof buf);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(fd);
    return false;
  }
  fd_ = fd;
  return true;
}

void UdpLink::send_to(const std::vector<uint8_t>& b) {
  if (::sendto(fd_, b.data(), b.size(), 0, reinterpret_cast<const sockaddr*>(&remote_), sizeof remote_) < 0)
    ++c.errors;
}

void UdpLink::loop() {
  while (!stop_ && !open()) {
    pollfd p{waker_.fd(), POLLIN, 0};
    ::poll(&p, 1, 200);
  }
  std::vector<uint8_t> rbuf(65536);
  while (!stop_) {
    pollfd p[2] = {{fd_, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
    ::poll(p, 2, 50);
    if (p[1].revents) waker_.drain();
    if (p[0].revents & POLLIN) receive(rbuf);
    const auto now = Clock::now();
    send_queued(now);
    retransmit(now);
    {
      std::lock_guard<std::mutex> l(mu_);
      pending_size_ = pending_.size();
    }
    c.connected = true;
  }
}

void UdpLink::receive(std::vector<uint8_t>& rbuf) {
  for (int k = 0; k < 256; ++k) {
    sockaddr_in from{};
    socklen_t fl = sizeof from;
    ssize_t r = ::recvfrom(fd_, rbuf.data(), rbuf.size(), MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&from), &fl);
    if (r < 0) break;
    if (from.sin_addr.s_addr != remote_.sin_addr.s_addr) {
      ++c.errors;  // only the configured peer may talk on this channel
      continue;
    }
    on_datagram(rbuf.data(), static_cast<size_t>(r), from);
  }
}

void UdpLink::on_datagram(const uint8_t* data, size_t n, const sockaddr_in& from) {
  Frame f;
  if (!decode_datagram(data, n, &f)) {
    ++c.errors;
    return;
  }
  if (f.kind == FrameKind::MSG) {
    MsgFrame mf;
    if (!decode_msg_body(f.body, &mf)) {
      ++c.errors;
      return;
    }
    if (mf.link_seq != 0) {
      auto a = encode_ack(mf.link_seq);
      ::sendto(fd_, a.data(), a.size(), 0, reinterpret_cast<const sockaddr*>(&from), sizeof from);
    }
    ++c.received;
    c.peer_agora = mf.msg.agora_id();
    rx_(std::make_shared<Msg>(std::move(mf.msg)), owner_);  // copies are dropped by the Agora
  } else if (f.kind == FrameKind::ACK) {
    uint64_t s;
    if (decode_ack_body(f.body, &s)) pending_.erase(s);
  }
}

void UdpLink::send_queued(Clock::time_point now) {
  std::deque<MsgPtr> batch;
  {
    std::lock_guard<std::mutex> l(mu_);
    batch.swap(outq_.q);
    outq_.bytes = 0;
  }
  for (auto& m : batch) {
    const bool retx = m->delivery_warranty() == DCDT_DW_RETRANSMIT;
    const uint64_t seq = retx ? next_seq_++ : 0;
    auto b = encode_msg(*m, seq);
    send_to(b);
    ++c.sent;
    if (retx) pending_[seq] = Retx{std::move(b), 1, now + std::chrono::milliseconds(o_.retransmit_interval_ms)};
  }
}

void UdpLink::retransmit(Clock::time_point now) {
  for (auto it = pending_.begin(); it != pending_.end();) {
    if (it->second.due > now) {
      ++it;
      continue;
    }
    if (it->second.tries >= o_.retransmit_tries) {
      ++c.dropped;
      it = pending_.erase(it);
      continue;
    }
    send_to(it->second.bytes);
    ++c.resent;
    ++it->second.tries;
    it->second.due = now + std::chrono::milliseconds(o_.retransmit_interval_ms);
    ++it;
  }
}

}  // namespace mrt::dcdt::link
