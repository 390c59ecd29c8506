// The diagnostics every node of the stack publishes at least (header-only;
// a node using it finds diagnostic_updater itself): one diagnostic_updater
// task, updated at 1 Hz, with each declared input's message count and age
// — WARN when an input has been silent longer than its timeout (or never
// arrived within it after start-up) — the counters the node keeps, and its
// own values through an optional callback. As robot_localization's nodes
// do: a node that stops hearing its inputs says so on /diagnostics.
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>

namespace mrt::ros_common {

class NodeDiagnostics {
 public:
  using Extra = std::function<void(diagnostic_updater::DiagnosticStatusWrapper&)>;

  /// `task`: the name of the status (e.g. "FollowMe guide"); `hardware_id`
  /// as diagnostic_updater's.
  NodeDiagnostics(ros::NodeHandle& nh, const std::string& task, const std::string& hardware_id,
                  Extra extra = nullptr)
      : extra_(std::move(extra)), start_(ros::Time::now()) {
    updater_.setHardwareID(hardware_id);
    updater_.add(task, this, &NodeDiagnostics::run);
    timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  }

  /// An input topic, silent for more than `timeout` s: WARN.
  void input(const std::string& name, double timeout) { inputs_[name].timeout = timeout; }
  /// A message of input `name` arrived now.
  void received(const std::string& name) {
    Input& in = inputs_[name];
    ++in.count;
    in.last = ros::Time::now();
  }
  /// Adds `n` to the counter `name` (published as a value).
  void count(const std::string& name, std::uint64_t n = 1) { counters_[name] += n; }
  std::uint64_t counter(const std::string& name) const {
    const auto it = counters_.find(name);
    return it == counters_.end() ? 0 : it->second;
  }

 private:
  struct Input {
    double timeout = 1.0;
    std::uint64_t count = 0;
    ros::Time last;
  };

  void run(diagnostic_updater::DiagnosticStatusWrapper& st) {
    const ros::Time now = ros::Time::now();
    std::string silent;
    for (const auto& [name, in] : inputs_) {
      const double age = in.count > 0 ? (now - in.last).toSec() : (now - start_).toSec();
      if (age > in.timeout) silent += (silent.empty() ? "" : ", ") + name;
      st.add(name + " messages", in.count);
      st.add(name + " age (s)", in.count > 0 ? age : -1.0);
    }
    for (const auto& [name, n] : counters_) st.add(name, n);
    if (silent.empty())
      st.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
    else
      st.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no recent messages on: " + silent);
    if (extra_) extra_(st);  // may raise the level with mergeSummary
  }

  diagnostic_updater::Updater updater_;
  Extra extra_;
  ros::Time start_;
  ros::Timer timer_;
  std::map<std::string, Input> inputs_;
  std::map<std::string, std::uint64_t> counters_;
};

}  // namespace mrt::ros_common
