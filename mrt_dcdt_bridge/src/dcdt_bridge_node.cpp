// dcdt_bridge_node: joins a DCDT community as an Agora and bridges the mapped
// DCDT message types to ROS topics and back (see README "Node API").
// Wiring only: the Agora and the BridgeMember are ROS-free.
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <diagnostic_msgs/DiagnosticArray.h>

#include <memory>
#include <thread>

#include "mrt_common/parse_error.h"
#include "mrt_dcdt_bridge/agora.h"
#include "mrt_dcdt_bridge/bridge_member.h"
#include "ros/conversions.h"

using namespace mrt::dcdt;

namespace {

struct NodeOptions {
  std::string agora_config;  // "" = STANDALONE
  std::string mapping;
  std::string inner_dir;
  std::string policy = "SLWB";
  int agora_id = 0;
  double diagnostics_period = 1.0;
  int queue_size = 100;
};

NodeOptions ReadOptions(ros::NodeHandle& pnh) {
  NodeOptions o;
  pnh.param("agora_config", o.agora_config, o.agora_config);
  if (!pnh.getParam("mapping", o.mapping) || o.mapping.empty())
    throw std::invalid_argument("parameter ~mapping (path of the YAML mapping file) is required");
  pnh.param("inner_dir", o.inner_dir, o.inner_dir);
  pnh.param("policy", o.policy, o.policy);
  pnh.param("agora_id", o.agora_id, o.agora_id);
  pnh.param("diagnostics_period", o.diagnostics_period, o.diagnostics_period);
  pnh.param("queue_size", o.queue_size, o.queue_size);
  if (o.diagnostics_period <= 0) throw std::invalid_argument("parameter ~diagnostics_period must be > 0");
  if (o.queue_size <= 0) throw std::invalid_argument("parameter ~queue_size must be > 0");
  if (o.agora_id < 0) throw std::invalid_argument("parameter ~agora_id must be >= 0");
  return o;
}

class BridgeNode {
 public:
  BridgeNode(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    const NodeOptions o = ReadOptions(pnh);
    AgoraOptions ao;
    if (!o.agora_config.empty()) {
      ao.network = true;
      ao.config = LoadAgoraConfig(o.agora_config);
    } else if (!ParsePolicy(o.policy, &ao.config.policy)) {
      throw std::invalid_argument("parameter ~policy must be SLWB, SLWDWCV or SLWSM");
    }
    ao.inner_dir = o.inner_dir;
    ao.agora_id = o.agora_id;
    BridgeMapping mapping = LoadBridgeMapping(o.mapping);
    agora_ = std::make_unique<Agora>(ao);

    for (const auto& m : mapping.to_ros) {
      switch (m.kind) {
        case PayloadKind::PERCEPT: pubs_[m.type] = nh.advertise<mrt_msgs::Percept>(m.topic, o.queue_size); break;
        case PayloadKind::CRISP_DATA:
          pubs_[m.type] = nh.advertise<mrt_msgs::CrispDataArray>(m.topic, o.queue_size);
          break;
        case PayloadKind::COMMANDS: pubs_[m.type] = nh.advertise<mrt_msgs::CommandArray>(m.topic, o.queue_size); break;
        case PayloadKind::RAW: pubs_[m.type] = nh.advertise<std_msgs::String>(m.topic, o.queue_size); break;
      }
    }
    member_ = std::make_unique<BridgeMember>(
        agora_.get(), mapping, [this](const TopicMapping& m, const Msg& msg, const XmlMessage* xml) { return ToRos(m, msg, xml); });
    for (const auto& m : member_->mapping().to_dcdt) Subscribe(nh, m, o.queue_size);
    diag_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    diag_timer_ = nh.createTimer(ros::Duration(o.diagnostics_period), [this](const ros::TimerEvent&) { Diagnostics(); });
    agora_->AddMember(member_.get());
    agora_->ActivateMember(member_.get());
    worker_ = std::thread([this] { agora_->LetsWork(); });
    ROS_INFO("dcdt_bridge: Agora %d (%s), %zu DCDT->ROS and %zu ROS->DCDT mappings", agora_->GetAgoraID(),
             ao.network ? "NETWORK" : "STANDALONE", member_->mapping().to_ros.size(), member_->mapping().to_dcdt.size());
  }

  ~BridgeNode() {
    agora_->Shutdown();
    if (worker_.joinable()) worker_.join();
    member_.reset();
    agora_.reset();
  }

 private:
  bool ToRos(const TopicMapping& m, const Msg& msg, const XmlMessage* xml) {
    auto& pub = pubs_.at(m.type);
    try {
      switch (m.kind) {
        case PayloadKind::PERCEPT: pub.publish(ros_conv::ToPercept(*xml)); break;
        case PayloadKind::CRISP_DATA: pub.publish(ros_conv::ToCrispData(*xml)); break;
        case PayloadKind::COMMANDS: pub.publish(ros_conv::ToCommands(*xml)); break;
        case PayloadKind::RAW: {
          std_msgs::String s;
          s.data = msg.PayloadString();
          pub.publish(s);
          break;
        }
      }
    } catch (const XmlError& e) {
      member_->CountError(std::string("type ") + std::to_string(m.type) + ": " + e.what(), BridgeError::CONVERSION);
      ROS_WARN_THROTTLE(5.0, "dcdt_bridge: dropped a DCDT message of type %d: %s", m.type, e.what());
      return false;
    }
    return true;
  }

  template <class M>
  void SubscribeKind(ros::NodeHandle& nh, const TopicMapping& m, int q, std::function<XmlMessage(const M&)> conv) {
    subs_.push_back(nh.subscribe<M>(m.topic, static_cast<uint32_t>(q),
                                    [this, m, conv](const ros::MessageEvent<M const>& ev) {
                                      if (ev.getPublisherName() == ros::this_node::getName()) return;  // our own echo
                                      try {
                                        member_->Share(m, EncodeXml(conv(*ev.getConstMessage())));
                                      } catch (const XmlError& e) {
                                        member_->CountError(m.topic + ": " + e.what(), BridgeError::CONVERSION);
                                        ROS_WARN_THROTTLE(5.0, "dcdt_bridge: dropped a message of %s: %s",
                                                          m.topic.c_str(), e.what());
                                      }
                                    }));
  }

  void Subscribe(ros::NodeHandle& nh, const TopicMapping& m, int q) {
    switch (m.kind) {
      case PayloadKind::PERCEPT:
        SubscribeKind<mrt_msgs::Percept>(nh, m, q, ros_conv::FromPercept);
        break;
      case PayloadKind::CRISP_DATA:
        SubscribeKind<mrt_msgs::CrispDataArray>(nh, m, q, ros_conv::FromCrispData);
        break;
      case PayloadKind::COMMANDS:
        SubscribeKind<mrt_msgs::CommandArray>(nh, m, q, ros_conv::FromCommands);
        break;
      case PayloadKind::RAW:
        subs_.push_back(nh.subscribe<std_msgs::String>(
            m.topic, static_cast<uint32_t>(q), [this, m](const ros::MessageEvent<std_msgs::String const>& ev) {
              if (ev.getPublisherName() == ros::this_node::getName()) return;
              member_->Share(m, ev.getConstMessage()->data);
            }));
        break;
    }
  }

  void Diagnostics() {
    const AgoraStats a = agora_->Stats();
    const BridgeStats b = member_->Stats();
    diagnostic_msgs::DiagnosticArray arr;
    arr.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus st;
    st.name = ros::this_node::getName() + ": DCDT Agora";
    st.hardware_id = "agora " + std::to_string(agora_->GetAgoraID());
    int connected = 0;
    for (const auto& c : a.channels) connected += c.connected ? 1 : 0;
    const int peers = a.inner_peers + a.finder_peers + connected;
    uint64_t channel_errors = 0;
    for (const auto& c : a.channels) channel_errors += c.errors;
    const bool trouble = b.parse_errors > 0 || b.conversion_errors > 0 || b.dropped > 0 || a.mailbox_dropped > 0 ||
                         a.hop_limited > 0 || a.inner_errors > 0 || channel_errors > 0;
    st.level = trouble ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK;
    st.message = peers > 0 ? "bridging" : "no peer Agora seen";
    if (peers == 0 && st.level == diagnostic_msgs::DiagnosticStatus::OK) st.level = diagnostic_msgs::DiagnosticStatus::WARN;
    auto kv = [&](const std::string& k, const std::string& v) {
      diagnostic_msgs::KeyValue x;
      x.key = k;
      x.value = v;
      st.values.push_back(x);
    };
    kv("agora_id", std::to_string(agora_->GetAgoraID()));
    kv("inner_peers", std::to_string(a.inner_peers));
    kv("finder_peers", std::to_string(a.finder_peers));
    std::string ids;
    for (int id : a.peer_ids) ids += (ids.empty() ? "" : ",") + std::to_string(id);
    kv("peers_seen", ids);
    kv("channels_connected", std::to_string(connected) + "/" + std::to_string(a.channels.size()));
    for (const auto& [type, n] : b.in) kv("in." + std::to_string(type), std::to_string(n));
    for (const auto& [type, n] : b.out) kv("out." + std::to_string(type), std::to_string(n));
    kv("parse_errors", std::to_string(b.parse_errors));
    kv("conversion_errors", std::to_string(b.conversion_errors));
    kv("dropped", std::to_string(b.dropped));
    kv("mailbox_dropped", std::to_string(a.mailbox_dropped));
    kv("hop_limited", std::to_string(a.hop_limited));
    kv("inner_errors", std::to_string(a.inner_errors));
    kv("channel_errors", std::to_string(channel_errors));
    kv("duplicates_suppressed", std::to_string(a.duplicates));
    if (!b.last_error.empty()) kv("last_error", b.last_error);
    for (const auto& c : a.channels)
      kv("channel " + c.name, std::string(c.connected ? "up" : "down") + " sent=" + std::to_string(c.sent) +
                                  " received=" + std::to_string(c.received) + " resent=" + std::to_string(c.resent) +
                                  " dropped=" + std::to_string(c.dropped) + " errors=" + std::to_string(c.errors) +
                                  " gaps=" + std::to_string(c.gaps) + " reconnects=" + std::to_string(c.reconnects));
    arr.status.push_back(st);
    diag_pub_.publish(arr);
  }

  std::unique_ptr<Agora> agora_;
  std::unique_ptr<BridgeMember> member_;
  std::map<int, ros::Publisher> pubs_;
  std::vector<ros::Subscriber> subs_;
  ros::Publisher diag_pub_;
  ros::Timer diag_timer_;
  std::thread worker_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "dcdt_bridge");
  ros::NodeHandle nh, pnh("~");
  std::unique_ptr<BridgeNode> node;
  try {
    node = std::make_unique<BridgeNode>(nh, pnh);
  } catch (const mrt::common::ParseError& e) {
    ROS_FATAL("dcdt_bridge: %s", e.what());
    return 1;
  } catch (const std::exception& e) {
    ROS_FATAL("dcdt_bridge: %s", e.what());
    return 1;
  }
  ros::spin();
  node.reset();
  return 0;
}
