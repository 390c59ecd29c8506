// rostest of murea_node's dynamic_reconfigure (test/murea_reconfigure.test):
// the laser robot of murea_laser.test stands at the ellipse's first pose
// (8.7, 3, pi/2), a scan every 0.1 s, the node tracking from its initial
// pose there. The server starts from the node's parameters (accuracy_xy
// 0.04, timeout 0.1, tolerance_wall [0.06, 0.02]), not the cfg's defaults;
// then, through amcl/set_parameters, each change shows in what the node
// publishes:
//   - accuracy 0.04 m / 1 deg -> 0.2 m / 0.1 rad: diagnostics report the
//     tracker's new accuracy, and its windowed searches evaluate fewer
//     cells (a lattice 5 times coarser in x and y);
//   - timeout 0.1 s -> 1 us and global_localization: the global searches
//     over the museum are cut short (diagnostics "complete" False; a
//     tracked search of some 65 cells ends before its first clock check);
//     back to 0.1 s and the truth as initialpose: complete again;
//   - the walls' base tolerance 0.06 m -> 0.3 m: many more lattice poses
//     tie with the best (particlecloud, the plateau) than with 0.06 m;
// and the estimate stays at the truth throughout.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "laser_sim.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_common_ros/rostest_helpers.h"

namespace {

using mrt::common::Pose2D;
using namespace mrt::murea::test;
namespace rc = mrt::ros_common;

struct Recorder {
  std::vector<std::map<std::string, std::string>> diags;  // murea's status, per /diagnostics message
  std::vector<std::size_t> cloud_sizes;
  std::vector<Pose2D> poses;
  dynamic_reconfigure::Config::ConstPtr updates;  // the latest ~parameter_updates
  void on_diag(const diagnostic_msgs::DiagnosticArray& m) {
    for (const auto& st : m.status) {
      if (st.name.find("murea") == std::string::npos) continue;
      std::map<std::string, std::string> d;
      for (const auto& kv : st.values) d[kv.key] = kv.value;
      diags.push_back(d);
    }
  }
  void on_cloud(const geometry_msgs::PoseArray& m) { cloud_sizes.push_back(m.poses.size()); }
  void on_pose(const geometry_msgs::PoseWithCovarianceStamped& m) { poses.push_back(rc::to_pose2d(m.pose.pose)); }
  void on_updates(const dynamic_reconfigure::Config::ConstPtr& c) { updates = c; }
};

double value_of(const dynamic_reconfigure::Config& c, const std::string& name) {
  for (const auto& d : c.doubles)
    if (d.name == name) return d.value;
  return NAN;
}

// amcl/set_parameters with the given doubles; the config the node applied.
dynamic_reconfigure::Config set(const std::map<std::string, double>& values) {
  dynamic_reconfigure::Reconfigure srv;
  for (const auto& [name, value] : values) {
    dynamic_reconfigure::DoubleParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.doubles.push_back(p);
  }
  EXPECT_TRUE(ros::service::call("amcl/set_parameters", srv));
  return srv.response.config;
}

double number(const std::map<std::string, std::string>& d, const std::string& key) {
  const auto it = d.find(key);
  return it == d.end() ? NAN : std::stod(it->second);
}

double median(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

class Fixture {
 public:
  Fixture(const std::string& world)
      : sim_(world, Pose2D(0.1, 0.0, 0.0)), odom_(ellipse_pose(0.0), 0.03, 0.03),
        robot_(sim_, odom_, "odom", "base_link", "laser") {
    ros::NodeHandle nh;
    subs_.push_back(nh.subscribe("/diagnostics", 20, &Recorder::on_diag, &rec));
    subs_.push_back(nh.subscribe("particlecloud", 20, &Recorder::on_cloud, &rec));
    subs_.push_back(nh.subscribe("amcl_pose", 20, &Recorder::on_pose, &rec));
    subs_.push_back(nh.subscribe("amcl/parameter_updates", 5, &Recorder::on_updates, &rec));
    initial_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", 1);
  }
  // The truth as initialpose (tracking from it again, whatever a cut
  // search did to the estimate).
  void reset_pose() {
    geometry_msgs::PoseWithCovarianceStamped m;
    m.header.stamp = ros::Time::now();
    m.header.frame_id = "map";
    m.pose.pose = rc::to_pose(ellipse_pose(0.0));
    m.pose.covariance[0] = m.pose.covariance[7] = 0.01;
    m.pose.covariance[35] = 0.01;
    initial_pub_.publish(m);
  }
  bool connected() const { return robot_.connected() && subs_[2].getNumPublishers() > 0; }
  // Scans of the robot standing at the start, every 0.1 s, until `pred`
  // holds or `seconds` have passed.
  template <class Pred>
  bool scan_until(Pred pred, double seconds) {
    return rc::wait_for(
        [&] {
          robot_.step(ellipse_pose(0.0), ros::Time::now());
          return pred();
        },
        seconds, 0.1);
  }
  // The diagnostics of frames searched with `accuracy_xy` (at least n of them).
  std::vector<std::map<std::string, std::string>> diags_with(double accuracy_xy, std::size_t n) {
    std::vector<std::map<std::string, std::string>> out;
    scan_until(
        [&] {
          out.clear();
          for (const auto& d : rec.diags)
            if (std::abs(number(d, "accuracy xy m") - accuracy_xy) < 1e-9) out.push_back(d);
          return out.size() >= n;
        },
        20.0);
    return out;
  }
  Recorder rec;

 private:
  LaserSim sim_;
  DriftingOdometry odom_;
  LaserRobot robot_;
  std::vector<ros::Subscriber> subs_;
  ros::Publisher initial_pub_;
};

// 2. the timeout: 1 us cuts the global searches short, 0.1 s lets the
// tracked ones complete.
void check_timeout(Fixture& f) {
  Recorder& rec = f.rec;
  const dynamic_reconfigure::Config applied =
      set({{"accuracy_xy", 0.04}, {"accuracy_theta", M_PI / 180}, {"timeout", 1e-6}});
  EXPECT_DOUBLE_EQ(value_of(applied, "timeout"), 1e-6);
  std_srvs::Empty global;
  EXPECT_TRUE(ros::service::call("global_localization", global));
  rec.diags.clear();
  EXPECT_TRUE(f.scan_until(
      [&] {
        return !rec.diags.empty() && number(rec.diags.back(), "timeout s") == 1e-6 &&
               rec.diags.back().count("complete") && rec.diags.back().at("complete") == "False";
      },
      20.0))
      << "the global searches were never cut short with a 1 us timeout";
  set({{"timeout", 0.1}});
  f.reset_pose();
  rec.diags.clear();
  EXPECT_TRUE(f.scan_until(
      [&] {
        return !rec.diags.empty() && number(rec.diags.back(), "timeout s") == 0.1 &&
               rec.diags.back().count("complete") && rec.diags.back().at("complete") == "True";
      },
      20.0))
      << "the searches stayed incomplete with the 0.1 s timeout back";
}

}  // namespace

TEST(MureaReconfigure, SearchParametersChangeWhatTheNodePublishes) {
  ros::NodeHandle pnh("~");
  std::string world;
  ASSERT_TRUE(pnh.getParam("world", world));
  Fixture f(world);
  Recorder& rec = f.rec;
  ASSERT_TRUE(rc::wait_for([&] { return f.connected(); }, 20.0));
  ASSERT_TRUE(ros::service::waitForService("amcl/set_parameters", ros::Duration(20)));
  ASSERT_TRUE(f.scan_until([&] { return !rec.poses.empty() && rec.updates; }, 30.0)) << "no amcl_pose";

  // the server's start: the node's parameters, the cfg's defaults elsewhere
  EXPECT_DOUBLE_EQ(value_of(*rec.updates, "accuracy_xy"), 0.04);
  EXPECT_DOUBLE_EQ(value_of(*rec.updates, "timeout"), 0.1);
  EXPECT_DOUBLE_EQ(value_of(*rec.updates, "tolerance_wall_base"), 0.06);
  EXPECT_DOUBLE_EQ(value_of(*rec.updates, "tolerance_wall_per_metre"), 0.02);
  EXPECT_DOUBLE_EQ(value_of(*rec.updates, "tolerance_goal_base"), 0.3);
  EXPECT_NEAR(value_of(*rec.updates, "accuracy_theta"), M_PI / 180, 1e-12);

  // 1. the accuracy: the diagnostics and the searches' cells
  const auto fine = f.diags_with(0.04, 3);
  ASSERT_GE(fine.size(), 3u) << "no diagnostics with accuracy xy 0.04";
  EXPECT_NEAR(number(fine.back(), "accuracy theta rad"), M_PI / 180, 1e-6);  // 6 digits
  const std::size_t clouds_fine = rec.cloud_sizes.size();
  dynamic_reconfigure::Config applied = set({{"accuracy_xy", 0.2}, {"accuracy_theta", 0.1}});
  EXPECT_DOUBLE_EQ(value_of(applied, "accuracy_xy"), 0.2);
  EXPECT_DOUBLE_EQ(value_of(applied, "accuracy_theta"), 0.1);
  EXPECT_DOUBLE_EQ(value_of(applied, "timeout"), 0.1);  // the others kept
  EXPECT_DOUBLE_EQ(value_of(applied, "tolerance_wall_base"), 0.06);
  const auto coarse = f.diags_with(0.2, 3);
  ASSERT_GE(coarse.size(), 3u) << "the diagnostics never reported accuracy xy 0.2";
  EXPECT_NEAR(number(coarse.back(), "accuracy theta rad"), 0.1, 1e-6);
  std::vector<double> cells_fine, cells_coarse;
  for (const auto& d : fine) cells_fine.push_back(number(d, "last search cells"));
  for (std::size_t i = 1; i < coarse.size(); ++i) cells_coarse.push_back(number(coarse[i], "last search cells"));
  std::printf("reconfigure: accuracy 0.04 m -> 0.2 m: median search cells %.0f -> %.0f\n", median(cells_fine),
              median(cells_coarse));
  EXPECT_LT(median(cells_coarse), median(cells_fine) / 2);
  EXPECT_GT(rec.cloud_sizes.size(), clouds_fine);

  check_timeout(f);

  // 3. the walls' tolerance: the plateau (particlecloud) widens
  rec.cloud_sizes.clear();
  ASSERT_TRUE(f.scan_until([&] { return rec.cloud_sizes.size() >= 10; }, 20.0));
  std::vector<double> narrow(rec.cloud_sizes.begin() + 2, rec.cloud_sizes.end());
  applied = set({{"tolerance_wall_base", 0.3}});
  EXPECT_DOUBLE_EQ(value_of(applied, "tolerance_wall_base"), 0.3);
  EXPECT_DOUBLE_EQ(value_of(applied, "tolerance_wall_per_metre"), 0.02);
  rec.cloud_sizes.clear();
  rec.poses.clear();
  ASSERT_TRUE(f.scan_until([&] { return rec.cloud_sizes.size() >= 10; }, 20.0));
  std::vector<double> wide(rec.cloud_sizes.begin() + 2, rec.cloud_sizes.end());
  std::printf("reconfigure: wall tolerance 0.06 m -> 0.3 m: median particlecloud %.0f -> %.0f poses\n",
              median(narrow), median(wide));
  EXPECT_GT(median(wide), 2 * median(narrow));
  ASSERT_FALSE(rec.poses.empty());
  const Pose2D truth = ellipse_pose(0.0), last = rec.poses.back();
  EXPECT_LT(std::hypot(last.x - truth.x, last.y - truth.y), 0.1);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "murea_reconfigure_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
