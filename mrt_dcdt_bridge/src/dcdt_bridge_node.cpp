// dcdt_bridge_node: joins a DCDT community as an Agora and bridges the mapped
// DCDT message types to ROS topics and back (see README "Node API").
// Wiring only: the Agora and the BridgeMember are ROS-free.
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <diagnostic_msgs/DiagnosticArray.h>

#include <memory>
#include <thread>

#include "mrt_common_ros/params.h"
#include "mrt_dcdt/agora.h"
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

// Every parameter, read once and validated (README "Parameters").
NodeOptions read_options(const ros::NodeHandle& pnh) {
  NodeOptions o;
  mrt::ros_common::ParamReader p(pnh);
  p.get("agora_config", o.agora_config)
      .require("mapping", o.mapping, "the path of the YAML mapping file")
      .get("inner_dir", o.inner_dir)
      .get("policy", o.policy)
      .get("agora_id", o.agora_id)
      .get_positive("diagnostics_period", o.diagnostics_period)
      .get_positive("queue_size", o.queue_size);
  p.check(!o.mapping.empty(), "mapping", "the path of the YAML mapping file");
  p.check(o.agora_id >= 0, "agora_id", "an integer >= 0 (0 = random)");
  PostOfficePolicy policy;
  p.check(parse_policy(o.policy, &policy), "policy", "SLWB, SLWDWCV or SLWSM");
  return o;
}

class BridgeNode {
 public:
  BridgeNode(ros::NodeHandle& nh, const ros::NodeHandle& pnh) {
    const NodeOptions o = read_options(pnh);
    AgoraOptions ao;
    if (!o.agora_config.empty()) {
      ao.network = true;
      ao.config = load_agora_config(o.agora_config);
    } else {
      parse_policy(o.policy, &ao.config.policy);  // checked by read_options
    }
    ao.inner_dir = o.inner_dir;
    ao.agora_id = o.agora_id;
    BridgeMapping mapping = load_bridge_mapping(o.mapping);
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
        agora_.get(), mapping, [this](const TopicMapping& m, const Msg& msg, const XmlMessage* xml) { return forward_to_ros(m, msg, xml); });
    for (const auto& m : member_->mapping().to_dcdt) subscribe(nh, m, o.queue_size);
    diag_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    diag_timer_ = nh.createTimer(ros::Duration(o.diagnostics_period), [this](const ros::TimerEvent&) { publish_diagnostics(); });
    agora_->add_member(member_.get());
    agora_->activate_member(member_.get());
    worker_ = std::thread([this] { agora_->lets_work(); });
    ROS_INFO("dcdt_bridge: Agora %d (%s), %zu DCDT->ROS and %zu ROS->DCDT mappings", agora_->agora_id(),
             ao.network ? "NETWORK" : "STANDALONE", member_->mapping().to_ros.size(), member_->mapping().to_dcdt.size());
  }

  ~BridgeNode() {
    agora_->shutdown();
    if (worker_.joinable()) worker_.join();
    member_.reset();
    agora_.reset();
  }

 private:
  bool forward_to_ros(const TopicMapping& m, const Msg& msg, const XmlMessage* xml) {
    auto& pub = pubs_.at(m.type);
    try {
      switch (m.kind) {
        case PayloadKind::PERCEPT: pub.publish(ros_conv::to_percept(*xml)); break;
        case PayloadKind::CRISP_DATA: pub.publish(ros_conv::to_crisp_data(*xml)); break;
        case PayloadKind::COMMANDS: pub.publish(ros_conv::to_commands(*xml)); break;
        case PayloadKind::RAW: {
          std_msgs::String s;
          s.data = msg.payload_string();
          pub.publish(s);
          break;
        }
      }
    } catch (const XmlError& e) {
      member_->count_error(std::string("type ") + std::to_string(m.type) + ": " + e.what(), BridgeError::CONVERSION);
      ROS_WARN_THROTTLE(5.0, "dcdt_bridge: dropped a DCDT message of type %d: %s", m.type, e.what());
      return false;
    }
    return true;
  }

  template <class M>
  void subscribe_kind(ros::NodeHandle& nh, const TopicMapping& m, int q, std::function<XmlMessage(const M&)> conv) {
    subs_.push_back(nh.subscribe<M>(m.topic, static_cast<uint32_t>(q),
                                    [this, m, conv](const ros::MessageEvent<M const>& ev) {
                                      if (ev.getPublisherName() == ros::this_node::getName()) return;  // our own echo
                                      try {
                                        member_->share(m, encode_xml(conv(*ev.getConstMessage())));
                                      } catch (const XmlError& e) {
                                        member_->count_error(m.topic + ": " + e.what(), BridgeError::CONVERSION);
                                        ROS_WARN_THROTTLE(5.0, "dcdt_bridge: dropped a message of %s: %s",
                                                          m.topic.c_str(), e.what());
                                      }
                                    }));
  }

  void subscribe(ros::NodeHandle& nh, const TopicMapping& m, int q) {
    switch (m.kind) {
      case PayloadKind::PERCEPT:
        subscribe_kind<mrt_msgs::Percept>(nh, m, q, ros_conv::from_percept);
        break;
      case PayloadKind::CRISP_DATA:
        subscribe_kind<mrt_msgs::CrispDataArray>(nh, m, q, ros_conv::from_crisp_data);
        break;
      case PayloadKind::COMMANDS:
        subscribe_kind<mrt_msgs::CommandArray>(nh, m, q, ros_conv::from_commands);
        break;
      case PayloadKind::RAW:
        subs_.push_back(nh.subscribe<std_msgs::String>(
            m.topic, static_cast<uint32_t>(q), [this, m](const ros::MessageEvent<std_msgs::String const>& ev) {
              if (ev.getPublisherName() == ros::this_node::getName()) return;
              member_->share(m, ev.getConstMessage()->data);
            }));
        break;
    }
  }

  void publish_diagnostics() {
    const AgoraStats a = agora_->stats();
    const BridgeStats b = member_->stats();
    diagnostic_msgs::DiagnosticArray arr;
    arr.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus st;
    st.name = ros::this_node::getName() + ": DCDT Agora";
    st.hardware_id = "agora " + std::to_string(agora_->agora_id());
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
    kv("agora_id", std::to_string(agora_->agora_id()));
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
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    BridgeNode node(nh, pnh);
    ros::spin();
    return 0;
  });
}
