// brian_node: Mr. BRIAN as a ROS node. Wiring only: parameters -> BrianOptions,
// mrt_msgs/CrispDataArray -> CrispDataList, CommandList -> mrt_msgs/CommandArray.
// See README.md for the topics, services and parameters.
#include <cmath>
#include <memory>
#include <string>

#include <diagnostic_updater/diagnostic_updater.h>
#include <mrt_msgs/BrianIntrospection.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include "mrt_brian/brian.h"
#include "mrt_common/parse_error.h"

namespace mrt::brian {

namespace {

struct NodeOptions {
  std::string config;
  BrianOptions brian;
  double rate = 0.0;
  bool introspection = true;
};

// Reads and validates the private parameters; throws std::invalid_argument
// naming the parameter.
NodeOptions read_options(const ros::NodeHandle& pnh) {
  NodeOptions o;
  if (!pnh.getParam("config", o.config) || o.config.empty())
    throw std::invalid_argument("~config: required, a rule-base directory or a BrianConfigs.ini");
  auto str = [&](const char* name, const std::string& def) {
    std::string v;
    pnh.param<std::string>(name, v, def);
    return v;
  };
  auto wrap = [](const char* name, auto fn) {
    try {
      return fn();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("~") + name + ": " + e.what());
    }
  };
  o.brian.profile = wrap("profile", [&] { return parse_profile(str("profile", "manual")); });
  pnh.param("threshold", o.brian.threshold, 0.49);
  if (!(o.brian.threshold >= 0.0 && o.brian.threshold <= 1.0))
    throw std::invalid_argument("~threshold: must be in [0, 1]");
  if (pnh.hasParam("threshold_reliability")) {
    bool b = false;
    pnh.getParam("threshold_reliability", b);
    o.brian.threshold_reliability = b;
  }
  o.brian.weight_composer = wrap("weight_composer", [&] { return parse_weight_composer(str("weight_composer", "mult")); });
  const std::string fc = str("float_composer", "");
  if (!fc.empty()) o.brian.float_composer = wrap("float_composer", [&] { return parse_float_composer(fc); });
  o.brian.defuzzification = wrap("defuzzification", [&] { return parse_defuzz_method(str("defuzzification", "singleton")); });
  pnh.param("rate", o.rate, 0.0);
  if (!(o.rate >= 0.0 && std::isfinite(o.rate))) throw std::invalid_argument("~rate: must be >= 0 (0: a cycle per message)");
  pnh.param("introspection", o.introspection, true);
  return o;
}

const char* profile_name(Profile p) { return p == Profile::kLegacy ? "legacy" : "manual"; }

}  // namespace

class BrianNode {
 public:
  BrianNode(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), pnh_(pnh), diag_(nh, pnh) {
    options_ = read_options(pnh_);
    brian_ = Brian::from_path(options_.config, options_.brian);  // throws: the node exits non-zero
    commands_pub_ = nh_.advertise<mrt_msgs::CommandArray>("commands", 10);
    if (options_.introspection) introspection_pub_ = pnh_.advertise<mrt_msgs::BrianIntrospection>("introspection", 10);
    crisp_sub_ = nh_.subscribe("crisp_data", 10, &BrianNode::on_crisp, this);
    reload_srv_ = pnh_.advertiseService("reload", &BrianNode::on_reload, this);
    if (options_.rate > 0.0) timer_ = nh_.createTimer(ros::Duration(1.0 / options_.rate), &BrianNode::on_timer, this);
    diag_.setHardwareID("mrt_brian");
    diag_.add("Mr. BRIAN", this, &BrianNode::diagnose);
    ROS_INFO("brian_node: rule base %s, profile %s, %d behaviours, %s", options_.config.c_str(),
             profile_name(options_.brian.profile), brian_->engine().size(),
             options_.rate > 0 ? ("cycle at " + std::to_string(options_.rate) + " Hz").c_str() : "a cycle per message");
  }

 private:
  static bool valid(const mrt_msgs::CrispData& d, std::string* why) {
    if (d.name.empty()) { *why = "empty name"; return false; }
    if (!std::isfinite(d.value)) { *why = d.name + ": value not finite"; return false; }
    if (!(d.reliability >= 0.0 && d.reliability <= 1.0)) { *why = d.name + ": reliability outside [0, 1]"; return false; }
    return true;
  }

  void on_crisp(const mrt_msgs::CrispDataArray::ConstPtr& msg) {
    std::string why;
    if (msg->data.size() > 10000) why = "more than 10000 data";
    for (const auto& d : msg->data)
      if (why.empty() && !valid(d, &why)) break;
    if (!why.empty()) {
      ++dropped_;
      ROS_WARN_THROTTLE(5.0, "brian_node: dropped a malformed crisp data message (%s); %lu dropped so far",
                        why.c_str(), static_cast<unsigned long>(dropped_));
      return;
    }
    input_.clear();
    for (const auto& d : msg->data) input_.push_back({d.name, d.value, d.reliability});
    have_input_ = true;
    if (options_.rate <= 0.0) cycle(msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp);
  }

  void on_timer(const ros::TimerEvent&) {
    if (have_input_) cycle(ros::Time::now());
  }

  void cycle(const ros::Time& stamp) {
    const bool intro = options_.introspection && introspection_pub_.getNumSubscribers() > 0;
    const CommandList& out = brian_->run(input_, intro ? &trace_ : nullptr);
    ++cycles_;
    mrt_msgs::CommandArray cmd;
    cmd.header.stamp = stamp;
    for (const auto& c : out) {
      mrt_msgs::Command m;
      m.name = c.name;
      m.value = c.value;
      cmd.commands.push_back(m);
    }
    commands_pub_.publish(cmd);
    if (intro) publish_introspection(stamp, cmd);
    diag_.update();
  }

  void publish_introspection(const ros::Time& stamp, const mrt_msgs::CommandArray& cmd) {
    mrt_msgs::BrianIntrospection m;
    m.header.stamp = stamp;
    m.cycle = cycles_;
    const BehaviorEngine& e = brian_->engine();
    for (int b = 0; b < e.size(); ++b) {
      const std::size_t i = static_cast<std::size_t>(b);
      mrt_msgs::BrianBehavior s;
      s.name = e.behavior(b).name();
      s.level = e.behavior(b).level();
      s.cando = brian_->cando()[i].value;
      s.cando_reliability = brian_->cando()[i].reliability;
      s.active = brian_->active()[i] != 0;
      s.want = brian_->want()[i].value;
      s.want_reliability = brian_->want()[i].reliability;
      s.weight = brian_->weights()[i];
      m.behaviors.push_back(s);
    }
    auto proposal = [](const std::string& action, const std::string& label, const std::string& behavior,
                       double value) {
      mrt_msgs::BrianProposal q;
      q.action = action;
      q.label = label;
      q.behavior = behavior;
      q.value = value;
      return q;
    };
    for (const auto& p : trace_.proposals) m.proposals.push_back(proposal(p.action, p.label, p.behavior, p.mu));
    for (const auto& a : trace_.actions) m.actions.push_back(proposal(a.action, a.label, "", a.mu));
    m.commands = cmd.commands;
    introspection_pub_.publish(m);
  }

  // Re-reads the parameters and the rule base; on any error the running rule
  // base stays and the response says why.
  bool on_reload(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    try {
      NodeOptions o = read_options(pnh_);
      auto b = Brian::from_path(o.config, o.brian);
      if (o.rate != options_.rate)
        ROS_WARN("brian_node: ~rate changes need a restart; keeping %g", options_.rate);
      o.rate = options_.rate;
      o.introspection = options_.introspection;
      brian_ = std::move(b);
      options_ = o;
      res.success = true;
      res.message = "reloaded " + options_.config + " (" + std::to_string(brian_->engine().size()) + " behaviours)";
      ++reloads_;
      last_reload_error_.clear();
      ROS_INFO("brian_node: %s", res.message.c_str());
    } catch (const std::exception& e) {
      res.success = false;
      res.message = std::string("reload failed, keeping the previous rule base: ") + e.what();
      last_reload_error_ = e.what();
      ROS_ERROR("brian_node: %s", res.message.c_str());
    }
    diag_.force_update();
    return true;
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    if (!last_reload_error_.empty())
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "last reload failed: " + last_reload_error_);
    else if (dropped_ > 0)
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN, "malformed crisp data messages dropped");
    else
      s.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
    s.add("rule base", options_.config);
    s.add("profile", profile_name(options_.brian.profile));
    s.add("behaviours", brian_->engine().size());
    s.add("cycles", cycles_);
    s.add("dropped messages", dropped_);
    s.add("reloads", reloads_);
  }

  ros::NodeHandle nh_, pnh_;
  diagnostic_updater::Updater diag_;
  NodeOptions options_;
  std::unique_ptr<Brian> brian_;
  ros::Publisher commands_pub_, introspection_pub_;
  ros::Subscriber crisp_sub_;
  ros::ServiceServer reload_srv_;
  ros::Timer timer_;
  CrispDataList input_;
  CycleTrace trace_;
  bool have_input_ = false;
  std::uint64_t cycles_ = 0, dropped_ = 0, reloads_ = 0;
  std::string last_reload_error_;
};

}  // namespace mrt::brian

int main(int argc, char** argv) {
  ros::init(argc, argv, "brian");
  try {
    mrt::brian::BrianNode node{ros::NodeHandle(), ros::NodeHandle("~")};
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("brian_node: %s", e.what());
    return 1;
  }
  return 0;
}
