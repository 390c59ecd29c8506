// The bridge's DCDT side (ROS-free): a message-driven Member that receives
// the mapped DCDT types, decodes their XML payloads and hands them to a
// callback (the ROS node publishes them), and shares messages coming from
// ROS. Counts traffic per type, parse errors and drops for diagnostics.
#pragma once

#include <functional>
#include <map>
#include <mutex>
#include <string>

#include "mrt_dcdt_bridge/bridge_mapping.h"
#include "mrt_dcdt/member.h"
#include "mrt_dcdt/xml_message.h"

namespace mrt::dcdt {

struct BridgeStats {
  std::map<int, uint64_t> in;   ///< DCDT -> ROS, per type: messages actually delivered
  std::map<int, uint64_t> out;  ///< ROS -> DCDT, per type
  uint64_t parse_errors = 0;       ///< payloads that are not valid MRT XML
  uint64_t conversion_errors = 0;  ///< valid XML or ROS messages that did not fit the mapped kind
  uint64_t dropped = 0;            ///< unmapped types, oversize payloads
  std::string last_error;
};

enum class BridgeError { PARSE, CONVERSION, DROPPED };

class BridgeMember : public Member {
 public:
  /// xml is null for PayloadKind::RAW. Returns whether the message was
  /// delivered (false: it could not be converted, and the callback has
  /// counted it with count_error).
  using Deliver = std::function<bool(const TopicMapping& m, const Msg& msg, const XmlMessage* xml)>;

  /// Period of a Member with no DCDT -> ROS mapping (it receives nothing).
  static constexpr int kIdlePeriodMs = 100;

  BridgeMember(Agora* agora, BridgeMapping mapping, Deliver deliver);
  void init() override;
  void do_your_job(int pending) override;

  /// ROS -> DCDT: shares payload as message type m.type (thread-safe).
  void share(const TopicMapping& m, const std::string& payload);
  /// Records a message that could not be converted (counted, not shared).
  void count_error(const std::string& what, BridgeError kind);

  BridgeStats stats();
  const BridgeMapping& mapping() const { return mapping_; }

 private:
  BridgeMapping mapping_;
  Deliver deliver_;
  std::mutex mutex_;
  BridgeStats stats_;
};

}  // namespace mrt::dcdt
