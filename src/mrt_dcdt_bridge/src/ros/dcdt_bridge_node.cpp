// dcdt_bridge_node: joins a DCDT community as an Agora and bridges the mapped
// DCDT message types to ROS topics and back (see README "Node API").
// Wiring only: the Agora and the BridgeMember are ROS-free.
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <diagnostic_msgs/DiagnosticArray.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "mrt_common_ros/params.h"
#include "mrt_dcdt/agora.h"
#include "mrt_dcdt_bridge/bridge_member.h"
#include "ros/conversions.h"
#include "ros/team_conversions.h"

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
    // The origin tag of what this node publishes: its agora id, under its
    // node name, set before anything is advertised (README "Two bridges").
    ros::param::set(origin_param(ros::this_node::getName()), agora_->agora_id());

    for (const auto& m : mapping.to_ros) {
      switch (m.kind) {
        case PayloadKind::PERCEPT: pubs_[m.type] = nh.advertise<mrt_msgs::Percept>(m.topic, o.queue_size); break;
        case PayloadKind::CRISP_DATA:
          pubs_[m.type] = nh.advertise<mrt_msgs::CrispDataArray>(m.topic, o.queue_size);
          break;
        case PayloadKind::COMMANDS: pubs_[m.type] = nh.advertise<mrt_msgs::CommandArray>(m.topic, o.queue_size); break;
        case PayloadKind::WORLD_MODEL:
          pubs_[m.type] = nh.advertise<mrt_msgs::WorldModel>(m.topic, o.queue_size);
          break;
        case PayloadKind::COORDINATION:
          pubs_[m.type] = nh.advertise<mrt_msgs::CoordinationParameters>(m.topic, o.queue_size);
          break;
        case PayloadKind::REFEREE:  // latched: a robot that joins late learns whether play is on
          pubs_[m.type] = nh.advertise<mrt_msgs::RefereeCommand>(m.topic, o.queue_size, true);
          break;
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
    ros::param::del(origin_param(ros::this_node::getName()));
    agora_->shutdown();
    if (worker_.joinable()) worker_.join();
    member_.reset();
    agora_.reset();
  }

 private:
  static std::string origin_param(const std::string& node) { return "/dcdt_bridges" + node; }

  // True when a ROS message comes from another bridge whose Agora is a peer
  // of ours: its content came out of our own DCDT community, so sharing it
  // again would echo it between the two bridges forever.
  bool from_peer_bridge(const std::string& publisher) {
    std::lock_guard<std::mutex> l(loop_mutex_);
    const double now = ros::WallTime::now().toSec();
    auto it = bridge_ids_.find(publisher);
    if (it == bridge_ids_.end() || now - it->second.second > 5.0) {
      int id = 0;
      if (!ros::param::get(origin_param(publisher), id)) id = 0;
      it = bridge_ids_.insert_or_assign(publisher, std::make_pair(id, now)).first;
    }
    const int id = it->second.first;
    if (id == 0) return false;
    if (now - peers_time_ > 0.2) {
      peers_ = agora_->stats().peer_ids;  // sorted
      peers_time_ = now;
    }
    if (!std::binary_search(peers_.begin(), peers_.end(), id)) return false;
    ++loops_suppressed_;
    return true;
  }

  bool forward_to_ros(const TopicMapping& m, const Msg& msg, const XmlMessage* xml) {
    auto& pub = pubs_.at(m.type);
    try {
      switch (m.kind) {
        case PayloadKind::PERCEPT: pub.publish(node::to_percept(*xml)); break;
        case PayloadKind::CRISP_DATA: pub.publish(node::to_crisp_data(*xml)); break;
        case PayloadKind::COMMANDS: pub.publish(node::to_commands(*xml)); break;
        case PayloadKind::WORLD_MODEL: pub.publish(node::to_world_model(*xml)); break;
        case PayloadKind::COORDINATION: pub.publish(node::to_coordination(*xml)); break;
        case PayloadKind::REFEREE: pub.publish(node::to_referee(*xml)); break;
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
    // A boost::function of MessageEvent picks roscpp's event overload: a bare
    // lambda would be called through the ConstPtr overload (MessageEvent
    // converts from it) and lose the publisher's name ("unknown_publisher").
    const boost::function<void(const ros::MessageEvent<M const>&)> cb =
                                    [this, m, conv](const ros::MessageEvent<M const>& ev) {
                                      if (ev.getPublisherName() == ros::this_node::getName()) return;  // our own echo
                                      if (from_peer_bridge(ev.getPublisherName())) return;  // another bridge's echo
                                      try {
                                        member_->share(m, encode_xml(conv(*ev.getConstMessage())));
                                      } catch (const XmlError& e) {
                                        member_->count_error(m.topic + ": " + e.what(), BridgeError::CONVERSION);
                                        ROS_WARN_THROTTLE(5.0, "dcdt_bridge: dropped a message of %s: %s",
                                                          m.topic.c_str(), e.what());
                                      }
                                    };
    subs_.push_back(nh.subscribe<M, const ros::MessageEvent<M const>&>(m.topic, static_cast<uint32_t>(q), cb));
  }

  void subscribe(ros::NodeHandle& nh, const TopicMapping& m, int q) {
    switch (m.kind) {
      case PayloadKind::PERCEPT:
        subscribe_kind<mrt_msgs::Percept>(nh, m, q, node::from_percept);
        break;
      case PayloadKind::CRISP_DATA:
        subscribe_kind<mrt_msgs::CrispDataArray>(nh, m, q, node::from_crisp_data);
        break;
      case PayloadKind::COMMANDS:
        subscribe_kind<mrt_msgs::CommandArray>(nh, m, q, node::from_commands);
        break;
      case PayloadKind::WORLD_MODEL:
        subscribe_kind<mrt_msgs::WorldModel>(nh, m, q, node::from_world_model);
        break;
      case PayloadKind::COORDINATION:
        subscribe_kind<mrt_msgs::CoordinationParameters>(nh, m, q, node::from_coordination);
        break;
      case PayloadKind::REFEREE:
        subscribe_kind<mrt_msgs::RefereeCommand>(nh, m, q, node::from_referee);
        break;
      case PayloadKind::RAW: {
        const boost::function<void(const ros::MessageEvent<std_msgs::String const>&)> cb =
            [this, m](const ros::MessageEvent<std_msgs::String const>& ev) {
              if (ev.getPublisherName() == ros::this_node::getName()) return;
              if (from_peer_bridge(ev.getPublisherName())) return;
              member_->share(m, ev.getConstMessage()->data);
            };
        subs_.push_back(nh.subscribe<std_msgs::String, const ros::MessageEvent<std_msgs::String const>&>(
            m.topic, static_cast<uint32_t>(q), cb));
        break;
      }
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
                         a.hop_limited > 0 || a.inner_errors > 0 || a.inner_dropped > 0 || a.guaranteed_refused > 0 ||
                         channel_errors > 0;
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
    kv("guaranteed_refused", std::to_string(a.guaranteed_refused));
    kv("hop_limited", std::to_string(a.hop_limited));
    kv("inner_errors", std::to_string(a.inner_errors));
    kv("inner_dropped", std::to_string(a.inner_dropped));
    std::string stalled;
    for (int id : a.inner_stalled_peers) stalled += (stalled.empty() ? "" : " ") + std::to_string(id);
    kv("inner_stalled_peers", stalled);
    kv("channel_errors", std::to_string(channel_errors));
    kv("duplicates_suppressed", std::to_string(a.duplicates));
    kv("loops_suppressed", std::to_string(loops_suppressed_.load()));
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
  std::mutex loop_mutex_;  // the loop guard's caches
  std::map<std::string, std::pair<int, double>> bridge_ids_;  // publisher -> (agora id or 0, wall time checked)
  std::vector<int> peers_;
  double peers_time_ = -1.0;
  std::atomic<uint64_t> loops_suppressed_{0};
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
