// A bag with bad stamps replayed through mice_odometry_node and brian_node
// (bad_stamps.test). The test writes two bags with rosbag's C++ API, each
// 200 mice readings and 200 crisp data messages at 50 Hz (recorded in
// arrival order), and replays them in that order:
//
// * clean: stamps 1000 + 0.02 k, each reading 1 cm straight ahead (both
//   mice of test/data/manual_mice.yaml: dy = 100 counts at 10000 counts/m),
//   crisp data Status 0, RemoteSpeed 40 + 10 (k % 5), RemoteAngle
//   60 + 20 (k % 4) (examples/harvesting);
// * bad: the same on a new time base (100 + 0.02 k: 900 s back, a bag loop:
//   the odometry resets), with messages 50, 55, 60 duplicated (same stamp),
//   70/71 and 80/81 swapped (the later one first), 100-119 missing (a
//   0.42 s gap), and every stamp from 130 on 2 s later (a forward jump).
//
// Worked out by hand: the odometry drops 3 duplicates and the 2 older ones of
// the swapped pairs (2 cm lost) and loses the 20 missing readings (20 cm):
// final x = 2.00 - 0.22 = 1.78 m against 2.00 m clean, heading 0; two gaps
// longer than ~stale_timeout (0.25 s): at 120 and at 130. Mr. BRIAN drops
// the same 3 + 2 messages, counts the same two gaps (~stamp_gap 0.25 s) and
// one jump back, and from message 130 on answers exactly as in the clean run.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <mrt_msgs/MiceReading.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "mrt_common_ros/rostest_helpers.h"

using mrt::ros_common::wait_for;

namespace {

constexpr int kMessages = 200;

ros::Time stamp_of(double base, int k) { return ros::Time(base + 0.02 * k + (base < 500 && k >= 130 ? 2.0 : 0.0)); }

mrt_msgs::MiceReading reading(const ros::Time& t) {
  mrt_msgs::MiceReading r;
  r.header.stamp = t;
  r.left.dy = r.right.dy = 100;
  return r;
}

mrt_msgs::CrispDataArray crisp(const ros::Time& t, int k) {
  mrt_msgs::CrispDataArray m;
  m.header.stamp = t;
  const std::map<std::string, double> data{
      {"Status", 0.0}, {"RemoteSpeed", 40.0 + 10.0 * (k % 5)}, {"RemoteAngle", 60.0 + 20.0 * (k % 4)}};
  for (const auto& [name, value] : data) {
    mrt_msgs::CrispData d;
    d.name = name;
    d.value = value;
    d.reliability = 1.0;
    m.data.push_back(d);
  }
  return m;
}

// The order in which the messages reach the bag (k of each), bad or clean.
std::vector<int> arrival_order(bool bad) {
  std::vector<int> order;
  for (int k = 0; k < kMessages; ++k) {
    if (bad && k >= 100 && k < 120) continue;  // lost
    if (bad && (k == 70 || k == 80)) continue;  // comes after k + 1
    order.push_back(k);
    if (bad && (k == 71 || k == 81)) order.push_back(k - 1);
    if (bad && (k == 50 || k == 55 || k == 60)) order.push_back(k);  // duplicated
  }
  return order;
}

void write_bag(const std::string& path, bool bad) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const double base = bad ? 100.0 : 1000.0;
  ros::Time rec(5000.0);  // recording time: arrival order
  for (int k : arrival_order(bad)) {
    rec += ros::Duration(0.001);
    bag.write("mice", rec, reading(stamp_of(base, k)));
    rec += ros::Duration(0.001);
    bag.write("crisp_data", rec, crisp(stamp_of(base, k), k));
  }
}

class Replay {
 public:
  Replay() {
    mice_pub_ = nh_.advertise<mrt_msgs::MiceReading>("mice", 100);
    crisp_pub_ = nh_.advertise<mrt_msgs::CrispDataArray>("crisp_data", 100);
    odom_sub_ = nh_.subscribe<nav_msgs::Odometry>("odom", 100, [this](const nav_msgs::Odometry::ConstPtr& o) {
      odom_ = *o;
      ++n_odom_;
    });
    cmd_sub_ = nh_.subscribe<mrt_msgs::CommandArray>("commands", 100, [this](const mrt_msgs::CommandArray::ConstPtr& c) {
      commands_[c->header.stamp.toSec()] = *c;
      ++n_cmd_;
    });
    diag_sub_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 50, [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& d) {
          for (const auto& s : d->status)
            for (const auto& kv : s.values) diag_[s.name + "/" + kv.key] = kv.value;
        });
  }
  bool connected() {
    return wait_for([&] {
      return mice_pub_.getNumSubscribers() > 0 && crisp_pub_.getNumSubscribers() > 0 &&
             odom_sub_.getNumPublishers() > 0 && cmd_sub_.getNumPublishers() > 0;
    }, 20.0);
  }
  // Publishes the bag's messages in their recorded order, each after the
  // nodes have answered the previous one (or dropped it: 0.3 s).
  void play(const std::string& path) {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    for (const rosbag::MessageInstance& m : rosbag::View(bag)) {
      if (auto r = m.instantiate<mrt_msgs::MiceReading>()) {
        const long n = n_odom_;
        mice_pub_.publish(*r);
        wait_for([&] { return n_odom_ > n; }, 0.3, 0.001);
      } else if (auto c = m.instantiate<mrt_msgs::CrispDataArray>()) {
        const long n = n_cmd_;
        crisp_pub_.publish(*c);
        wait_for([&] { return n_cmd_ > n; }, 0.3, 0.001);
      }
    }
  }
  // The diagnostics value `key` of the status whose name contains `name`.
  std::string diag(const std::string& name, const std::string& key) const {
    for (const auto& [k, v] : diag_)
      if (k.find(name) != std::string::npos && k.size() > key.size() &&
          k.compare(k.size() - key.size() - 1, std::string::npos, "/" + key) == 0)
        return v;
    return "";
  }

  ros::NodeHandle nh_;
  ros::Publisher mice_pub_, crisp_pub_;
  ros::Subscriber odom_sub_, cmd_sub_, diag_sub_;
  nav_msgs::Odometry odom_;
  long n_odom_ = 0, n_cmd_ = 0;
  std::map<double, mrt_msgs::CommandArray> commands_;  // by stamp
  std::map<std::string, std::string> diag_;
};

}  // namespace

TEST(BadStamps, CountedAndTheEstimateRecovers) {
  char tmpl[] = "/tmp/mrt_bad_stamps_XXXXXX";
  ASSERT_NE(mkdtemp(tmpl), nullptr);
  const std::string dir = tmpl;
  const std::string clean_bag = dir + "/bad_stamps_clean.bag", bad_bag = dir + "/bad_stamps_bad.bag";
  write_bag(clean_bag, false);
  write_bag(bad_bag, true);
  Replay r;
  ASSERT_TRUE(r.connected());

  r.play(clean_bag);
  ASSERT_EQ(r.n_odom_, kMessages);
  ASSERT_EQ(r.n_cmd_, kMessages);
  const double clean_x = r.odom_.pose.pose.position.x;
  EXPECT_NEAR(clean_x, 2.0, 1e-9);
  const std::map<double, mrt_msgs::CommandArray> clean_cmd = r.commands_;

  r.play(bad_bag);
  // 200 - 20 missing - 2 out of order (the 3 duplicates dropped as well).
  EXPECT_EQ(r.n_odom_, kMessages + 178);
  EXPECT_EQ(r.n_cmd_, kMessages + 178);
  const double lost = 0.22;  // 2 out-of-order + 20 missing readings of 1 cm
  EXPECT_NEAR(r.odom_.pose.pose.position.x, clean_x - lost, 1e-9);
  EXPECT_LT(std::fabs(r.odom_.pose.pose.position.x - clean_x), lost + 1e-6);
  EXPECT_NEAR(r.odom_.pose.pose.position.y, 0.0, 1e-9);
  EXPECT_NEAR(r.odom_.twist.twist.linear.x, 0.5, 1e-6);  // 1 cm in 20 ms again after the gaps

  // Mr. BRIAN after the bad section answers as in the clean run.
  int compared = 0;
  for (int k = 130; k < kMessages; ++k) {
    const auto b = r.commands_.find(stamp_of(100.0, k).toSec());
    const auto c = clean_cmd.find(stamp_of(1000.0, k).toSec());
    ASSERT_TRUE(b != r.commands_.end() && c != clean_cmd.end()) << k;
    ASSERT_EQ(b->second.commands.size(), c->second.commands.size());
    for (std::size_t i = 0; i < b->second.commands.size(); ++i) {
      EXPECT_EQ(b->second.commands[i].name, c->second.commands[i].name);
      EXPECT_DOUBLE_EQ(b->second.commands[i].value, c->second.commands[i].value) << k;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 70);

  // One more message each, 1.1 s later, so that Mr. BRIAN (which updates
  // its diagnostics on cycles) publishes them.
  ros::WallDuration(1.1).sleep();
  r.mice_pub_.publish(reading(stamp_of(100.0, kMessages)));
  r.crisp_pub_.publish(crisp(stamp_of(100.0, kMessages), kMessages));
  auto counted = [&](const char* node, const char* key, const char* value) {
    EXPECT_TRUE(wait_for([&] { return r.diag(node, key) == value; }, 5.0))
        << node << " " << key << ": " << r.diag(node, key);
  };
  counted("mice odometry", "duplicate stamps (dropped)", "3");
  counted("mice odometry", "out-of-order stamps (dropped)", "2");
  counted("mice odometry", "stamp gaps (no twist)", "2");
  counted("mice odometry", "resets (time jumped back)", "1");
  counted("Mr. BRIAN", "duplicate stamps (dropped)", "3");
  counted("Mr. BRIAN", "out-of-order stamps (dropped)", "2");
  counted("Mr. BRIAN", "stamp gaps", "2");
  counted("Mr. BRIAN", "stamp jumps back (new time base)", "1");
  std::remove(clean_bag.c_str());
  std::remove(bad_bag.c_str());
  rmdir(dir.c_str());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "bad_stamps_test");
  return RUN_ALL_TESTS();
}
