#include "mrt_dcdt_bridge/bridge_member.h"

namespace mrt::dcdt {

BridgeMember::BridgeMember(Agora* agora, BridgeMapping mapping, Deliver deliver)
    : Member(agora), mapping_(std::move(mapping)), deliver_(std::move(deliver)) {}

void BridgeMember::Init() {
  for (const auto& m : mapping_.to_ros) SubscribeMsgType(m.type, m.scope);
}

void BridgeMember::DoYourJob(int) {
  while (Msg* msg = ReceiveMsg()) {
    const TopicMapping* map = nullptr;
    for (const auto& m : mapping_.to_ros)
      if (m.type == msg->ReadType()) map = &m;
    if (!map) {
      CountError("unmapped type " + std::to_string(msg->ReadType()), BridgeError::DROPPED);
      continue;
    }
    bool delivered = false;
    if (map->kind == PayloadKind::RAW) {
      delivered = deliver_(*map, *msg, nullptr);
    } else {
      XmlMessage xml;
      try {
        xml = DecodeXml(msg->PayloadString());
      } catch (const XmlError& e) {
        CountError("type " + std::to_string(msg->ReadType()) + " from agora " + std::to_string(msg->ReadAgoraID()) +
                       ": " + e.what(),
                   BridgeError::PARSE);
        continue;
      }
      delivered = deliver_(*map, *msg, &xml);
    }
    if (!delivered) continue;
    std::lock_guard<std::mutex> l(mutex_);
    ++stats_.in[msg->ReadType()];
  }
  RemoveCurrMsg();
}

void BridgeMember::Share(const TopicMapping& m, const std::string& payload) {
  if (payload.size() > kMaxPayload) {
    CountError("payload of " + m.topic + " larger than " + std::to_string(kMaxPayload) + " bytes",
               BridgeError::DROPPED);
    return;
  }
  Msg* msg = CreateMsg(m.type, m.warranty);
  msg->SetPayload(payload);
  ShareMsg(msg);
  std::lock_guard<std::mutex> l(mutex_);
  ++stats_.out[m.type];
}

void BridgeMember::CountError(const std::string& what, BridgeError kind) {
  std::lock_guard<std::mutex> l(mutex_);
  switch (kind) {
    case BridgeError::PARSE: ++stats_.parse_errors; break;
    case BridgeError::CONVERSION: ++stats_.conversion_errors; break;
    case BridgeError::DROPPED: ++stats_.dropped; break;
  }
  stats_.last_error = what;
}

BridgeStats BridgeMember::Stats() {
  std::lock_guard<std::mutex> l(mutex_);
  return stats_;
}

}  // namespace mrt::dcdt
