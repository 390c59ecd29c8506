// Communication channels between Agoras (manual §3.3.1): `ip` channels (a TCP
// stream for guaranteed messages, UDP datagrams for the other warranties) and
// `ser` channels (the same frames over an RS-232 byte stream). Each channel
// runs its own receiving/sending threads (the manual's LinkRx / LinkTx).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "mrt_dcdt/config.h"
#include "mrt_dcdt/post_office.h"

namespace mrt::dcdt {

struct ChannelStats {
  std::string name;
  bool connected = false;
  int peer_agora = 0;
  uint64_t sent = 0, received = 0, resent = 0, errors = 0, reconnects = 0;
  uint64_t dropped = 0;  ///< messages without the guaranteed warranty dropped from a full out-queue
  uint64_t refused = 0;  ///< guaranteed messages refused by a full out-queue (the sender was told)
  uint64_t gaps = 0;     ///< guaranteed frames discarded after a lost one (then resent)
  uint64_t pending = 0;  ///< queued or sent-but-unacknowledged messages
};

class Channel {
 public:
  /// Called from the channel's thread for every message received.
  using ReceiveFn = std::function<void(std::shared_ptr<Msg>, Channel*)>;
  virtual ~Channel() = default;
  virtual void start() = 0;
  virtual void stop() = 0;
  /// Queues a message for sending; never blocks on the network. False when
  /// a guaranteed message was refused: the channel holds
  /// ChannelOptions::max_queue_bytes already (then it is counted in
  /// `refused`). A message without that warranty is never refused: the
  /// oldest of them are dropped instead (counted in `dropped`).
  virtual bool send(const MsgPtr& msg) = 0;
  virtual ChannelStats stats() const = 0;
  /// A dynamic (Finder) channel whose connection ended; the Agora drops it.
  virtual bool dead() const { return false; }

  ChannelMode mode = ChannelMode::LINK;
  int level = 0;
};

/// Options shared by the channel implementations.
struct ChannelOptions {
  int agora_id = 0;
  uint64_t incarnation = 0;         ///< this Agora's run (HELLO); set by the Agora
  int retransmit_interval_ms = 20;  ///< DCDT_DW_RETRANSMIT
  int retransmit_tries = 5;
  size_t max_unacked = 200000;      ///< DCDT_DW_GUARANTEED messages in flight (window, messages)
  size_t max_queue_bytes = 64u << 20;  ///< per link: queued + unacknowledged messages, in PostOffice::cost bytes
  int reconnect_ms = 50;
  int stream_resend_ms = 300;       ///< guaranteed on a stream: resend the unacknowledged after this long without an ACK
};

std::unique_ptr<Channel> make_ip_channel(const ChannelConfig& c, const ChannelOptions& o, Channel::ReceiveFn rx);
std::unique_ptr<Channel> make_serial_channel(const ChannelConfig& c, const ChannelOptions& o, Channel::ReceiveFn rx);

}  // namespace mrt::dcdt
