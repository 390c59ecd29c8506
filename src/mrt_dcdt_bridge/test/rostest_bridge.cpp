// rostest: legacy Agora -> bridge -> ROS with every field intact; ROS ->
// bridge -> legacy Agora; no echo; diagnostics.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <mrt_msgs/Percept.h>

#include <atomic>
#include <map>
#include <mutex>

#include "mrt_common_ros/rostest_helpers.h"
#include "mrt_dcdt/xml_message.h"
#include "mrt_dcdt/testing/process.h"

using namespace mrt::dcdt;

namespace {

std::string g_inner_dir;

using mrt::ros_common::spin_for;
using mrt::ros_common::wait_for;

TEST(Bridge, LegacyPerceptsArriveAsRosMessagesWithEveryField) {
  ros::NodeHandle nh;
  std::mutex m;
  std::vector<mrt_msgs::Percept> got;
  auto sub = nh.subscribe<mrt_msgs::Percept>("vision/percepts", 10, [&](const mrt_msgs::Percept::ConstPtr& p) {
    std::lock_guard<std::mutex> l(m);
    got.push_back(*p);
  });
  ASSERT_TRUE(wait_for([&] { std::lock_guard<std::mutex> l(m); return !got.empty(); }, 20.0));
  std::lock_guard<std::mutex> l(m);
  const auto& p = got.front();
  // Expected values written by hand from test/data/percept_ball.xml (the DTD
  // defaults variability 0 and reliability 1 where the file omits them).
  EXPECT_EQ(p.header.stamp.sec, 1700000000u);
  EXPECT_EQ(p.header.stamp.nsec, 250000000u);
  EXPECT_EQ(p.header.frame_id, "base_link");
  EXPECT_EQ(p.sensor, "omnivision");
  EXPECT_EQ(p.robot, "ianus3");
  ASSERT_EQ(p.objects.size(), 3u);
  EXPECT_EQ(p.objects[0].name, "ball");
  EXPECT_EQ(p.objects[0].membership_class, "Ball");
  ASSERT_EQ(p.objects[0].attributes.size(), 3u);
  struct Want {
    const char* name;
    double value;
    const char* symbol;
    double variability, reliability;
  };
  const Want ball[3] = {{"distance", 2.4, "", 0.1, 0.9}, {"bearing", -0.35, "", 0.02, 0.9}, {"colour", 0, "orange", 0, 1}};
  for (int j = 0; j < 3; ++j) {
    const auto& a = p.objects[0].attributes[j];
    EXPECT_EQ(a.name, ball[j].name);
    EXPECT_EQ(a.value, ball[j].value) << a.name;  // bit-exact: the same decimal read by strtod
    EXPECT_EQ(a.symbol, ball[j].symbol);
    EXPECT_EQ(a.variability, ball[j].variability) << a.name;
    EXPECT_EQ(a.reliability, ball[j].reliability) << a.name;
  }
  EXPECT_EQ(p.objects[1].name, "goal_yellow");
  EXPECT_EQ(p.objects[1].membership_class, "Goal");
  ASSERT_EQ(p.objects[1].attributes.size(), 1u);
  EXPECT_EQ(p.objects[1].attributes[0].name, "distance");
  EXPECT_EQ(p.objects[1].attributes[0].value, 4.75);
  EXPECT_EQ(p.objects[1].attributes[0].symbol, "");
  EXPECT_EQ(p.objects[1].attributes[0].variability, 0.0);
  EXPECT_EQ(p.objects[1].attributes[0].reliability, 1.0);
  EXPECT_EQ(p.objects[2].name, "nothing_known");
  EXPECT_EQ(p.objects[2].membership_class, "Obstacle");
  EXPECT_TRUE(p.objects[2].attributes.empty());
}

mrt_msgs::Percept SamplePercept() {
  mrt_msgs::Percept p;
  p.header.stamp = ros::Time(1234, 567890123);
  p.header.frame_id = "robot1/base_link";
  p.sensor = "sonar";
  p.robot = "roby";
  mrt_msgs::PerceptObject o;
  o.name = "wall<1>";
  o.membership_class = "Wall";
  mrt_msgs::Attribute a;
  a.name = "distance";
  a.value = 0.1 + 0.2;
  a.variability = 0.05;
  a.reliability = 0.75;
  o.attributes.push_back(a);
  a.name = "side";
  a.value = 0;
  a.symbol = "left & front";
  o.attributes.push_back(a);
  p.objects.push_back(o);
  return p;
}

std::string Unescape(const std::string& s) {
  std::string o;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      o += s[i + 1] == 'n' ? '\n' : s[i + 1];
      ++i;
    } else {
      o += s[i];
    }
  }
  return o;
}

TEST(Bridge, RosPerceptReachesTheLegacyAgora) {
  const std::string out = g_inner_dir + "_motion.txt";
  mrt::dcdt::test_support::Process legacy({DCDT_AGORA, "--inner-dir", g_inner_dir, "--subscribe", "MSG_TO_MOTION", "--expect", "1",
                             "--duration", "30", "--out", out});
  ASSERT_TRUE(wait_for([&] { return mrt::dcdt::test_support::slurp(out).find("ready") != std::string::npos; }, 10.0));
  ros::NodeHandle nh;
  auto pub = nh.advertise<mrt_msgs::Percept>("motion/percepts", 10);
  const auto sent = SamplePercept();
  ASSERT_TRUE(wait_for(
      [&] {
        pub.publish(sent);
        ros::WallDuration(0.1).sleep();
        return !mrt::dcdt::test_support::lines(out, "recv ").empty();
      },
      20.0));
  auto line = mrt::dcdt::test_support::lines(out, "recv ")[0];
  EXPECT_EQ(mrt::dcdt::test_support::field(line, "type"), "32");
  EXPECT_EQ(mrt::dcdt::test_support::field(line, "warranty"), "2");
  const XmlMessage x = decode_xml(Unescape(mrt::dcdt::test_support::field(line, "payload")));
  EXPECT_EQ(x.sec, 1234);
  EXPECT_EQ(x.nsec, 567890123u);
  EXPECT_EQ(x.frame, "robot1/base_link");
  EXPECT_EQ(x.sensor, "sonar");
  EXPECT_EQ(x.robot, "roby");
  ASSERT_EQ(x.objects.size(), 1u);
  EXPECT_EQ(x.objects[0].name, "wall<1>");
  EXPECT_EQ(x.objects[0].membership_class, "Wall");
  ASSERT_EQ(x.objects[0].attributes.size(), 2u);
  EXPECT_EQ(x.objects[0].attributes[0].value, 0.1 + 0.2);
  EXPECT_EQ(x.objects[0].attributes[0].variability, 0.05);
  EXPECT_EQ(x.objects[0].attributes[0].reliability, 0.75);
  EXPECT_EQ(x.objects[0].attributes[1].symbol, "left & front");
  EXPECT_EQ(legacy.wait(10000), 0);
}

TEST(Bridge, NoEchoOnATopicMappedBothWays) {
  // A legacy Agora listening to MSG_FROM_MAP: the bridge must forward our
  // three messages to DCDT (else "no echo" would hold trivially).
  const std::string out = g_inner_dir + "_map.txt";
  mrt::dcdt::test_support::Process legacy({DCDT_AGORA, "--inner-dir", g_inner_dir, "--subscribe", "MSG_FROM_MAP", "--expect", "3",
                             "--linger", "700", "--duration", "30", "--out", out});
  ASSERT_TRUE(wait_for([&] { return mrt::dcdt::test_support::slurp(out).find("ready") != std::string::npos; }, 10.0));
  ros::NodeHandle nh;
  std::atomic<int> seen{0};
  auto sub = nh.subscribe<mrt_msgs::Percept>("map/percepts", 10, [&](const mrt_msgs::Percept::ConstPtr&) { ++seen; });
  auto pub = nh.advertise<mrt_msgs::Percept>("map/percepts", 10);
  // Wait until the bridge is connected to our publisher.
  ASSERT_TRUE(wait_for([&] { return pub.getNumSubscribers() >= 2 && sub.getNumPublishers() >= 2; }, 10.0));
  for (int i = 0; i < 3; ++i) pub.publish(SamplePercept());
  spin_for(1.5);
  EXPECT_EQ(seen.load(), 3);  // ours only: the bridge did not send them back
  EXPECT_EQ(legacy.wait(15000), 0) << mrt::dcdt::test_support::slurp(out);
  const auto recv = mrt::dcdt::test_support::lines(out, "recv ");
  ASSERT_EQ(recv.size(), 3u) << mrt::dcdt::test_support::slurp(out);  // each exactly once (the linger would show more)
  for (const auto& l : recv) {
    EXPECT_EQ(mrt::dcdt::test_support::field(l, "type"), "23");
    EXPECT_NE(mrt::dcdt::test_support::field(l, "payload").find("robot1/base_link"), std::string::npos) << l;
  }
}

TEST(Bridge, DiagnosticsReportPeersAndTraffic) {
  ros::NodeHandle nh;
  std::mutex m;
  diagnostic_msgs::DiagnosticStatus last;
  bool have = false;
  auto sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& a) {
        for (const auto& s : a->status) {
          if (s.name.find("DCDT Agora") == std::string::npos) continue;
          std::lock_guard<std::mutex> l(m);
          last = s;
          have = true;
        }
      });
  auto value = [&](const std::string& k) {
    for (const auto& kv : last.values)
      if (kv.key == k) return kv.value;
    return std::string();
  };
  ASSERT_TRUE(wait_for(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return have && !value("in.18").empty() && value("inner_peers") != "0";
      },
      10.0));
  std::lock_guard<std::mutex> l(m);
  EXPECT_EQ(value("parse_errors"), "0");
  EXPECT_EQ(value("conversion_errors"), "0");
  EXPECT_EQ(value("dropped"), "0");
  EXPECT_EQ(value("mailbox_dropped"), "0");
  EXPECT_EQ(value("hop_limited"), "0");
  EXPECT_EQ(value("inner_errors"), "0");
  EXPECT_EQ(value("channel_errors"), "0");  // STANDALONE: no channels at all
  EXPECT_EQ(value("channels_connected"), "0/0");
  EXPECT_GT(std::stoi(value("in.18")), 0);
  EXPECT_EQ(value("out.23"), "3");            // the three of NoEchoOnATopicMappedBothWays
  EXPECT_GE(std::stoi(value("out.32")), 1);   // RosPerceptReachesTheLegacyAgora
  EXPECT_FALSE(value("peers_seen").empty());  // at least the legacy vision Agora
}

TEST(Bridge, MalformedDcdtPayloadIsDroppedCountedAndTheNodeKeepsRunning) {
  const std::string out = g_inner_dir + "_bad.txt";
  mrt::dcdt::test_support::Process bad({DCDT_AGORA, "--inner-dir", g_inner_dir, "--publish", "MSG_FROM_BRIAN", "--text",
                          "<message time='1'><object name='x'></message> {i}", "--count", "3", "--rate", "50",
                          "--wait-peers", "1", "--duration", "10", "--out", out});
  EXPECT_EQ(bad.wait(15000), 0);
  // Valid XML, but percepts where the mapping wants commands: the conversion
  // to ROS fails; counted apart, and never as traffic in.
  const std::string out2 = g_inner_dir + "_shape.txt";
  mrt::dcdt::test_support::Process shape({DCDT_AGORA, "--inner-dir", g_inner_dir, "--publish", "MSG_FROM_BRIAN", "--xml",
                            DCDT_TEST_DATA "/percept_ball.xml", "--count", "2", "--rate", "50", "--wait-peers", "1",
                            "--duration", "10", "--out", out2});
  EXPECT_EQ(shape.wait(15000), 0);
  ros::NodeHandle nh;
  std::mutex m;
  std::map<std::string, std::string> values;
  auto sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& a) {
        for (const auto& s : a->status) {
          if (s.name.find("DCDT Agora") == std::string::npos) continue;
          std::lock_guard<std::mutex> l(m);
          for (const auto& kv : s.values) values[kv.key] = kv.value;
          values["level"] = std::to_string(s.level);
        }
      });
  ASSERT_TRUE(wait_for(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return values.count("parse_errors") && values["parse_errors"] == "3" && values["conversion_errors"] == "2";
      },
      10.0));
  std::lock_guard<std::mutex> l(m);
  EXPECT_EQ(values["level"], "1");  // WARN
  EXPECT_NE(values["last_error"].find("is not a Command"), std::string::npos) << values["last_error"];
  EXPECT_EQ(values.count("in.25"), 0u);  // nothing of type 25 reached ROS
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "dcdt_bridge_test");
  ros::NodeHandle pnh("~");
  pnh.param<std::string>("inner_dir", g_inner_dir, "/tmp/dcdt_rostest");
  return RUN_ALL_TESTS();
}
