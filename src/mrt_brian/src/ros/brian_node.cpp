// brian_node: Mr. BRIAN as a ROS node. Wiring only: parameters -> BrianOptions,
// mrt_msgs/CrispDataArray -> CrispDataList, CommandList -> mrt_msgs/CommandArray.
// See README.md for the topics, services and parameters. dynamic_reconfigure
// (cfg/Brian.cfg): the CANDO threshold; one mutex serializes every callback
// with the reconfiguration.
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <mrt_msgs/BrianIntrospection.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include "mrt_brian/BrianConfig.h"
#include "mrt_brian/brian.h"
#include "mrt_common/parse_error.h"
#include "mrt_common_ros/params.h"

namespace mrt::brian::node {

namespace {

using mrt::ros_common::ParamError;
using mrt::ros_common::ParamReader;

struct NodeOptions {
  std::string config;
  BrianOptions brian;
  double rate = 0.0;
  bool introspection = true;
  /// Fixed rate only: seconds without crisp data after which the safe
  /// commands are published instead (0: never).
  double input_timeout = 0.0;
  /// Safe set-points by action name; actions not listed get 0.
  std::map<std::string, double> safe_commands;
  /// Crisp data stamped back by up to this (s) is out of order and dropped;
  /// further back (a bag loop, a restarted clock) is taken as a new time
  /// base; forward by more than this is a gap. Stamps of 0 are not checked.
  double stamp_gap = 1.0;
};

// A string parameter parsed by `parse` (std::invalid_argument -> ParamError).
template <class T, class Parse>
void get_choice(ParamReader& r, const std::string& name, T& value, const std::string& def, const std::string& choices,
                Parse parse) {
  std::string s = def;
  r.get(name, s);
  try {
    value = parse(s);
  } catch (const std::invalid_argument&) {
    throw ParamError(name, choices + ", got '" + s + "'");
  }
}

// Reads and validates the private parameters once (the stack's ParamReader
// style); throws ParamError naming the parameter.
NodeOptions read_options(const ros::NodeHandle& pnh) {
  NodeOptions o;
  ParamReader r(pnh);
  r.require("config", o.config, "a rule-base directory or a BrianConfigs.ini");
  ParamReader::check(!o.config.empty(), "config", "a rule-base directory or a BrianConfigs.ini");
  get_choice(r, "profile", o.brian.profile, "manual", "'manual' or 'legacy'", parse_profile);
  r.get("threshold", o.brian.threshold);
  ParamReader::check(o.brian.threshold >= 0.0 && o.brian.threshold <= 1.0, "threshold", "a number in [0, 1]");
  if (pnh.hasParam("threshold_reliability")) {
    bool b = false;
    r.get("threshold_reliability", b);
    o.brian.threshold_reliability = b;
  }
  get_choice(r, "weight_composer", o.brian.weight_composer, "mult", "'mult', 'max' or 'min'", parse_weight_composer);
  if (pnh.hasParam("float_composer")) {
    FloatComposerKind k{};
    get_choice(r, "float_composer", k, "", "'average', 'max', 'min' or 'best'", parse_float_composer);
    o.brian.float_composer = k;
  }
  get_choice(r, "defuzzification", o.brian.defuzzification, "singleton", "'singleton' or 'barycenter'",
             parse_defuzz_method);
  r.get_non_negative("rate", o.rate).get("introspection", o.introspection);
  r.get_non_negative("input_timeout", o.input_timeout).get("safe_commands", o.safe_commands);
  r.get_positive("stamp_gap", o.stamp_gap);
  ParamReader::check(o.input_timeout == 0.0 || o.rate > 0.0, "input_timeout",
                     "0 unless ~rate > 0 (the timeout is checked at every fixed-rate cycle)");
  for (const auto& [name, value] : o.safe_commands)
    ParamReader::check(std::isfinite(value), "safe_commands", "finite set-points (" + name + ")");
  o.brian.warn = [](const std::string& w) { ROS_WARN("brian_node: %s", w.c_str()); };
  return o;
}

// The safe commands for `brian`'s actions: the configured value, else 0.
// A name that is not an action of the rule base is a parameter error.
CommandList safe_commands(const NodeOptions& o, const Brian& brian) {
  for (const auto& [name, value] : o.safe_commands)
    ParamReader::check(brian.defuzzyfier().action_id(name) >= 0, "safe_commands",
                       "names of actions of the rule base (s_ftoc), got '" + name + "'");
  CommandList out;
  for (int a = 0; a < brian.defuzzyfier().action_count(); ++a) {
    const std::string& name = brian.defuzzyfier().action_name(a);
    const auto it = o.safe_commands.find(name);
    out.push_back({name, it == o.safe_commands.end() ? 0.0 : it->second});
  }
  return out;
}

const char* profile_name(Profile p) { return p == Profile::kLegacy ? "legacy" : "manual"; }

}  // namespace

class BrianNode {
 public:
  BrianNode(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), pnh_(pnh), diag_(nh, pnh) {
    options_ = read_options(pnh_);
    brian_ = Brian::from_path(options_.config, options_.brian);  // throws: the node exits non-zero
    safe_ = safe_commands(options_, *brian_);
    last_input_ = ros::Time::now();
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
    // last: from here the threshold is also ~threshold's dynamic_reconfigure
    // (the validated start-up value, not the server's clamped copy)
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<mrt_brian::BrianConfig>>(reconfigure_mutex_, pnh_);
    reconfigure_->updateConfig(current_config());
    reconfigure_->setCallback([this](mrt_brian::BrianConfig& c, uint32_t) { on_reconfigure(c); });
  }

 private:
  static bool valid(const mrt_msgs::CrispData& d, std::string* why) {
    if (d.name.empty()) { *why = "empty name"; return false; }
    if (!std::isfinite(d.value)) { *why = d.name + ": value not finite"; return false; }
    if (!(d.reliability >= 0.0 && d.reliability <= 1.0)) { *why = d.name + ": reliability outside [0, 1]"; return false; }
    return true;
  }

  mrt_brian::BrianConfig current_config() const {
    mrt_brian::BrianConfig c = mrt_brian::BrianConfig::__getDefault__();
    c.threshold = brian_->engine().threshold();
    return c;
  }

  // The threshold from the next cycle (BehaviorEngine::set_threshold, the
  // legacy WANT filter too); kept in the options, so ~reload keeps it.
  void on_reconfigure(mrt_brian::BrianConfig& c) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (c.threshold >= 0.0 && c.threshold <= 1.0 && c.threshold != brian_->engine().threshold()) {
      brian_->engine().set_threshold(c.threshold);
      options_.brian.threshold = c.threshold;
      ROS_INFO("brian_node: CANDO threshold %g", c.threshold);
    }
    c = current_config();
  }

  void on_crisp(const mrt_msgs::CrispDataArray::ConstPtr& msg) {
    const std::lock_guard<std::mutex> lock(mutex_);
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
    if (!stamp_in_order(msg->header.stamp)) return;
    input_.clear();
    for (const auto& d : msg->data) input_.push_back({d.name, d.value, d.reliability});
    have_input_ = true;
    last_input_ = ros::Time::now();
    if (stale_) {
      stale_ = false;
      ROS_INFO("brian_node: crisp data again, cycling on it");
    }
    if (options_.rate <= 0.0) cycle(msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp);
  }

  // Checks a message's stamp against the previous one: duplicated and
  // out-of-order stamps are dropped (false), gaps and jumps back beyond
  // ~stamp_gap are taken (true); each counted in the diagnostics.
  bool stamp_in_order(const ros::Time& stamp) {
    if (stamp.isZero()) return true;
    if (have_stamp_) {
      const double d = (stamp - last_stamp_).toSec();
      if (d == 0.0 || (d < 0.0 && -d <= options_.stamp_gap)) {
        std::uint64_t& n = d == 0.0 ? duplicate_stamps_ : out_of_order_stamps_;
        ++n;
        ROS_WARN_THROTTLE(5.0, "brian_node: dropped crisp data with a %s stamp (%.3f s after the previous one)",
                          d == 0.0 ? "duplicated" : "out-of-order", d);
        return false;
      }
      if (d < 0.0) ++stamp_jumps_back_;
      else if (d > options_.stamp_gap) ++stamp_gaps_;
    }
    have_stamp_ = true;
    last_stamp_ = stamp;
    return true;
  }

  // Fixed rate: a cycle on the latest input, or the safe commands when no
  // crisp data arrived within ~input_timeout.
  void on_timer(const ros::TimerEvent&) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time now = ros::Time::now();
    if (options_.input_timeout > 0.0 && (now - last_input_).toSec() > options_.input_timeout) {
      if (!stale_) {
        stale_ = true;
        ++stale_periods_;
        ROS_WARN("brian_node: no crisp data for %.3f s (~input_timeout): publishing the safe commands",
                 (now - last_input_).toSec());
        diag_.force_update();
      }
      publish(safe_, now);
      diag_.update();
      return;
    }
    if (have_input_) cycle(now);
  }

  void publish(const CommandList& out, const ros::Time& stamp) {
    mrt_msgs::CommandArray cmd;
    cmd.header.stamp = stamp;
    for (const auto& c : out) {
      mrt_msgs::Command m;
      m.name = c.name;
      m.value = c.value;
      cmd.commands.push_back(m);
    }
    commands_pub_.publish(cmd);
    last_cmd_ = std::move(cmd);
  }

  void cycle(const ros::Time& stamp) {
    const bool intro = options_.introspection && introspection_pub_.getNumSubscribers() > 0;
    const CommandList& out = brian_->run(input_, intro ? &trace_ : nullptr);
    ++cycles_;
    publish(out, stamp);
    if (intro) publish_introspection(stamp, last_cmd_);
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
  bool on_reload(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      reload(req, res);
    }
    // the server's copy of ~threshold (outside mutex_: the server's mutex
    // is taken first in on_reconfigure)
    reconfigure_->updateConfig(current_config());
    return true;
  }

  void reload(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    try {
      NodeOptions o = read_options(pnh_);
      auto b = Brian::from_path(o.config, o.brian);
      CommandList safe = safe_commands(o, *b);
      if (o.rate != options_.rate)
        ROS_WARN("brian_node: ~rate changes need a restart; keeping %g", options_.rate);
      o.rate = options_.rate;
      o.introspection = options_.introspection;
      brian_ = std::move(b);
      safe_ = std::move(safe);
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
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
    if (stale_)
      s.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                "no crisp data within ~input_timeout: publishing the safe commands");
    else if (!last_reload_error_.empty())
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
    s.add("input timeout (s)", options_.input_timeout);
    s.add("publishing safe commands", stale_ ? "yes" : "no");
    s.add("stale-input periods", stale_periods_);
    s.add("duplicate stamps (dropped)", duplicate_stamps_);
    s.add("out-of-order stamps (dropped)", out_of_order_stamps_);
    s.add("stamp gaps", stamp_gaps_);
    s.add("stamp jumps back (new time base)", stamp_jumps_back_);
  }

  std::mutex mutex_;  // every callback's: the reconfiguration changes the engine
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
  CommandList safe_;
  mrt_msgs::CommandArray last_cmd_;
  ros::Time last_input_;
  bool have_input_ = false, stale_ = false, have_stamp_ = false;
  ros::Time last_stamp_;
  std::uint64_t duplicate_stamps_ = 0, out_of_order_stamps_ = 0, stamp_gaps_ = 0, stamp_jumps_back_ = 0;
  std::uint64_t cycles_ = 0, dropped_ = 0, reloads_ = 0, stale_periods_ = 0;
  std::string last_reload_error_;
  boost::recursive_mutex reconfigure_mutex_;  // the server's own, held around on_reconfigure
  std::unique_ptr<dynamic_reconfigure::Server<mrt_brian::BrianConfig>> reconfigure_;
};

}  // namespace mrt::brian::node

int main(int argc, char** argv) {
  ros::init(argc, argv, "brian");
  return mrt::ros_common::run_node([] {
    mrt::brian::node::BrianNode node{ros::NodeHandle(), ros::NodeHandle("~")};
    ros::spin();
    return 0;
  });
}
