// diagnostic_aggregator_node against test/data/aggregator.yaml: statuses
// published on /diagnostics come out grouped on /diagnostics_agg, the
// missing expected item stale, a silent item stale after its 2 s, and the
// worst level on /diagnostics_toplevel_state.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <map>
#include <string>

#include "mrt_common_ros/rostest_helpers.h"

using diagnostic_msgs::DiagnosticStatus;
using mrt::ros_common::wait_for;

namespace {

struct Listener {
  explicit Listener(ros::NodeHandle& nh)
      : agg_sub(nh.subscribe("/diagnostics_agg", 10, &Listener::on_agg, this)),
        top_sub(nh.subscribe("/diagnostics_toplevel_state", 10, &Listener::on_top, this)) {}
  void on_agg(const diagnostic_msgs::DiagnosticArray& a) {
    last.clear();
    for (const auto& s : a.status) last[s.name] = s;
    ++count;
  }
  void on_top(const DiagnosticStatus& s) { top = s; ++top_count; }
  bool has(const std::string& name, int level) const {
    const auto it = last.find(name);
    return it != last.end() && it->second.level == level;
  }

  std::map<std::string, DiagnosticStatus> last;
  DiagnosticStatus top;
  int count = 0, top_count = 0;
  ros::Subscriber agg_sub, top_sub;
};

DiagnosticStatus status(const std::string& name, int level, const std::string& message) {
  DiagnosticStatus s;
  s.name = name;
  s.level = static_cast<uint8_t>(level);
  s.message = message;
  s.hardware_id = "test";
  diagnostic_msgs::KeyValue kv;
  kv.key = "messages";
  kv.value = "7";
  s.values.push_back(kv);
  return s;
}

}  // namespace

TEST(DiagnosticAggregatorNode, GroupsStatusesAndReportsStaleOnes) {
  ros::NodeHandle nh;
  Listener l(nh);
  ros::Publisher pub = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);

  // Before any status: /Sensors has no item, the expected AIRBoard is missing.
  ASSERT_TRUE(wait_for([&] { return l.count > 0 && l.top_count > 0; }, 20.0)) << "no /diagnostics_agg";
  EXPECT_TRUE(l.has("/Sensors", DiagnosticStatus::STALE));
  EXPECT_TRUE(l.has("/Control/airboard: AIRBoard link", DiagnosticStatus::STALE));
  EXPECT_EQ(l.last["/Control/airboard: AIRBoard link"].message, "expected, never received");
  EXPECT_EQ(l.top.level, DiagnosticStatus::STALE);

  // Everything heard, the sonar warning: /Sensors WARN, /Control OK, top WARN.
  const auto publish_all = [&](int sonar_level) {
    diagnostic_msgs::DiagnosticArray a;
    a.header.stamp = ros::Time::now();
    a.status.push_back(status("robot1/sonar_crisp: sonar sectors", sonar_level, "sector 3 silent"));
    a.status.push_back(status("robot1/brian: Mr. BRIAN", DiagnosticStatus::OK, "ok"));
    a.status.push_back(status("robot1/airboard: AIRBoard link", DiagnosticStatus::OK, "ok"));
    a.status.push_back(status("visitor: FollowMe visitor", DiagnosticStatus::OK, "ok"));
    pub.publish(a);
  };
  ASSERT_TRUE(wait_for(
      [&] {
        publish_all(DiagnosticStatus::WARN);
        return l.has("/Sensors", DiagnosticStatus::WARN) && l.has("/Control", DiagnosticStatus::OK);
      },
      10.0))
      << "the published statuses were not aggregated";
  EXPECT_TRUE(l.has("/Sensors/sonar_crisp: sonar sectors", DiagnosticStatus::WARN));
  const DiagnosticStatus& item = l.last["/Sensors/sonar_crisp: sonar sectors"];
  EXPECT_EQ(item.message, "sector 3 silent");
  EXPECT_EQ(item.hardware_id, "test");
  ASSERT_EQ(item.values.size(), 1u);
  EXPECT_EQ(item.values[0].value, "7");
  EXPECT_TRUE(l.has("/Control/brian: Mr. BRIAN", DiagnosticStatus::OK));
  EXPECT_TRUE(l.has("/Control/airboard: AIRBoard link", DiagnosticStatus::OK));
  EXPECT_TRUE(l.has("/Other/visitor: FollowMe visitor", DiagnosticStatus::OK));  // matched by no analyzer
  EXPECT_TRUE(wait_for([&] { return l.top.level == DiagnosticStatus::WARN; }, 3.0));
  EXPECT_EQ(l.top.message, "Warning: /Sensors");

  // Silence: after the sensors' 2 s the sonar is stale; /Control (5 s) not yet.
  const ros::WallTime silent = ros::WallTime::now();
  ASSERT_TRUE(wait_for([&] { return l.has("/Sensors", DiagnosticStatus::STALE); }, 6.0)) << "no stale sonar";
  EXPECT_GT((ros::WallTime::now() - silent).toSec(), 1.5);
  EXPECT_TRUE(l.has("/Sensors/sonar_crisp: sonar sectors", DiagnosticStatus::STALE));
  EXPECT_TRUE(l.has("/Control", DiagnosticStatus::OK));
  EXPECT_TRUE(wait_for([&] { return l.top.level == DiagnosticStatus::STALE; }, 3.0));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "diagnostic_aggregator_rostest");
  return RUN_ALL_TESTS();
}
