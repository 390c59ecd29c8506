// rostest of brian_node on examples/harvesting: crisp data in, the
// commands worked by hand in the rule base's README out; introspection; a
// good and a bad ~reload (the bad one keeps the running rule base); the
// CANDO threshold through dynamic_reconfigure.
#include <gtest/gtest.h>
#include <mrt_msgs/BrianIntrospection.h>
#include <mrt_msgs/CommandArray.h>
#include <mrt_msgs/CrispDataArray.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <cmath>
#include <map>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Reconfigure.h>

#include "mrt_common_ros/rostest_helpers.h"

namespace {

class Harness {
 public:
  Harness() {
    pub_ = nh_.advertise<mrt_msgs::CrispDataArray>("crisp_data", 10);
    sub_ = nh_.subscribe("commands", 10, &Harness::on_commands, this);
    intro_sub_ = nh_.subscribe("brian/introspection", 10, &Harness::on_intro, this);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
    while ((pub_.getNumSubscribers() == 0 || sub_.getNumPublishers() == 0 || intro_sub_.getNumPublishers() == 0) &&
           ros::WallTime::now() < deadline) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
  }

  // Publishes one cycle's data and returns the commands of the reply.
  std::map<std::string, double> cycle(const std::map<std::string, double>& data) {
    mrt_msgs::CrispDataArray m;
    m.header.stamp = ros::Time::now();
    for (const auto& [name, value] : data) {
      mrt_msgs::CrispData d;
      d.name = name;
      d.value = value;
      d.reliability = 1.0;
      m.data.push_back(d);
    }
    const std::size_t before = received_;
    pub_.publish(m);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
    while (received_ == before && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      ros::WallDuration(0.002).sleep();
    }
    EXPECT_GT(received_, before) << "no commands";
    // Give the introspection message (published right after) a moment.
    const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(0.2);
    while (ros::WallTime::now() < until) {
      ros::spinOnce();
      ros::WallDuration(0.005).sleep();
    }
    return last_;
  }

  // Publishes without waiting for a reply (fixed-rate mode).
  void send(const std::map<std::string, double>& data) {
    mrt_msgs::CrispDataArray m;
    for (const auto& [name, value] : data) {
      mrt_msgs::CrispData d;
      d.name = name;
      d.value = value;
      d.reliability = 1.0;
      m.data.push_back(d);
    }
    pub_.publish(m);
  }
  std::size_t received() const { return received_; }
  const std::map<std::string, double>& last() const { return last_; }

  mrt_msgs::BrianIntrospection intro_;
  bool have_intro_ = false;

 private:
  void on_commands(const mrt_msgs::CommandArray::ConstPtr& m) {
    last_.clear();
    for (const auto& c : m->commands) last_[c.name] = c.value;
    ++received_;
  }
  void on_intro(const mrt_msgs::BrianIntrospection::ConstPtr& m) {
    intro_ = *m;
    have_intro_ = true;
  }
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Subscriber sub_, intro_sub_;
  std::map<std::string, double> last_;
  std::size_t received_ = 0;
};

const std::map<std::string, double> kAutoFarTarget = {
    {"Status", 1},        {"TargetVisible", 1}, {"TargetDistance", 200}, {"TargetAngle", 0},
    {"Battery", 100},     {"Grasping", 0},      {"ObstacleDistance", 500}, {"ObstacleAngle", 0},
    {"HomeDistance", 300}, {"HomeAngle", 180}};

}  // namespace

TEST(Harvesting, ReactsToCrispData) {
  Harness h;
  // Target far ahead, nothing in the way: GoToTarget FAST (75 cm/s), NORTH (0 deg).
  auto c = h.cycle(kAutoFarTarget);
  ASSERT_EQ(c.count("SpeedModule"), 1u);
  EXPECT_NEAR(c["SpeedModule"], 75.0, 1e-6);
  EXPECT_NEAR(c["SpeedAngle"], 0.0, 1e-6);
  EXPECT_EQ(c.count("Grasp"), 0u);

  // Obstacle 50 cm ahead: AvoidObstacle (level 2) deletes both and proposes
  // VERY_SLOW (10 cm/s) and WEST (90 deg).
  auto in = kAutoFarTarget;
  in["ObstacleDistance"] = 50;
  c = h.cycle(in);
  EXPECT_NEAR(c["SpeedModule"], 10.0, 1e-6);
  EXPECT_NEAR(c["SpeedAngle"], 90.0, 1e-6);
  ASSERT_TRUE(h.have_intro_);
  bool avoid_active = false;
  for (const auto& b : h.intro_.behaviors)
    if (b.name == "AvoidObstacle") {
      avoid_active = b.active;
      EXPECT_NEAR(b.cando, 0.5, 1e-9);
      EXPECT_NEAR(b.weight, 0.5, 1e-9);
    }
  EXPECT_TRUE(avoid_active);
  ASSERT_EQ(h.intro_.proposals.size(), 2u);
  for (const auto& p : h.intro_.proposals) EXPECT_EQ(p.behavior, "AvoidObstacle");

  // Manual mode (§10.4.10): only ManualMove, straight from the remote.
  c = h.cycle({{"Status", 0}, {"RemoteSpeed", 80}, {"RemoteAngle", 90}});
  EXPECT_NEAR(c["SpeedModule"], 75.0, 1e-6);
  EXPECT_NEAR(c["SpeedAngle"], 90.0, 1e-6);
}

TEST(Harvesting, ReloadKeepsTheRuleBaseOnError) {
  Harness h;
  ros::NodeHandle nh;
  ros::ServiceClient reload = nh.serviceClient<std_srvs::Trigger>("brian/reload");
  ASSERT_TRUE(reload.waitForExistence(ros::Duration(20.0)));
  std::string good;
  ASSERT_TRUE(ros::param::get("~config", good));

  std_srvs::Trigger t;
  ros::param::set("brian/config", good + "/does_not_exist");
  ASSERT_TRUE(reload.call(t));
  EXPECT_FALSE(t.response.success);
  EXPECT_NE(t.response.message.find("keeping the previous rule base"), std::string::npos) << t.response.message;
  auto c = h.cycle(kAutoFarTarget);
  EXPECT_NEAR(c["SpeedModule"], 75.0, 1e-6);

  ros::param::set("brian/config", good);
  ASSERT_TRUE(reload.call(t));
  EXPECT_TRUE(t.response.success) << t.response.message;
  c = h.cycle(kAutoFarTarget);
  EXPECT_NEAR(c["SpeedModule"], 75.0, 1e-6);
}

// dynamic_reconfigure of the CANDO threshold (§10.4.4: a behaviour is
// active when its CANDO is above it). An obstacle at 50 cm is NEAREST
// (TRA 0 0.1 40 60: (60 - 50) / 20) and NEAR (TRA 40 60 100 120:
// (50 - 40) / 20) to degree 0.5, so AvoidObstacle's CANDO, (AND Auto
// ObstacleClose), is 0.5: active under 0.49, not under 0.6. GoToTarget's
// CANDO is 1 (Auto, target seen, batteries almost full), GoToHome's WANT 0:
// without AvoidObstacle the commands are the far target's, 75 cm/s at 0 deg
// (ReactsToCrispData), with it 10 cm/s at 90 deg.
bool set_threshold(double value, double* applied) {
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::DoubleParameter p;
  p.name = "threshold";
  p.value = value;
  srv.request.config.doubles.push_back(p);
  if (!ros::service::call("brian/set_parameters", srv)) return false;
  for (const auto& d : srv.response.config.doubles)
    if (d.name == "threshold") *applied = d.value;
  return true;
}

bool active(const mrt_msgs::BrianIntrospection& m, const std::string& behavior) {
  for (const auto& b : m.behaviors)
    if (b.name == behavior) return b.active;
  ADD_FAILURE() << "no behaviour " << behavior;
  return false;
}

TEST(Harvesting, ReconfiguredThresholdChangesWhichBehavioursAct) {
  Harness h;
  ASSERT_TRUE(ros::service::waitForService("brian/set_parameters", ros::Duration(20)));
  auto in = kAutoFarTarget;
  in["ObstacleDistance"] = 50;
  auto c = h.cycle(in);
  EXPECT_NEAR(c["SpeedModule"], 10.0, 1e-6);
  EXPECT_NEAR(c["SpeedAngle"], 90.0, 1e-6);
  EXPECT_TRUE(active(h.intro_, "AvoidObstacle"));

  double applied = -1;
  ASSERT_TRUE(set_threshold(0.6, &applied));
  EXPECT_DOUBLE_EQ(applied, 0.6);
  double param = -1;
  EXPECT_TRUE(ros::param::get("brian/threshold", param));  // the server mirrors it
  EXPECT_DOUBLE_EQ(param, 0.6);
  h.have_intro_ = false;
  c = h.cycle(in);
  EXPECT_NEAR(c["SpeedModule"], 75.0, 1e-6);
  EXPECT_NEAR(c["SpeedAngle"], 0.0, 1e-6);
  ASSERT_TRUE(h.have_intro_);
  EXPECT_FALSE(active(h.intro_, "AvoidObstacle"));
  EXPECT_TRUE(active(h.intro_, "GoToTarget"));

  ASSERT_TRUE(set_threshold(0.49, &applied));
  c = h.cycle(in);
  EXPECT_NEAR(c["SpeedModule"], 10.0, 1e-6);
  EXPECT_NEAR(c["SpeedAngle"], 90.0, 1e-6);
  EXPECT_TRUE(active(h.intro_, "AvoidObstacle"));
}

// Run by harvesting_rate.test (~rate 20 Hz): one input, a cycle every 50 ms.
TEST(Harvesting, FixedRate) {
  Harness h;
  h.send(kAutoFarTarget);
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
  while (h.received() == 0 && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  ASSERT_GT(h.received(), 0u);
  const std::size_t first = h.received();
  const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(1.0);
  while (ros::WallTime::now() < until) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  const std::size_t cycles = h.received() - first;
  EXPECT_GE(cycles, 12u);  // 20 expected in 1 s; slack for a loaded machine
  EXPECT_LE(cycles, 25u);
  ASSERT_EQ(h.last().count("SpeedModule"), 1u);
  EXPECT_NEAR(h.last().at("SpeedModule"), 75.0, 1e-6);
}

// Run by input_timeout.test (~rate 20 Hz, ~input_timeout 0.3 s,
// ~safe_commands {SpeedAngle: 45}): on data, the hand-computed commands of
// kAutoFarTarget (SpeedModule 75, SpeedAngle 0); 0.3 s after the data stop,
// the safe commands (SpeedModule 0, SpeedAngle 45, Grasp 0) and a WARN in
// /diagnostics; on new data, 75 and 0 again and the WARN clears.
TEST(Harvesting, InputTimeout) {
  using mrt::ros_common::spin_for;
  using mrt::ros_common::wait_for;
  Harness h;
  ros::NodeHandle nh;
  diagnostic_msgs::DiagnosticStatus status;
  bool have_status = false;
  auto diag_sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
        for (const auto& s : m->status)
          if (s.name.find("Mr. BRIAN") != std::string::npos) {
            status = s;
            have_status = true;
          }
      });
  auto fresh = [&] {
    return h.last().count("SpeedModule") && std::abs(h.last().at("SpeedModule") - 75.0) < 1e-6;
  };
  // Keep the data coming for a while (every 0.1 s < 0.3 s).
  for (int i = 0; i < 10; ++i) {
    h.send(kAutoFarTarget);
    spin_for(0.1);
  }
  ASSERT_TRUE(wait_for(fresh, 2.0));
  EXPECT_NEAR(h.last().at("SpeedAngle"), 0.0, 1e-6);
  // Stop: after 0.3 s the safe commands.
  auto safe = [&] {
    return h.last().count("SpeedModule") && h.last().at("SpeedModule") == 0.0 && h.last().count("SpeedAngle") &&
           h.last().at("SpeedAngle") == 45.0;
  };
  ASSERT_TRUE(wait_for(safe, 3.0));
  EXPECT_EQ(h.last().count("Grasp"), 1u);
  EXPECT_EQ(h.last().at("Grasp"), 0.0);
  ASSERT_TRUE(wait_for([&] { return have_status && status.level == diagnostic_msgs::DiagnosticStatus::WARN; }, 5.0));
  EXPECT_NE(status.message.find("safe commands"), std::string::npos) << status.message;
  // Data again (every 0.1 s): the rule base's answer, and the warning clears.
  bool ok = false;
  for (int i = 0; i < 50 && !(ok && fresh()); ++i) {
    h.send(kAutoFarTarget);
    spin_for(0.1);
    ok = status.level == diagnostic_msgs::DiagnosticStatus::OK;
  }
  EXPECT_TRUE(fresh());
  EXPECT_TRUE(ok) << status.message;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "brian_harvesting_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
