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
      CountError("unmapped type " + std::to_string(msg->ReadType()), false);
      continue;
    }
    if (map->kind == PayloadKind::RAW) {
      deliver_(*map, *msg, nullptr);
    } else {
      XmlMessage xml;
      try {
        xml = DecodeXml(msg->PayloadString());
      } catch (const XmlError& e) {
        CountError("type " + std::to_string(msg->ReadType()) + " from agora " + std::to_string(msg->ReadAgoraID()) +
                       ": " + e.what(),
                   true);
        continue;
      }
      deliver_(*map, *msg, &xml);
    }
    std::lock_guard<std::mutex> l(mutex_);
    ++stats_.in[msg->ReadType()];
  }
  RemoveCurrMsg();
}

void BridgeMember::Share(const TopicMapping& m, const std::string& payload) {
  if (payload.size() > kMaxPayload) {
    CountError("payload of " + m.topic + " larger than " + std::to_string(kMaxPayload) + " bytes", false);
    return;
  }
  Msg* msg = CreateMsg(m.type, m.warranty);
  msg->SetPayload(payload);
  ShareMsg(msg);
  std::lock_guard<std::mutex> l(mutex_);
  ++stats_.out[m.type];
}

void BridgeMember::CountError(const std::string& what, bool parse_error) {
  std::lock_guard<std::mutex> l(mutex_);
  if (parse_error) ++stats_.parse_errors;
  else ++stats_.dropped;
  stats_.last_error = what;
}

BridgeStats BridgeMember::Stats() {
  std::lock_guard<std::mutex> l(mutex_);
  return stats_;
}

}  // namespace mrt::dcdt
