// diagnostic_aggregator_node: the stack's diagnostic aggregator (Debian's
// ROS ships diagnostic_aggregator's binary without its package). Reads a
// GenericAnalyzer configuration (~config, the diagnostic_aggregator YAML
// format: include/mrt_common_ros/diagnostic_aggregator.h), hears
// /diagnostics and publishes /diagnostics_agg (diagnostic_msgs/
// DiagnosticArray: "/Path" and "/Path/item") and /diagnostics_toplevel_state
// (the worst level) at ~pub_rate Hz. Wiring only: README "diagnostic_aggregator_node".
#include <diagnostic_msgs/DiagnosticArray.h>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/ros.h>

#include <string>

#include "mrt_common_ros/diagnostic_aggregator.h"
#include "mrt_common_ros/params.h"

namespace {

using mrt::ros_common::AggStatus;

AggStatus from_msg(const diagnostic_msgs::DiagnosticStatus& m) {
  AggStatus s;
  s.level = m.level;
  s.name = m.name;
  s.message = m.message;
  s.hardware_id = m.hardware_id;
  for (const auto& kv : m.values) s.values.emplace_back(kv.key, kv.value);
  return s;
}

diagnostic_msgs::DiagnosticStatus to_msg(const AggStatus& s) {
  diagnostic_msgs::DiagnosticStatus m;
  m.level = s.level;
  m.name = s.name;
  m.message = s.message;
  m.hardware_id = s.hardware_id;
  for (const auto& [k, v] : s.values) {
    diagnostic_msgs::KeyValue kv;
    kv.key = k;
    kv.value = v;
    m.values.push_back(kv);
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "diagnostic_aggregator");
  return mrt::ros_common::run_node([] {
    ros::NodeHandle nh, pnh("~");
    std::string file;
    double other_timeout = 5.0;
    mrt::ros_common::ParamReader p(pnh);
    p.require("config", file, "the aggregator's YAML file (analyzers: GenericAnalyzer entries)")
        .get_positive("other_timeout", other_timeout);
    mrt::ros_common::AggregatorConfig config = mrt::ros_common::load_aggregator_config(file);
    if (pnh.hasParam("pub_rate")) {  // the parameter wins over the file's pub_rate
      p.get_positive("pub_rate", config.pub_rate);
      p.check(config.pub_rate <= 100.0, "pub_rate", "a number in (0, 100]");
    }
    mrt::ros_common::Aggregator agg(config, other_timeout);
    ros::Publisher agg_pub = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics_agg", 1);
    ros::Publisher top_pub = nh.advertise<diagnostic_msgs::DiagnosticStatus>("/diagnostics_toplevel_state", 1);
    ros::Subscriber sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 1000, [&agg](const diagnostic_msgs::DiagnosticArray::ConstPtr& a) {
          const double now = ros::Time::now().toSec();
          for (const auto& s : a->status) agg.add(from_msg(s), now);
        });
    ros::Timer timer = nh.createTimer(ros::Duration(1.0 / config.pub_rate), [&](const ros::TimerEvent&) {
      const ros::Time now = ros::Time::now();
      const mrt::ros_common::AggOutput out = agg.aggregate(now.toSec());
      diagnostic_msgs::DiagnosticArray arr;
      arr.header.stamp = now;
      for (const auto& s : out.statuses) arr.status.push_back(to_msg(s));
      agg_pub.publish(arr);
      top_pub.publish(to_msg(out.toplevel));
    });
    ROS_INFO("diagnostic_aggregator: %zu analyzers from %s, %.1f Hz", config.analyzers.size(), file.c_str(),
             config.pub_rate);
    ros::spin();
    return 0;
  });
}
