// Finder (manual §3.1): announces this Agora by UDP multicast and keeps one
// TCP `link` channel to every Agora it hears of on another machine
// (internal). The channel of a peer lives as long as the peer is heard of:
// a connection that drops is dialled again (or accepted again and handed to
// the same channel), so the channel's link sequences, acknowledgements and
// resend buffer carry over and nothing guaranteed is lost or duplicated.
#pragma once

#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "mrt_dcdt/channel.h"
#include "mrt_dcdt/config.h"
#include "mrt_dcdt/frame.h"
#include "net_util.h"

namespace mrt::dcdt {

class Agora;

/// The connection slot of one Finder channel, shared by the Finder and the
/// channel's thread. Dialling side (our id is the smaller): the Finder sets
/// `dial` whenever it hears the peer while the channel is not connected.
/// Accepting side: the Finder hands over each connection whose HELLO names
/// the peer (fd, plus the bytes it read). `forget` ends the channel.
struct FinderSlot {
  std::mutex mu;
  std::string addr;
  int port = 0;
  bool dial = false;
  int fd = -1;
  std::vector<uint8_t> prefix;
  std::atomic<bool> fd_waiting{false};
  std::atomic<bool> forget{false};
  ~FinderSlot();
};

/// A Finder channel to a peer (mode LINK, level 0), named `name` in its stats.
std::unique_ptr<Channel> make_finder_channel(const std::string& name, bool dialling,
                                             std::shared_ptr<FinderSlot> slot, const ChannelOptions& o,
                                             Channel::ReceiveFn rx);

class Finder {
 public:
  Finder(Agora* agora, const AgoraConfig& cfg, const std::string& inner_dir, int period_ms);
  ~Finder();
  void start();
  void stop();
  /// Agoras heard from during the last 3 s.
  int peers();
  std::vector<int> peer_ids();

 private:
  using Clock = std::chrono::steady_clock;
  struct Link {
    std::shared_ptr<FinderSlot> slot;
    bool dialling = false;
    Clock::time_point seen;
  };
  /// An accepted connection whose first HELLO has not arrived yet.
  struct Accepted {
    int fd;
    FrameDecoder dec;
    std::vector<uint8_t> bytes;
    Clock::time_point deadline;
  };

  void loop();
  void on_beacon(const Beacon& b);
  /// Reads from an accepted connection; true when it is done with (handed
  /// over to its peer's channel, or closed).
  bool on_accepted_readable(Accepted& a);
  /// Caller holds mutex_. Creates the channel of `peer` if it has none.
  Link& link_of(int peer, bool dialling, const std::string& name);
  /// Ends the channels of peers not heard of for forget_ms and not connected.
  void forget_silent_peers();

  Agora* agora_;
  AgoraConfig cfg_;
  std::string host_key_;
  int period_ms_;
  int mcast_fd_ = -1, listen_fd_ = -1;
  std::atomic<bool> stop_{false};
  net::Waker waker_;
  std::thread thread_;
  std::mutex mutex_;
  std::map<int, Clock::time_point> seen_;
  std::map<int, Link> links_;
  std::vector<std::unique_ptr<Accepted>> accepted_;  // Finder thread only
  std::vector<std::unique_ptr<Channel>> new_channels_;  // created under mutex_, added to the Agora outside it
};

}  // namespace mrt::dcdt
