// StreamLink (internal): a TCP or serial byte stream carrying DCDT frames,
// with acknowledged, resendable guaranteed messages.
//
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
// Guaranteed MSG frames are accepted only once the peer has named our
// incarnation (frames left in a line's buffers by an earlier run are not
// taken for ours). A link holds at most max_queue_bytes of queued and
// unacknowledged messages; a guaranteed message beyond that is refused.
#pragma once

#include <atomic>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "link_common.h"
#include "mrt_dcdt/frame.h"
#include "net_util.h"

namespace mrt::dcdt::link {

class StreamLink {
 public:
  /// Returns a connected fd, -1 to retry later, kGiveUp to end for good.
  /// Bytes already read from the fd (an accepted connection whose HELLO the
  /// Finder read to learn the peer) go to *prefix; the session handles them first.
  using ConnectFn = std::function<int(const std::atomic<bool>& stop, std::vector<uint8_t>* prefix)>;
  /// Asked every poll round (<= 50 ms): true ends the current session so
  /// that the next connection (already waiting) replaces it.
  using ReplacedFn = std::function<bool()>;

  StreamLink(ChannelOptions o, ConnectFn connect, Channel* owner, Channel::ReceiveFn rx, bool lossy,
             ReplacedFn replaced = nullptr)
      : o_(o), connect_(std::move(connect)), replaced_(std::move(replaced)), owner_(owner), rx_(std::move(rx)),
        lossy_(lossy) {}
  ~StreamLink() { stop(); }

  void start() { thread_ = std::thread([this] { loop(); }); }
  void stop();
  /// Queues a message; never blocks on the network. False: a guaranteed
  /// message refused because the link holds max_queue_bytes (Channel::send).
  bool send(const MsgPtr& m);
  bool dead() const { return dead_; }
  uint64_t pending() const;
  Counters c;

 private:
  struct Unacked {
    uint64_t seq;
    MsgPtr msg;
    std::vector<uint8_t> bytes;
  };
  /// What one connection (session) keeps between its poll rounds.
  struct SessionState {
    FrameDecoder dec;
    bool peer_ready = false;
    bool send_ack = false;
    Clock::time_point last_hello = Clock::now() - std::chrono::seconds(10);
    Clock::time_point nack_at = Clock::now() - std::chrono::seconds(10);
    uint64_t nack_for = ~0ull;
    uint64_t counted_errors = 0;  ///< dec.errors() already added to c.errors
    std::vector<uint8_t> wbuf;
  };

  void loop();
  void sleep(int ms);
  /// One connection: returns when it ends (EOF, error, stop).
  void session(int fd, const std::vector<uint8_t>& prefix);
  /// Feeds received bytes to the decoder and handles the frames.
  void handle_bytes(const uint8_t* data, size_t n, SessionState& s);
  enum class ReadResult { kEnded, kRetry, kDone };
  /// Reads what the peer sent and handles its frames: kEnded when the
  /// connection ended, kRetry when the read was interrupted.
  ReadResult read_frames(int fd, std::vector<uint8_t>& rbuf, SessionState& s);
  void on_frame(const Frame& f, SessionState& s);
  void on_msg(MsgFrame mf, SessionState& s);
  void on_hello(const Hello& h, bool* ready, std::vector<uint8_t>& wbuf);
  /// Resends what stays unacknowledged and moves queued messages into wbuf
  /// within the window.
  void fill_outbound(std::vector<uint8_t>& wbuf);
  std::vector<uint8_t> my_hello(bool reply) const;
  // Removes what the peer acknowledged (cumulative). Caller holds mu_.
  void ack_up_to(uint64_t s);
  // Appends every unacknowledged frame (go-back-N). Caller holds mu_.
  void resend_all(std::vector<uint8_t>& wbuf);

  ChannelOptions o_;
  ConnectFn connect_;
  ReplacedFn replaced_;
  Channel* owner_;
  Channel::ReceiveFn rx_;
  bool lossy_;  ///< serial: frames can be lost without the connection dropping
  std::atomic<bool> stop_{false}, dead_{false};
  net::Waker waker_;
  std::thread thread_;
  mutable std::mutex mu_;
  OutQueue outq_;
  std::deque<Unacked> unacked_;
  size_t unacked_bytes_ = 0;  ///< cost() of unacked_, counted against max_queue_bytes
  Clock::time_point front_since_ = Clock::now();
  uint64_t next_seq_ = 1;
  uint64_t last_rx_ = 0;
  uint64_t peer_inc_ = 0;
};

}  // namespace mrt::dcdt::link
