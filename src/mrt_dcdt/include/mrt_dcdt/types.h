// Basic DCDT vocabulary (manual §3.2, §3.3): request scopes, delivery
// warranties, the legacy MRT message type numbers. ROS-free.
#pragma once

#include <cstdint>

namespace mrt::dcdt {

/// Subscription scope (manual §3.3.2). A bit mask: ALL = LOCAL | REMOTE.
enum RequestType : int {
  DCDT_LOCAL_MSG = 1,   ///< produced on this machine or received through a `bridge` channel
  DCDT_REMOTE_MSG = 2,  ///< received through a `link` channel
  DCDT_ALL_MSG = 3,
};

/// Delivery warranty of a message (manual §3.2), chosen in create_msg.
enum DeliveryWarranty : int {
  DCDT_DW_NONE = 0,        ///< UDP datagram, sent once
  DCDT_DW_RETRANSMIT = 1,  ///< UDP datagram, acknowledged, retransmitted a bounded number of times
  DCDT_DW_GUARANTEED = 2,  ///< TCP stream, acknowledged end to end, resent after a reconnection
};

/// Nanoseconds since the Unix epoch (system clock) at which a message was created.
using DCDT_TIME = int64_t;

/// Now, as a DCDT_TIME.
DCDT_TIME now_ns();

/// The legacy MRT message type numbers (kept unchanged on the wire).
enum MrtMsgType : int {
  MSG_FROM_VISION = 18,
  MSG_FROM_VISION_OMNIDIR = 19,
  MSG_FROM_VISION_FRONTAL = 20,
  MSG_FROM_MOTION = 21,
  MSG_FROM_MONITOR = 22,
  MSG_FROM_MAP = 23,
  MSG_FROM_SCARE = 24,
  MSG_FROM_BRIAN = 25,
  MSG_FROM_ANCHORER = 27,
  MSG_FROM_REFBOX = 28,
  MSG_TO_BRIAN = 31,
  MSG_TO_MOTION = 32,
  MSG_TO_ANCHORER = 34,
  MSG_FROM_JOYPAD_BRIEF = 43,
  MSG_FROM_SONAR_QUALITY = 44,
};

/// The legacy name of a type number ("MSG_FROM_VISION"), or "" when unknown.
const char* msg_type_name(int type);
/// The number of a legacy name or of a decimal string; -1 when neither.
int msg_type_from_name(const char* name);

/// Hard limits (untrusted input): payload bytes and hops a message may travel.
constexpr uint32_t kMaxPayload = 1u << 20;
constexpr int kMaxHops = 15;

}  // namespace mrt::dcdt
