// Channel implementations: StreamLink (TCP or serial byte stream with
// acknowledged, resendable guaranteed messages) and UdpLink (datagrams with
// optional acknowledged retransmission). See README "Wire protocol".
#include <arpa/inet.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <algorithm>
#include <deque>
#include <map>
#include <mutex>
#include <thread>

#include "mrt_dcdt_bridge/channel.h"
#include "mrt_dcdt_bridge/frame.h"
#include "net_util.h"

namespace mrt::dcdt {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kGiveUp = -2;
constexpr size_t kMaxOutQueue = 200000;
constexpr size_t kMaxUdpFrame = 60000;
constexpr size_t kLossyWindow = 64;  // guaranteed messages in flight on a serial line

// Appends to a link's outbound queue, dropping (and counting) the oldest
// message when it is full. Returns whether the queue was empty, i.e. whether
// the link's thread needs a wake-up. The caller holds the queue's lock.
bool PushBounded(std::deque<MsgPtr>& q, const MsgPtr& m, std::atomic<uint64_t>& dropped) {
  if (q.size() >= kMaxOutQueue) {
    q.pop_front();
    ++dropped;
  }
  const bool was_empty = q.empty();
  q.push_back(m);
  return was_empty;
}

struct Counters {
  std::atomic<uint64_t> sent{0}, received{0}, resent{0}, dropped{0}, errors{0}, reconnects{0}, gaps{0};
  std::atomic<bool> connected{false};
  std::atomic<int> peer_agora{0};
  void Fill(ChannelStats* s) const {
    s->sent += sent;
    s->received += received;
    s->resent += resent;
    s->dropped += dropped;
    s->errors += errors;
    s->reconnects += reconnects;
    s->gaps += gaps;
    s->connected = s->connected || connected;
    if (peer_agora) s->peer_agora = peer_agora;
  }
};

// ---------------------------------------------------------------- StreamLink
// Guaranteed messages on a stream carry a link sequence 1, 2, 3 ... per
// (our incarnation, peer incarnation) pair; the receiver accepts only the
// next one (a frame lost to a CRC error leaves a gap: later frames are
// discarded and a NACK asks for everything after the last good one) and
// acknowledges cumulatively. Other warranties carry link sequence 0 and are
// accepted as they come. The HELLO handshake: each side announces its
// (agora id, incarnation), the incarnation it knows of the peer and what it
// received from it; MSG frames are sent only once the peer's HELLO names our
// incarnation. A new peer incarnation (a restart, even with the same id)
// resets what we received from it and renumbers what we still owe it.
class StreamLink {
 public:
  /// Returns a connected fd, -1 to retry later, kGiveUp to end for good.
  using ConnectFn = std::function<int(const std::atomic<bool>& stop)>;

  StreamLink(ChannelOptions o, ConnectFn connect, Channel* owner, Channel::ReceiveFn rx, bool lossy)
      : o_(o), connect_(std::move(connect)), owner_(owner), rx_(std::move(rx)), lossy_(lossy) {}
  ~StreamLink() { Stop(); }

  void Start() { thread_ = std::thread([this] { Loop(); }); }
  void Stop() {
    stop_ = true;
    waker_.Wake();
    if (thread_.joinable()) thread_.join();
  }
  void Send(const MsgPtr& m) {
    bool was_empty;
    {
      std::lock_guard<std::mutex> l(mu_);
      was_empty = PushBounded(outq_, m, c.dropped);
    }
    // The thread drains the whole queue: only the first message needs a wake-up.
    if (was_empty) waker_.Wake();
  }
  bool dead() const { return dead_; }
  uint64_t Pending() const {
    std::lock_guard<std::mutex> l(mu_);
    return outq_.size() + unacked_.size();
  }
  Counters c;

 private:
  struct Unacked {
    uint64_t seq;
    MsgPtr msg;
    std::vector<uint8_t> bytes;
  };

  void Loop() {
    while (!stop_) {
      int fd = connect_(stop_);
      if (fd == kGiveUp) break;
      if (fd < 0) {
        Sleep(o_.reconnect_ms);
        continue;
      }
      ++c.reconnects;
      c.connected = true;
      Session(fd);
      c.connected = false;
      ::close(fd);
    }
    dead_ = true;
  }

  void Sleep(int ms) {
    pollfd p{waker_.fd(), POLLIN, 0};
    ::poll(&p, 1, ms);
    waker_.Drain();
  }

  std::vector<uint8_t> MyHello(bool reply) const {
    return EncodeHello(Hello{o_.agora_id, o_.incarnation, peer_inc_, last_rx_, reply});
  }

  // Removes what the peer acknowledged (cumulative). Caller holds mu_.
  void AckUpTo(uint64_t s) {
    bool progress = false;
    while (!unacked_.empty() && unacked_.front().seq <= s) {
      unacked_.pop_front();
      progress = true;
    }
    if (progress) front_since_ = Clock::now();
  }
  // Appends every unacknowledged frame (go-back-N). Caller holds mu_.
  void ResendAll(std::vector<uint8_t>& wbuf) {
    for (auto& u : unacked_) {
      wbuf.insert(wbuf.end(), u.bytes.begin(), u.bytes.end());
      ++c.resent;
    }
    front_since_ = Clock::now();
  }

  void OnHello(const Hello& h, bool* ready, std::vector<uint8_t>& wbuf) {
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
        u.bytes = EncodeMsg(*u.msg, u.seq);
      }
      next_seq_ = seq + 1;
      *ready = false;
    }
    const bool was_ready = *ready;
    if (h.peer_incarnation == o_.incarnation) *ready = true;  // it knows this run of us
    if (h.reply) {
      auto hb = MyHello(!*ready);
      wbuf.insert(wbuf.end(), hb.begin(), hb.end());
    }
    if (!*ready) return;
    AckUpTo(h.last_rx);
    if (!was_ready) ResendAll(wbuf);  // a new session: whatever it has not acknowledged
  }

  void Session(int fd) {
    FrameDecoder dec;
    bool peer_ready = false;
    auto last_hello = Clock::now() - std::chrono::seconds(10);
    auto nack_at = Clock::now() - std::chrono::seconds(10);
    uint64_t nack_for = ~0ull;
    std::vector<uint8_t> rbuf(65536), wbuf;
    while (!stop_) {
      const auto now = Clock::now();
      wbuf.clear();
      if (!peer_ready && now - last_hello > std::chrono::milliseconds(300)) {
        std::lock_guard<std::mutex> l(mu_);
        auto h = MyHello(true);
        wbuf.insert(wbuf.end(), h.begin(), h.end());
        last_hello = now;
      }
      if (!wbuf.empty() && !net::WriteAll(fd, wbuf.data(), wbuf.size())) return;
      wbuf.clear();
      pollfd p[2] = {{fd, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
      if (::poll(p, 2, 50) < 0 && errno != EINTR) return;
      if (p[1].revents) waker_.Drain();
      bool send_ack = false;
      if (p[0].revents & (POLLIN | POLLHUP | POLLERR)) {
        ssize_t r = ::read(fd, rbuf.data(), rbuf.size());
        if (r <= 0) {
          if (r < 0 && (errno == EINTR || errno == EAGAIN)) continue;
          return;  // EOF or error: reconnect
        }
        dec.Feed(rbuf.data(), static_cast<size_t>(r));
        while (auto f = dec.Next()) {
          if (f->kind == FrameKind::HELLO) {
            Hello h;
            if (!DecodeHelloBody(f->body, &h)) {
              ++c.errors;
              continue;
            }
            OnHello(h, &peer_ready, wbuf);
          } else if (f->kind == FrameKind::MSG) {
            MsgFrame mf;
            if (!DecodeMsgBody(f->body, &mf)) {
              ++c.errors;
              continue;
            }
            if (mf.link_seq != 0) {
              send_ack = true;
              if (mf.link_seq <= last_rx_) continue;  // already delivered (a resend)
              if (mf.link_seq != last_rx_ + 1) {
                // A gap: an earlier frame was lost. Do not deliver out of
                // order nor acknowledge past the gap; ask for a resend.
                ++c.gaps;
                if (nack_for != last_rx_ || Clock::now() - nack_at > std::chrono::milliseconds(100)) {
                  auto n = EncodeNack(last_rx_);
                  wbuf.insert(wbuf.end(), n.begin(), n.end());
                  nack_for = last_rx_;
                  nack_at = Clock::now();
                }
                continue;
              }
              last_rx_ = mf.link_seq;
            }
            ++c.received;
            rx_(std::make_shared<Msg>(std::move(mf.msg)), owner_);
          } else if (f->kind == FrameKind::ACK || f->kind == FrameKind::NACK) {
            uint64_t s;
            if (!DecodeAckBody(f->body, &s)) {
              ++c.errors;
              continue;
            }
            if (!peer_ready) continue;  // it refers to a run of us the peer has not confirmed
            std::lock_guard<std::mutex> l(mu_);
            AckUpTo(s);
            if (f->kind == FrameKind::NACK) ResendAll(wbuf);  // go back N
          }
        }
        c.errors += dec.errors() - counted_errors_;
        counted_errors_ = dec.errors();
      }
      if (send_ack) {
        auto a = EncodeAck(last_rx_);
        wbuf.insert(wbuf.end(), a.begin(), a.end());
      }
      if (peer_ready) {
        std::lock_guard<std::mutex> l(mu_);
        // A lossy line can also lose the last frame or an ACK/NACK: resend
        // what stays unacknowledged for too long.
        if (lossy_ && !unacked_.empty() &&
            Clock::now() - front_since_ > std::chrono::milliseconds(o_.stream_resend_ms))
          ResendAll(wbuf);
        // At most `window` guaranteed messages in flight; the rest wait in
        // the (bounded) queue, so the link sequence never has holes. On a
        // lossy line a small window bounds what one go-back resends.
        const size_t window = lossy_ ? std::min<size_t>(o_.max_unacked, kLossyWindow) : o_.max_unacked;
        while (!outq_.empty() && wbuf.size() < (4u << 20) && unacked_.size() < window) {
          MsgPtr m = std::move(outq_.front());
          outq_.pop_front();
          if (m->ReadDeliveryWarranty() == DCDT_DW_GUARANTEED) {
            const uint64_t seq = next_seq_++;
            auto bytes = EncodeMsg(*m, seq);
            wbuf.insert(wbuf.end(), bytes.begin(), bytes.end());
            if (unacked_.empty()) front_since_ = Clock::now();
            unacked_.push_back(Unacked{seq, std::move(m), std::move(bytes)});
          } else {
            auto bytes = EncodeMsg(*m, 0);
            wbuf.insert(wbuf.end(), bytes.begin(), bytes.end());
          }
          ++c.sent;
        }
        if (!outq_.empty() && unacked_.size() < window) waker_.Wake();
      }
      if (!wbuf.empty() && !net::WriteAll(fd, wbuf.data(), wbuf.size())) return;
    }
  }

  ChannelOptions o_;
  ConnectFn connect_;
  Channel* owner_;
  Channel::ReceiveFn rx_;
  bool lossy_;  ///< serial: frames can be lost without the connection dropping
  std::atomic<bool> stop_{false}, dead_{false};
  net::Waker waker_;
  std::thread thread_;
  mutable std::mutex mu_;
  std::deque<MsgPtr> outq_;
  std::deque<Unacked> unacked_;
  Clock::time_point front_since_ = Clock::now();
  uint64_t next_seq_ = 1;
  uint64_t last_rx_ = 0;
  uint64_t peer_inc_ = 0;
  uint64_t counted_errors_ = 0;
};

// ------------------------------------------------------------------ UdpLink
class UdpLink {
 public:
  UdpLink(const ChannelConfig& cfg, ChannelOptions o, Channel* owner, Channel::ReceiveFn rx)
      : cfg_(cfg), o_(o), owner_(owner), rx_(std::move(rx)) {}
  ~UdpLink() { Stop(); }

  void Start() {
    net::MakeAddr(cfg_.remote_addr, cfg_.remote_port, &remote_);
    thread_ = std::thread([this] { Loop(); });
  }
  void Stop() {
    stop_ = true;
    waker_.Wake();
    if (thread_.joinable()) thread_.join();
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  void Send(const MsgPtr& m) {
    bool was_empty;
    {
      std::lock_guard<std::mutex> l(mu_);
      was_empty = PushBounded(outq_, m, c.dropped);
    }
    // The thread drains the whole queue: only the first message needs a wake-up.
    if (was_empty) waker_.Wake();
  }
  uint64_t Pending() const {
    std::lock_guard<std::mutex> l(mu_);
    return outq_.size() + pending_size_;
  }
  Counters c;

 private:
  bool Open() {
    sockaddr_in a;
    if (!net::MakeAddr(cfg_.local_addr, cfg_.local_port, &a)) return false;
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
  void SendTo(const std::vector<uint8_t>& b) {
    if (::sendto(fd_, b.data(), b.size(), 0, reinterpret_cast<const sockaddr*>(&remote_), sizeof remote_) < 0)
      ++c.errors;
  }

  void Loop() {
    while (!stop_ && !Open()) {
      pollfd p{waker_.fd(), POLLIN, 0};
      ::poll(&p, 1, 200);
    }
    std::vector<uint8_t> rbuf(65536);
    while (!stop_) {
      int timeout = 50;
      pollfd p[2] = {{fd_, POLLIN, 0}, {waker_.fd(), POLLIN, 0}};
      ::poll(p, 2, timeout);
      if (p[1].revents) waker_.Drain();
      if (p[0].revents & POLLIN) {
        for (int k = 0; k < 256; ++k) {
          sockaddr_in from{};
          socklen_t fl = sizeof from;
          ssize_t r = ::recvfrom(fd_, rbuf.data(), rbuf.size(), MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&from), &fl);
          if (r < 0) break;
          if (from.sin_addr.s_addr != remote_.sin_addr.s_addr) {
            ++c.errors;  // only the configured peer may talk on this channel
            continue;
          }
          Frame f;
          if (!DecodeDatagram(rbuf.data(), static_cast<size_t>(r), &f)) {
            ++c.errors;
            continue;
          }
          if (f.kind == FrameKind::MSG) {
            MsgFrame mf;
            if (!DecodeMsgBody(f.body, &mf)) {
              ++c.errors;
              continue;
            }
            if (mf.link_seq != 0) {
              auto a = EncodeAck(mf.link_seq);
              ::sendto(fd_, a.data(), a.size(), 0, reinterpret_cast<sockaddr*>(&from), fl);
            }
            ++c.received;
            c.peer_agora = mf.msg.ReadAgoraID();
            rx_(std::make_shared<Msg>(std::move(mf.msg)), owner_);  // copies are dropped by the Agora
          } else if (f.kind == FrameKind::ACK) {
            uint64_t s;
            if (DecodeAckBody(f.body, &s)) pending_.erase(s);
          }
        }
      }
      std::deque<MsgPtr> batch;
      {
        std::lock_guard<std::mutex> l(mu_);
        batch.swap(outq_);
      }
      const auto now = Clock::now();
      for (auto& m : batch) {
        const bool retx = m->ReadDeliveryWarranty() == DCDT_DW_RETRANSMIT;
        const uint64_t seq = retx ? next_seq_++ : 0;
        auto b = EncodeMsg(*m, seq);
        SendTo(b);
        ++c.sent;
        if (retx) pending_[seq] = Retx{std::move(b), 1, now + std::chrono::milliseconds(o_.retransmit_interval_ms)};
      }
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
        SendTo(it->second.bytes);
        ++c.resent;
        ++it->second.tries;
        it->second.due = now + std::chrono::milliseconds(o_.retransmit_interval_ms);
        ++it;
      }
      {
        std::lock_guard<std::mutex> l(mu_);
        pending_size_ = pending_.size();
      }
      c.connected = true;
    }
  }

  struct Retx {
    std::vector<uint8_t> bytes;
    int tries;
    Clock::time_point due;
  };
  ChannelConfig cfg_;
  ChannelOptions o_;
  Channel* owner_;
  Channel::ReceiveFn rx_;
  sockaddr_in remote_{};
  int fd_ = -1;
  std::atomic<bool> stop_{false};
  net::Waker waker_;
  std::thread thread_;
  mutable std::mutex mu_;
  std::deque<MsgPtr> outq_;
  std::map<uint64_t, Retx> pending_;
  size_t pending_size_ = 0;
  uint64_t next_seq_ = 1;
};

// ---------------------------------------------------------------- channels
class IpChannel : public Channel {
 public:
  IpChannel(const ChannelConfig& cfg, const ChannelOptions& o, ReceiveFn rx) : cfg_(cfg) {
    mode = cfg.mode;
    level = cfg.level;
    const bool dial = std::make_pair(ntohl(Addr(cfg.local_addr)), cfg.local_port) <
                      std::make_pair(ntohl(Addr(cfg.remote_addr)), cfg.remote_port);
    StreamLink::ConnectFn fn;
    if (dial) {
      fn = [this](const std::atomic<bool>&) {
        return net::TcpConnect(cfg_.local_addr, cfg_.remote_addr, cfg_.remote_port, 200);
      };
    } else {
      fn = [this](const std::atomic<bool>&) {
        if (listen_fd_ < 0) listen_fd_ = net::TcpListen(cfg_.local_addr, cfg_.local_port);
        if (listen_fd_ < 0) return -1;
        sockaddr_in peer{};
        int fd = net::TcpAccept(listen_fd_, 100, &peer);
        if (fd >= 0 && peer.sin_addr.s_addr != Addr(cfg_.remote_addr)) {
          ::close(fd);  // only the configured peer may connect
          return -1;
        }
        return fd;
      };
    }
    stream_ = std::make_unique<StreamLink>(o, fn, this, rx, /*lossy=*/false);
    udp_ = std::make_unique<UdpLink>(cfg, o, this, rx);
  }
  ~IpChannel() override { Stop(); }
  void Start() override {
    stream_->Start();
    udp_->Start();
  }
  void Stop() override {
    stream_->Stop();
    udp_->Stop();
    if (listen_fd_ >= 0) ::close(listen_fd_);
    listen_fd_ = -1;
  }
  void Send(const MsgPtr& m) override {
    if (m->ReadDeliveryWarranty() == DCDT_DW_GUARANTEED ||
        static_cast<size_t>(m->ReadPayloadLen()) + kMsgBodyFixed + kFrameOverhead > kMaxUdpFrame)
      stream_->Send(m);  // too big for a datagram: the stream carries it
    else
      udp_->Send(m);
  }
  ChannelStats Stats() const override {
    ChannelStats s;
    s.name = std::string(mode == ChannelMode::LINK ? "ip link " : "ip bridge ") + cfg_.local_addr + ":" +
             std::to_string(cfg_.local_port) + " -> " + cfg_.remote_addr + ":" + std::to_string(cfg_.remote_port);
    stream_->c.Fill(&s);
    udp_->c.Fill(&s);
    s.connected = stream_->c.connected;
    s.pending = stream_->Pending() + udp_->Pending();
    return s;
  }

 private:
  static in_addr_t Addr(const std::string& ip) {
    sockaddr_in a;
    net::MakeAddr(ip, 0, &a);
    return a.sin_addr.s_addr;
  }
  ChannelConfig cfg_;
  int listen_fd_ = -1;
  std::unique_ptr<StreamLink> stream_;
  std::unique_ptr<UdpLink> udp_;
};

class StreamChannel : public Channel {
 public:
  StreamChannel(std::string name, const ChannelOptions& o, StreamLink::ConnectFn fn, ReceiveFn rx, bool lossy)
      : name_(std::move(name)) {
    stream_ = std::make_unique<StreamLink>(o, std::move(fn), this, std::move(rx), lossy);
  }
  ~StreamChannel() override { Stop(); }
  void Start() override { stream_->Start(); }
  void Stop() override { stream_->Stop(); }
  void Send(const MsgPtr& m) override { stream_->Send(m); }
  bool Dead() const override { return stream_->dead(); }
  ChannelStats Stats() const override {
    ChannelStats s;
    s.name = name_;
    stream_->c.Fill(&s);
    s.pending = stream_->Pending();
    return s;
  }

 private:
  std::string name_;
  std::unique_ptr<StreamLink> stream_;
};

int OpenSerial(const std::string& dev) {
  int fd = ::open(dev.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return -1;
  if (::isatty(fd)) {
    termios t{};
    if (tcgetattr(fd, &t) == 0) {
      cfmakeraw(&t);
      cfsetispeed(&t, B115200);
      cfsetospeed(&t, B115200);
      t.c_cflag |= CLOCAL | CREAD;
      tcsetattr(fd, TCSANOW, &t);
    }
  }
  return fd;
}

}  // namespace

std::unique_ptr<Channel> MakeIpChannel(const ChannelConfig& c, const ChannelOptions& o, Channel::ReceiveFn rx) {
  return std::make_unique<IpChannel>(c, o, std::move(rx));
}

std::unique_ptr<Channel> MakeSerialChannel(const ChannelConfig& c, const ChannelOptions& o, Channel::ReceiveFn rx) {
  std::string dev = c.device;
  auto ch = std::make_unique<StreamChannel>(
      std::string(c.mode == ChannelMode::LINK ? "ser link " : "ser bridge ") + dev, o,
      [dev](const std::atomic<bool>&) { return OpenSerial(dev); }, std::move(rx), /*lossy=*/true);
  ch->mode = c.mode;
  ch->level = c.level;
  return ch;
}

std::unique_ptr<Channel> MakeDialledTcpChannel(const std::string& addr, int port, const ChannelOptions& o,
                                               Channel::ReceiveFn rx) {
  auto used = std::make_shared<bool>(false);
  auto ch = std::make_unique<StreamChannel>(
      "finder -> " + addr + ":" + std::to_string(port), o,
      [addr, port, used](const std::atomic<bool>&) {
        if (*used) return kGiveUp;
        *used = true;
        int fd = net::TcpConnect("", addr, port, 500);
        return fd < 0 ? kGiveUp : fd;
      },
      std::move(rx), /*lossy=*/false);
  return ch;
}

std::unique_ptr<Channel> MakeAcceptedTcpChannel(int fd, const ChannelOptions& o, Channel::ReceiveFn rx) {
  auto used = std::make_shared<bool>(false);
  return std::make_unique<StreamChannel>(
      "finder <- accepted", o,
      [fd, used](const std::atomic<bool>&) {
        if (*used) return kGiveUp;
        *used = true;
        return fd;
      },
      std::move(rx), /*lossy=*/false);
}

}  // namespace mrt::dcdt
