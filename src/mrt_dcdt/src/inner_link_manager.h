// InnerLinkManager (manual §3.1): the Agoras of one machine reach each other
// through Unix datagram sockets `<dir>/<agora id>.sock` (internal header).
//
// Each local peer has its own connected, non-blocking socket and its own
// queue, bounded in bytes: a publisher never blocks on a peer, a message is
// cut into fragments that fit any socket buffer (reassembled by the
// receiver), and a peer that stops reading is dropped from delivery when its
// queue is full (counted in dropped(), listed by stalled_peers()) until it
// has read everything queued for it.
#pragma once

#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "mrt_dcdt/msg.h"
#include "net_util.h"

namespace mrt::dcdt {

struct InnerLinkOptions {
  std::string dir;
  int agora_id = 0;
  uint64_t incarnation = 0;
  int socket_buffer = 4 << 20;        ///< SO_SNDBUF / SO_RCVBUF asked for (bytes)
  size_t queue_bytes = 8u << 20;      ///< per peer
};

/// Fragment header of an inner-link datagram (doc/protocol.md "Inner links").
constexpr size_t kInnerFragmentHeader = 32;
constexpr size_t kInnerFragmentData = 60 * 1024;

/// Refuses (std::runtime_error naming it) a directory that is not a real
/// directory owned by this user and closed to group and others for writing;
/// creates it (0700) when missing.
void check_inner_dir(const std::string& dir);

class InnerLinkManager {
 public:
  using ReceiveFn = std::function<void(std::shared_ptr<Msg>)>;
  InnerLinkManager(InnerLinkOptions options, ReceiveFn rx);
  ~InnerLinkManager();
  /// Checks the directory (throws std::runtime_error), binds, starts the thread.
  void start();
  void stop();
  /// Queues msg for every other Agora of the directory; never blocks.
  void send(const Msg& msg);
  int peers();
  /// Agora ids of the peers (from their socket names).
  std::vector<int> peer_ids();
  uint64_t errors() const { return errors_; }
  /// Messages not delivered to a peer because its queue was full.
  uint64_t dropped() const { return dropped_; }
  /// Peers currently dropped from delivery.
  std::vector<int> stalled_peers();

 private:
  using Datagrams = std::vector<std::vector<uint8_t>>;
  struct Peer {
    std::string path;
    int id = 0;
    int fd = -1;
    std::deque<std::shared_ptr<const Datagrams>> queue;  // whole messages
    size_t next_fragment = 0;  // of queue.front()
    size_t bytes = 0;
    bool stalled = false;
    bool dead = false;
    ~Peer();
  };
  struct Partial {
    uint64_t number = 0;
    uint32_t next = 0, count = 0;
    std::vector<uint8_t> bytes;
  };

  void loop();
  void refresh_peers(bool force);
  bool connect_peer(Peer& p);
  /// Sends what it can of p's queue without blocking. Caller holds mutex_.
  void flush_locked(Peer& p);
  void receive_datagram(const uint8_t* data, size_t len);
  void deliver(const uint8_t* data, size_t len);

  InnerLinkOptions options_;
  std::string path_;
  ReceiveFn rx_;
  int fd_ = -1;
  std::atomic<bool> stop_{false};
  std::atomic<uint64_t> errors_{0}, dropped_{0};
  net::Waker waker_;
  std::thread thread_;
  std::mutex mutex_;  // peers_, numbering
  std::map<std::string, std::shared_ptr<Peer>> peers_;
  int64_t peers_time_ = 0;
  uint64_t next_number_ = 0;
  std::map<std::pair<int, uint64_t>, Partial> partials_;  // by sender (agora id, incarnation); receive thread only
};

}  // namespace mrt::dcdt
