// Agora (the manual's DCDT_Agora, §3.1, §3.3.1; its legacy names are in
// dcdt.h): hosts Members, owns the PostOffice and, as system Members, the
// InnerLinkManager, the channels and the Finder.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <unordered_set>
#include <vector>

#include "mrt_dcdt/channel.h"
#include "mrt_dcdt/config.h"
#include "mrt_dcdt/member.h"
#include "mrt_dcdt/post_office.h"

namespace mrt::dcdt {

class InnerLinkManager;
class Finder;

struct AgoraOptions {
  bool network = false;         ///< NETWORK (channels, Finder) or STANDALONE
  AgoraConfig config;           ///< NETWORK only (STANDALONE uses policy only)
  std::string inner_dir;        ///< "" = $DCDT_INNER_DIR, else /tmp/dcdt-<uid>
  bool inner_links = true;      ///< talk to the other Agoras of this machine
  bool finder = true;           ///< NETWORK: discover Agoras by multicast
  int finder_period_ms = 200;
  int finder_tcp_port = 0;        ///< the Finder's TCP listening port (0 = any free one)
  int finder_announce_port = 0;   ///< the port announced in beacons (0 = the listening one; else e.g. a forwarded port)
  int finder_forget_ms = 10000;   ///< a Finder peer unheard of this long and not connected is forgotten, with what was owed to it
  int agora_id = 0;             ///< 0 = random
  int inner_socket_buffer = 4 << 20;  ///< SO_SNDBUF/SO_RCVBUF asked for the inner-link socket (bytes)
  size_t inner_queue_bytes = 8u << 20;  ///< per local peer: bytes waiting for a slow Agora before it is dropped from delivery
  ChannelOptions channel;
};

struct AgoraStats {
  uint64_t routed = 0;
  uint64_t duplicates = 0;       ///< copies recognised by origin (agora id, incarnation, seq) and dropped
  uint64_t hop_limited = 0;      ///< dropped after more than kMaxHops channels
  uint64_t inner_errors = 0;     ///< malformed or undeliverable inner-link datagrams
  uint64_t mailbox_dropped = 0;  ///< non-guaranteed messages discarded because a Member's mailbox was full
  uint64_t guaranteed_refused = 0;  ///< guaranteed messages a full mailbox refused (the sender was told under SLWB)
  uint64_t inner_dropped = 0;    ///< messages not delivered to a stalled local Agora (its queue was full)
  std::vector<int> inner_stalled_peers;  ///< local Agoras currently dropped from delivery
  uint64_t channel_refused = 0;  ///< guaranteed messages a full channel out-queue refused (route/share_msg returned false)
  uint64_t channels_lost = 0;    ///< messages still queued or unacknowledged on Finder channels of forgotten peers
  int inner_peers = 0;
  int finder_peers = 0;
  std::vector<int> peer_ids;  ///< Agoras seen: inner-link peers, Finder peers, channel peers (sorted, unique)
  std::vector<ChannelStats> channels;
};

/// Where a message entered this Agora.
struct Source {
  enum Kind { MEMBER, INNER, CHANNEL } kind = MEMBER;
  Channel* channel = nullptr;
};

class Agora {
 public:
  /// STANDALONE Agora.
  Agora();
  /// NETWORK Agora configured by a file (throws mrt::common::ParseError).
  explicit Agora(const char* config_file);
  explicit Agora(const std::string& config_file);
  explicit Agora(AgoraOptions options);
  ~Agora();
  Agora(const Agora&) = delete;
  Agora& operator=(const Agora&) = delete;

  void add_member(Member* m);
  /// Creates the Member's thread; it starts working in lets_work (or at once
  /// if lets_work is already running).
  void activate_member(Member* m);
  /// Runs the active Members; returns when all are TERMINATING/TERMINATED or
  /// one called shutdown(). Members are joined and close()d before returning.
  void lets_work();
  void shutdown();
  /// Installs a handler for signum that stops every running Agora of the
  /// process (async-signal-safe: it only sets a flag that lets_work polls).
  static void shutdown_on_signal(int signum);

  int agora_id() const { return agora_id_; }
  /// Random, non-zero, new in every process: tells a restarted Agora with a
  /// fixed id from its previous run (wire: MSG origin, HELLO).
  uint64_t incarnation() const { return incarnation_; }
  bool is_network() const { return options_.network; }
  PostOffice& post_office() { return *post_office_; }
  AgoraStats stats();
  const AgoraOptions& options() const { return options_; }

  // --- used by Members and system Members ---
  /// False when a guaranteed message was refused by a full local mailbox
  /// (SLWB) or by a full channel out-queue; it went to every other destination.
  bool route(std::shared_ptr<Msg> msg, const Source& src);
  int next_member_id() { return ++member_counter_; }
  uint64_t next_seq() { return ++seq_counter_; }
  void add_channel(std::unique_ptr<Channel> c);
  /// True when a live channel is connected to Agora `id`.
  bool has_connected_peer(int id);
  void notify_state_change();

 private:
  friend class Member;
  /// A Member's destructor: stops its thread if still running (no virtual
  /// call), waits for its joiner, leaves the Agora.
  void detach_member(Member* m);
  /// Member::terminate.
  void terminate_member(Member* m);
  /// Joins every started Member thread exactly once, never under the lock.
  void join_members();
  /// Caller holds members_mutex_.
  void start_thread_locked(Member* m);
  void setup();
  void stop_network();
  bool seen_before(const MsgHeader& h);

  AgoraOptions options_;
  int agora_id_ = 0;
  uint64_t incarnation_ = 0;
  std::unique_ptr<PostOffice> post_office_;
  std::atomic<int> member_counter_{0};
  std::atomic<uint64_t> seq_counter_{0};

  std::mutex members_mutex_;
  std::condition_variable members_cv_;
  std::vector<Member*> members_;
  bool running_ = false;
  std::atomic<bool> stop_{false};  // read by the Member threads
  std::atomic<bool> shutdown_{false};
  unsigned signal_base_ = 0;  // signals counted by shutdown_on_signal's handler at construction

  std::mutex seen_mutex_;
  struct Origin {
    int32_t agora;
    uint64_t incarnation, seq;
    bool operator==(const Origin& o) const { return agora == o.agora && incarnation == o.incarnation && seq == o.seq; }
  };
  struct OriginHash {
    size_t operator()(const Origin& o) const {
      return std::hash<uint64_t>()(o.seq * 0x9E3779B97F4A7C15ull ^ o.incarnation ^ static_cast<uint32_t>(o.agora));
    }
  };
  std::unordered_set<Origin, OriginHash> seen_;
  std::deque<Origin> seen_order_;

  std::mutex channels_mutex_;
  std::vector<std::unique_ptr<Channel>> channels_;
  std::unique_ptr<InnerLinkManager> inner_;
  std::unique_ptr<Finder> finder_;
  std::atomic<uint64_t> routed_{0}, duplicates_{0}, hop_limited_{0}, channel_refused_{0}, channels_lost_{0};
};

}  // namespace mrt::dcdt
