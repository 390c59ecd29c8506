// What the link implementations share (internal): the outbound queue, capped
// in bytes, and the per-link counters. See doc/protocol.md "Wire protocol" and
// doc/faults.md ("Guarantees under faults").
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>

#include "mrt_dcdt/channel.h"

namespace mrt::dcdt::link {

using Clock = std::chrono::steady_clock;
/// A ConnectFn's answer: end the link for good.
constexpr int kGiveUp = -2;

struct Counters {
  std::atomic<uint64_t> sent{0}, received{0}, resent{0}, dropped{0}, refused{0}, errors{0}, reconnects{0}, gaps{0};
  std::atomic<bool> connected{false};
  std::atomic<int> peer_agora{0};
  void fill(ChannelStats* s) const {
    s->sent += sent;
    s->received += received;
    s->resent += resent;
    s->dropped += dropped;
    s->refused += refused;
    s->errors += errors;
    s->reconnects += reconnects;
    s->gaps += gaps;
    s->connected = s->connected || connected;
    if (peer_agora) s->peer_agora = peer_agora;
  }
};

/// What a queued message costs against a link's cap (as a mailbox's).
inline size_t cost(const Msg& m) { return PostOffice::cost(m); }

/// A link's outbound queue with its size in cost() bytes. The cap covers
/// the queue plus what the link holds besides it (`held`: guaranteed
/// messages sent and not yet acknowledged). The caller holds the link's lock.
struct OutQueue {
  std::deque<MsgPtr> q;
  size_t bytes = 0;

  enum Result { kQueued, kQueuedFirst, kDropped, kRefused };
  /// Appends m if it fits under `cap`. To make room the oldest queued
  /// messages without the guaranteed warranty are dropped (counted in
  /// c.dropped). A guaranteed message that still does not fit is refused
  /// (counted in c.refused, kRefused: the sender is told); any other is
  /// dropped (counted, kDropped). kQueuedFirst: the queue was empty, the
  /// link's thread needs a wake-up.
  Result push(const MsgPtr& m, size_t held, size_t cap, Counters& c) {
    const size_t need = cost(*m);
    if (held + bytes + need > cap) {
      for (auto it = q.begin(); it != q.end() && held + bytes + need > cap;) {
        if ((*it)->delivery_warranty() == DCDT_DW_GUARANTEED) {
          ++it;
          continue;
        }
        bytes -= cost(**it);
        it = q.erase(it);
        ++c.dropped;
      }
    }
    if (held + bytes + need > cap) {
      if (m->delivery_warranty() == DCDT_DW_GUARANTEED) {
        ++c.refused;
        return kRefused;
      }
      ++c.dropped;
      return kDropped;
    }
    const bool first = q.empty();
    q.push_back(m);
    bytes += need;
    return first ? kQueuedFirst : kQueued;
  }
  MsgPtr pop() {
    MsgPtr m = std::move(q.front());
    q.pop_front();
    bytes -= cost(*m);
    return m;
  }
  bool empty() const { return q.empty(); }
  size_t size() const { return q.size(); }
};

}  // namespace mrt::dcdt::link
