// Channel implementations (manual's LinkRx / LinkTx): `ip` channels (a
// StreamLink over TCP for guaranteed messages and big ones, a UdpLink for the
// rest) and stream channels (serial lines, Finder connections). The links
// themselves are in stream_link.cpp and udp_link.cpp. See doc/protocol.md "Wire protocol".
#include <arpa/inet.h>
#include <unistd.h>

#include "finder.h"
#include "mrt_common/serial_port.h"
#include "mrt_dcdt/channel.h"
#include "stream_link.h"
#include "udp_link.h"

namespace mrt::dcdt {

namespace {

using link::kGiveUp;
using link::StreamLink;
using link::UdpLink;
constexpr size_t kMaxUdpFrame = 60000;

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
      fn = [this](const std::atomic<bool>&, std::vector<uint8_t>*) {
        return net::tcp_connect(cfg_.local_addr, cfg_.remote_addr, cfg_.remote_port, 200);
      };
    } else {
      fn = [this](const std::atomic<bool>&, std::vector<uint8_t>*) {
        if (listen_fd_ < 0) listen_fd_ = net::tcp_listen(cfg_.local_addr, cfg_.local_port);
        if (listen_fd_ < 0) return -1;
        sockaddr_in peer{};
        int fd = net::tcp_accept(listen_fd_, 100, &peer);
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
  ~IpChannel() override { stop(); }
  void start() override {
    stream_->start();
    udp_->start();
  }
  void stop() override {
    stream_->stop();
    udp_->stop();
    if (listen_fd_ >= 0) ::close(listen_fd_);
    listen_fd_ = -1;
  }
  bool send(const MsgPtr& m) override {
    if (m->delivery_warranty() == DCDT_DW_GUARANTEED ||
        static_cast<size_t>(m->payload_len()) + kMsgBodyFixed + kFrameOverhead > kMaxUdpFrame)
      return stream_->send(m);  // too big for a datagram: the stream carries it
    udp_->send(m);
    return true;
  }
  ChannelStats stats() const override {
    ChannelStats s;
    s.name = std::string(mode == ChannelMode::LINK ? "ip link " : "ip bridge ") + cfg_.local_addr + ":" +
             std::to_string(cfg_.local_port) + " -> " + cfg_.remote_addr + ":" + std::to_string(cfg_.remote_port);
    stream_->c.fill(&s);
    udp_->c.fill(&s);
    s.connected = stream_->c.connected;
    s.pending = stream_->pending() + udp_->pending();
    return s;
  }

 private:
  static in_addr_t Addr(const std::string& ip) {
    sockaddr_in a;
    net::make_addr(ip, 0, &a);
    return a.sin_addr.s_addr;
  }
  ChannelConfig cfg_;
  int listen_fd_ = -1;
  std::unique_ptr<StreamLink> stream_;
  std::unique_ptr<UdpLink> udp_;
};

class StreamChannel : public Channel {
 public:
  StreamChannel(std::string name, const ChannelOptions& o, StreamLink::ConnectFn fn, ReceiveFn rx, bool lossy,
                StreamLink::ReplacedFn replaced = nullptr)
      : name_(std::move(name)) {
    stream_ = std::make_unique<StreamLink>(o, std::move(fn), this, std::move(rx), lossy, std::move(replaced));
  }
  ~StreamChannel() override { stop(); }
  void start() override { stream_->start(); }
  void stop() override { stream_->stop(); }
  bool send(const MsgPtr& m) override { return stream_->send(m); }
  bool dead() const override { return stream_->dead(); }
  ChannelStats stats() const override {
    ChannelStats s;
    s.name = name_;
    stream_->c.fill(&s);
    s.pending = stream_->pending();
    return s;
  }

 private:
  std::string name_;
  std::unique_ptr<StreamLink> stream_;
};

// The stack's serial port (shared with the AIRBoard driver), opened
// blocking at 115200 8N1 and handed to the stream link, which owns the
// descriptor from then on. A device that is not a terminal is used as it is;
// -1 when it cannot be opened (the link retries).
int open_serial(const std::string& dev) {
  mrt::common::SerialOptions o;
  o.baud = 115200;
  o.non_blocking = false;
  o.require_tty = false;
  o.flush_input = false;
  try {
    mrt::common::SerialPort port;
    port.open(dev, o);
    return port.release();
  } catch (const mrt::common::SerialError&) {
    return -1;
  }
}

}  // namespace

std::unique_ptr<Channel> make_ip_channel(const ChannelConfig& c, const ChannelOptions& o, Channel::ReceiveFn rx) {
  return std::make_unique<IpChannel>(c, o, std::move(rx));
}

std::unique_ptr<Channel> make_serial_channel(const ChannelConfig& c, const ChannelOptions& o, Channel::ReceiveFn rx) {
  std::string dev = c.device;
  auto ch = std::make_unique<StreamChannel>(
      std::string(c.mode == ChannelMode::LINK ? "ser link " : "ser bridge ") + dev, o,
      [dev](const std::atomic<bool>&, std::vector<uint8_t>*) { return open_serial(dev); }, std::move(rx), /*lossy=*/true);
  ch->mode = c.mode;
  ch->level = c.level;
  return ch;
}

std::unique_ptr<Channel> make_finder_channel(const std::string& name, bool dialling,
                                             std::shared_ptr<FinderSlot> slot, const ChannelOptions& o,
                                             Channel::ReceiveFn rx) {
  StreamLink::ConnectFn connect;
  StreamLink::ReplacedFn replaced;
  if (dialling) {
    connect = [slot](const std::atomic<bool>&, std::vector<uint8_t>*) {
      if (slot->forget) return kGiveUp;
      std::string addr;
      int port;
      {
        std::lock_guard<std::mutex> l(slot->mu);
        if (!slot->dial) return -1;  // waits for the Finder to hear the peer again
        slot->dial = false;
        addr = slot->addr;
        port = slot->port;
      }
      return net::tcp_connect("", addr, port, 500);
    };
    replaced = [slot] { return slot->forget.load(); };
  } else {
    connect = [slot](const std::atomic<bool>&, std::vector<uint8_t>* prefix) {
      if (slot->forget) return kGiveUp;
      std::lock_guard<std::mutex> l(slot->mu);
      const int fd = slot->fd;
      if (fd < 0) return -1;  // waits for the Finder to accept the peer's next connection
      slot->fd = -1;
      slot->fd_waiting = false;
      prefix->swap(slot->prefix);
      slot->prefix.clear();
      return fd;
    };
    // A new connection from the same peer replaces one that went silent.
    replaced = [slot] { return slot->fd_waiting.load() || slot->forget.load(); };
  }
  auto ch = std::make_unique<StreamChannel>(
      name, o,
      std::move(connect), std::move(rx), /*lossy=*/false, std::move(replaced));
  return ch;
}

}  // namespace mrt::dcdt
