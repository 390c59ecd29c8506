// What the link implementations share (internal): the outbound queue bound
// and the per-link counters. See README "Wire protocol".
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
constexpr size_t kMaxOutQueue = 200000;

/// Appends to a link's outbound queue, dropping (and counting) the oldest
/// message when it is full. Returns whether the queue was empty, i.e. whether
/// the link's thread needs a wake-up. The caller holds the queue's lock.
inline bool push_bounded(std::deque<MsgPtr>& q, const MsgPtr& m, std::atomic<uint64_t>& dropped) {
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
  void fill(ChannelStats* s) const {
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

}  // namespace mrt::dcdt::link
