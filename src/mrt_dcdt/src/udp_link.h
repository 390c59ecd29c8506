// UdpLink (internal): DCDT frames in UDP datagrams to one configured peer,
// with acknowledged retransmission for DCDT_DW_RETRANSMIT messages.
#pragma once

#include <netinet/in.h>

#include <atomic>
#include <deque>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "link_common.h"
#include "mrt_dcdt/config.h"
#include "net_util.h"

namespace mrt::dcdt::link {

class UdpLink {
 public:
  UdpLink(const ChannelConfig& cfg, ChannelOptions o, Channel* owner, Channel::ReceiveFn rx)
      : cfg_(cfg), o_(o), owner_(owner), rx_(std::move(rx)) {}
  ~UdpLink() { stop(); }

  void start();
  void stop();
  /// Queues a message; never blocks on the network.
  void send(const MsgPtr& m);
  uint64_t pending() const;
  Counters c;

 private:
  struct Retx {
    std::vector<uint8_t> bytes;
    int tries;
    Clock::time_point due;
  };

  bool open();
  void send_to(const std::vector<uint8_t>& b);
  void loop();
  /// Reads up to 256 waiting datagrams: messages (acknowledged when they ask
  /// for it) and ACKs of our retransmitted ones.
  void receive(std::vector<uint8_t>& rbuf);
  void on_datagram(const uint8_t* data, size_t n, const sockaddr_in& from);
  void send_queued(Clock::time_point now);
  void retransmit(Clock::time_point now);

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
  OutQueue outq_;
  std::map<uint64_t, Retx> pending_;
  size_t pending_size_ = 0;
  uint64_t next_seq_ = 1;
};

}  // namespace mrt::dcdt::link
