#include "mrt_dcdt_bridge/bridge_member.h"

namespace mrt::dcdt {

// With DCDT -> ROS mappings the Member is message-driven (it sleeps until
// mail arrives). Without any (e.g. the referee box's bridge, which only
// shares /referee) a Member of period 0 would be free-running, calling
// do_your_job in a loop: one core busy for nothing (82 % of a core measured
// in the RoboCup bringup). share() runs in the ROS callbacks, so such a
// Member has nothing to do and wakes rarely.
BridgeMember::BridgeMember(Agora* agora, BridgeMapping mapping, Deliver deliver)
    : Member(agora, mapping.to_ros.empty() ? kIdlePeriodMs : 0),
      mapping_(std::move(mapping)),
      deliver_(std::move(deliver)) {}

void BridgeMember::init() {
  for (const auto& m : mapping_.to_ros) subscribe_msg_type(m.type, m.scope);
}

void BridgeMember::do_your_job(int) {
  while (const Msg* msg = receive_msg()) {
    const TopicMapping* map = nullptr;
    for (const auto& m : mapping_.to_ros)
      if (m.type == msg->type()) map = &m;
    if (!map) {
      count_error("unmapped type " + std::to_string(msg->type()), BridgeError::DROPPED);
      continue;
    }
    bool delivered = false;
    if (map->kind == PayloadKind::RAW) {
      delivered = deliver_(*map, *msg, nullptr);
    } else {
      XmlMessage xml;
      try {
        xml = decode_xml(msg->payload_string());
      } catch (const XmlError& e) {
        count_error("type " + std::to_string(msg->type()) + " from agora " + std::to_string(msg->agora_id()) +
                       ": " + e.what(),
                   BridgeError::PARSE);
        continue;
      }
      delivered = deliver_(*map, *msg, &xml);
    }
    if (!delivered) continue;
    std::lock_guard<std::mutex> l(mutex_);
    ++stats_.in[msg->type()];
  }
  remove_curr_msg();
}

void BridgeMember::share(const TopicMapping& m, const std::string& payload) {
  if (payload.size() > kMaxPayload) {
    count_error("payload of " + m.topic + " larger than " + std::to_string(kMaxPayload) + " bytes",
               BridgeError::DROPPED);
    return;
  }
  Msg* msg = create_msg(m.type, m.warranty);
  msg->set_payload(payload);
  share_msg(msg);
  std::lock_guard<std::mutex> l(mutex_);
  ++stats_.out[m.type];
}

void BridgeMember::count_error(const std::string& what, BridgeError kind) {
  std::lock_guard<std::mutex> l(mutex_);
  switch (kind) {
    case BridgeError::PARSE: ++stats_.parse_errors; break;
    case BridgeError::CONVERSION: ++stats_.conversion_errors; break;
    case BridgeError::DROPPED: ++stats_.dropped; break;
  }
  stats_.last_error = what;
}

BridgeStats BridgeMember::stats() {
  std::lock_guard<std::mutex> l(mutex_);
  return stats_;
}

}  // namespace mrt::dcdt
