// murea_eval on bags written here with the rosbag C++ API: the robot r1
// drives a straight line near the blue goal of the MSL field (noise-free
// percepts of the simulator, with colours, 10 Hz for 4 s); odometry either
// on /r1/odom or as tf r1/odom -> r1/base_link (percepts then in a camera
// frame mounted 0.1 m ahead, through /tf_static); ground truth on
// /r1/ground_truth.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "mrt_common/testing/cli_runner.h"
#include "mrt_common_ros/conversions.h"
#include "mrt_msgs/Percept.h"
#include "mrt_sim/sensors.h"
#include "mrt_sim/world.h"

namespace {

using mrt::common::Pose2D;
namespace rc = mrt::ros_common;
const std::string kMap = std::string(MRT_MUREA_DATA) + "/msl_field.yaml";

mrt_msgs::Attribute attr(const std::string& name, double value, const std::string& symbol = "") {
  mrt_msgs::Attribute a;
  a.name = name;
  a.value = value;
  a.symbol = symbol;
  a.reliability = 1.0;
  return a;
}

// The simulator's noise-free percepts seen from `eye`, stamped `t`, in
// `frame`; with lines_only, only the field-line points (the field's point
// symmetry then makes every global search ambiguous).
mrt_msgs::Percept percepts(const mrt::sim::World& w, const Pose2D& eye, const ros::Time& t, const std::string& frame,
                           bool lines_only = false) {
  mrt::sim::SensorsConfig cfg;
  cfg.vision_range = 6.0;
  cfg.line_point_spacing = 0.25;
  mrt_msgs::Percept m;
  m.header.stamp = t;
  m.header.frame_id = frame;
  for (const auto& s : mrt::sim::vision_percepts(w, {}, eye, cfg)) {
    if (lines_only && s.membership_class != "Line") continue;
    mrt_msgs::PerceptObject o;
    o.membership_class = s.membership_class;
    o.attributes = {attr("distance", s.distance), attr("bearing", s.bearing), attr("color", 0.0, s.color)};
    m.objects.push_back(o);
  }
  return m;
}

// 40 frames at 10 Hz from (-5.5, -1, 0.5 rad) at 0.3 m/s along x; returns the bag's path.
std::string write_bag(const std::string& name, bool odom_topic, bool lines_only = false) {
  const mrt::sim::World w = mrt::sim::load_world(kMap);
  const std::string path = ::testing::TempDir() + name;
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const Pose2D mount(0.1, 0.0, 0.0);  // camera in base_link (tf case)
  if (!odom_topic) {
    tf2_msgs::TFMessage st;
    st.transforms.push_back(rc::to_transform(mount, "r1/base_link", "r1/camera", ros::Time(1)));
    bag.write("/tf_static", ros::Time(0.5), st);  // latched: recorded first
  }
  for (int i = 0; i < 40; ++i) {
    const ros::Time t(1.0 + 0.1 * i);
    const Pose2D truth(-5.5 + 0.03 * i, -1.0, 0.5);
    // Odometry starts at the origin of r1/odom: odom pose = start^-1 * truth.
    const Pose2D odom = Pose2D(-5.5, -1.0, 0.5).inverse() * truth;
    if (odom_topic) {
      bag.write("/r1/odom", t, rc::to_odometry(odom, 0, 0, 0, "r1/odom", "r1/base_link", t));
    } else {
      tf2_msgs::TFMessage tf;
      tf.transforms.push_back(rc::to_transform(odom, "r1/odom", "r1/base_link", t));
      bag.write("/tf", t, tf);
    }
    bag.write("/r1/ground_truth", t, rc::to_odometry(truth, 0, 0, 0, "map", "r1/base_link", t));
    bag.write("/r1/percepts", t,
              odom_topic ? percepts(w, truth, t, "r1/base_link", lines_only)
                         : percepts(w, truth * mount, t, "r1/camera", lines_only));
  }
  bag.close();
  return path;
}

// Field k (from 0) of a CSV row.
std::string field(const std::string& row, int k) {
  std::stringstream in(row);
  std::string f;
  for (int i = 0; i <= k; ++i) std::getline(in, f, ',');
  return f;
}

const char* const kHeader = "stamp,x,y,theta,cov_xx,cov_yy,cov_tt,mode,evidence,alt_x,alt_y,alt_theta,alt_evidence";

int rows(const std::string& csv, std::string* first_mode) {
  std::ifstream in(csv);
  std::string line, header;
  std::getline(in, header);
  // The first eight columns are the contract other tools read.
  EXPECT_EQ(header.substr(0, 44), "stamp,x,y,theta,cov_xx,cov_yy,cov_tt,mode,ev");
  EXPECT_EQ(header, kHeader);
  int n = 0;
  while (std::getline(in, line)) {
    if (n++ == 0) *first_mode = field(line, 7);
  }
  return n;
}

double figure(const std::string& out, const std::string& name) {
  const auto at = out.find(name + ": ");
  return at == std::string::npos ? -1.0 : std::stod(out.substr(at + name.size() + 2));
}

void check(const std::string& bag) {
  const std::string csv = bag + ".csv";
  const auto r = mrt::common::testing::run("'" MUREA_EVAL "' --map '" + kMap + "' --bag '" + bag +
                                           "' --robot r1 --out '" + csv + "' --timeout 0 2>/dev/null");
  ASSERT_EQ(r.code, 0) << r.text;
  std::string mode;
  // Every frame localizes: the blue goal and its posts are named, so the
  // first (global) search is unambiguous, then 39 tracked frames.
  EXPECT_EQ(rows(csv, &mode), 40);
  EXPECT_EQ(mode, "global");
  EXPECT_NE(r.text.find("frames: 40\nestimates: 40 (1 global)"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("compared with ground truth: 40"), std::string::npos) << r.text;
  // Noise-free percepts and odometry: the fitted pose is off by far less
  // than the 5 cm lattice (the least-squares fit is exact up to the 2.5 cm
  // pixel lookups of the nearest line; measured: 0.0000 m), so RMSE < 1 cm,
  // worst < 2 cm.
  EXPECT_GE(figure(r.text, "rmse_xy"), 0.0);
  EXPECT_LT(figure(r.text, "rmse_xy"), 0.01) << r.text;
  EXPECT_LT(figure(r.text, "worst_xy"), 0.02) << r.text;
  EXPECT_LT(figure(r.text, "rmse_theta"), 0.5) << r.text;
}

TEST(MureaEval, OdometryTopicBag) { check(write_bag("murea_eval_odom.bag", true)); }

TEST(MureaEval, TfBagWithCameraFrame) { check(write_bag("murea_eval_tf.bag", false)); }

// murea_plot on murea_eval's output for the odometry-topic bag: the PNG
// is written (its 8-byte signature), the same 40 estimates and, as above,
// RMSE < 1 cm; murea_eval's CSV with its header removed is refused (line 1).
TEST(MureaPlot, DrawsTheEvaluationOfABag) {
  const std::string bag = write_bag("murea_plot.bag", true), csv = bag + ".csv", png = bag + ".png";
  namespace t = mrt::common::testing;
  ASSERT_EQ(t::run("'" MUREA_EVAL "' --map '" + kMap + "' --bag '" + bag + "' --robot r1 --out '" + csv +
                   "' --timeout 0 >/dev/null 2>&1").code, 0);
  const std::string plot = "/usr/bin/python3 '" MUREA_PLOT "' --bag '" + bag + "' --robot r1 --png '" + png + "'";
  const auto r = t::run(plot + " --estimates '" + csv + "' 2>&1");
  ASSERT_EQ(r.code, 0) << r.text;
  EXPECT_NE(r.text.find("estimates: 40\n"), std::string::npos) << r.text;
  EXPECT_GE(figure(r.text, "rmse_xy"), 0.0);
  EXPECT_LT(figure(r.text, "rmse_xy"), 0.01) << r.text;
  std::ifstream in(png, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  EXPECT_EQ(std::string(sig, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const auto bad = t::run("tail -n +2 '" + csv + "' > '" + csv + ".bad'; " + plot + " --estimates '" + csv +
                          ".bad' 2>&1 >/dev/null");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.text.find(".bad:1: expected the header"), std::string::npos) << bad.text;
  EXPECT_EQ(t::run("/usr/bin/python3 '" MUREA_PLOT "' --help >/dev/null 2>&1").code, 0);
}

// --initial-pose: tracking from the first frame's true pose, no global
// search (0 global), the same 40 estimates within the same bounds as above.
TEST(MureaEval, InitialPoseTracksFromTheStart) {
  const std::string bag = write_bag("murea_eval_initial.bag", true), csv = bag + ".csv";
  const auto r = mrt::common::testing::run("'" MUREA_EVAL "' --map '" + kMap + "' --bag '" + bag +
                                           "' --robot r1 --out '" + csv + "' --timeout 0 --initial-pose -5.5 -1 0.5 2>/dev/null");
  ASSERT_EQ(r.code, 0) << r.text;
  std::string mode;
  EXPECT_EQ(rows(csv, &mode), 40);
  EXPECT_EQ(mode, "tracking");
  EXPECT_NE(r.text.find("estimates: 40 (0 global)\nambiguous: 0\n"), std::string::npos) << r.text;
  EXPECT_LT(figure(r.text, "rmse_xy"), 0.01) << r.text;
}

// Field-line points only: the field is symmetric under the half turn
// (x, y, theta) -> (-x, -y, theta + pi), so without a prior every frame is
// ambiguous: 40 rows of mode `ambiguous` whose pose and runner-up are the
// truth (-5.5 + 0.03 i, -1, 0.5) and its mirror (5.5 - 0.03 i, 1, 0.5 + pi),
// in either order: the pose is the plateau's mean, within the plateau's
// box (0.3 m, 10 deg) of its mode; the runner-up a lattice pose of the
// other mode's plateau, within the same box. With --initial-pose the prior
// takes the true mode and every frame is tracked.
TEST(MureaEval, AmbiguousRowsCarryTheRunnerUp) {
  const std::string bag = write_bag("murea_eval_lines.bag", true, true), csv = bag + ".csv";
  const std::string cmd = "'" MUREA_EVAL "' --map '" + kMap + "' --bag '" + bag + "' --robot r1 --out '" + csv +
                          "' --timeout 0";
  const auto r = mrt::common::testing::run(cmd + " 2>/dev/null");
  ASSERT_EQ(r.code, 0) << r.text;
  EXPECT_NE(r.text.find("estimates: 0 (0 global)\nambiguous: 40\n"), std::string::npos) << r.text;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  const double box = 0.3, box_theta = 10 * M_PI / 180;
  auto near = [&](double x, double y, double th, const Pose2D& p) {
    return std::hypot(x - p.x, y - p.y) < box && std::abs(std::remainder(th - p.theta, 2 * M_PI)) < box_theta;
  };
  for (int i = 0; std::getline(in, line); ++i) {
    SCOPED_TRACE(line);
    ASSERT_LT(i, 40);
    EXPECT_EQ(field(line, 7), "ambiguous");
    const Pose2D truth(-5.5 + 0.03 * i, -1.0, 0.5), mirror(5.5 - 0.03 * i, 1.0, 0.5 + M_PI);
    const double x = std::stod(field(line, 1)), y = std::stod(field(line, 2)), th = std::stod(field(line, 3));
    ASSERT_FALSE(field(line, 9).empty()) << "no runner-up";
    const double ax = std::stod(field(line, 9)), ay = std::stod(field(line, 10)), at = std::stod(field(line, 11));
    EXPECT_TRUE((near(x, y, th, truth) && near(ax, ay, at, mirror)) || (near(x, y, th, mirror) && near(ax, ay, at, truth)));
  }
  const auto tracked = mrt::common::testing::run(cmd + " --initial-pose -5.5 -1 0.5 2>/dev/null");
  ASSERT_EQ(tracked.code, 0) << tracked.text;
  std::string mode;
  EXPECT_EQ(rows(csv, &mode), 40);
  EXPECT_EQ(mode, "tracking");
  EXPECT_NE(tracked.text.find("estimates: 40 (0 global)\nambiguous: 0\n"), std::string::npos) << tracked.text;
  EXPECT_LT(figure(tracked.text, "rmse_xy"), 0.01) << tracked.text;
}

TEST(MureaEval, BadInput) {
  namespace t = mrt::common::testing;
  EXPECT_EQ(t::help(MUREA_EVAL).code, 0);
  const auto missing = t::err(MUREA_EVAL, "--map '" + kMap + "' --bag /nonexistent.bag --robot r1 --out /dev/null");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.text.find("murea_eval: "), std::string::npos) << missing.text;
  const auto usage = t::err(MUREA_EVAL, "--map '" + kMap + "' --bag x.bag --out /dev/null");  // no --robot
  EXPECT_EQ(usage.code, 2);
  const auto bad_map = t::err(MUREA_EVAL, std::string("--map '") + MRT_MUREA_DATA +
                                              "/bad_map.yaml' --bag x.bag --robot r1 --out /dev/null");
  EXPECT_EQ(bad_map.code, 2);
  EXPECT_NE(bad_map.text.find("bad_map.yaml:"), std::string::npos) << bad_map.text;
  const auto two = t::err(MUREA_EVAL, "--map '" + kMap + "' --bag x.bag --robot r1 --out /dev/null --initial-pose 1 2");
  EXPECT_EQ(two.code, 2);
  const auto nan = t::err(MUREA_EVAL, "--map '" + kMap + "' --bag x.bag --robot r1 --out /dev/null --initial-pose 1 nan 0");
  EXPECT_EQ(nan.code, 2);
}

}  // namespace
