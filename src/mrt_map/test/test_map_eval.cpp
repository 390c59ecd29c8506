// map_eval on a bag written here: two robots, one ball at world (2, 1).
#include <gtest/gtest.h>
#include <mrt_msgs/Percept.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mrt_common/testing/cli_runner.h"

using mrt::common::testing::run;

namespace {

std::string temp_dir() {
  char tmpl[] = "/tmp/mrt_map_eval_XXXXXX";
  return mkdtemp(tmpl);
}

mrt_msgs::Percept ball(const std::string& robot, double t, double x, double y) {
  mrt_msgs::Percept p;
  p.header.stamp = ros::Time(t);
  p.header.frame_id = robot + "/base_link";
  p.sensor = "omnivision";
  p.robot = robot;
  mrt_msgs::PerceptObject o;
  o.membership_class = "Ball";
  mrt_msgs::Attribute a;
  a.name = "color";
  a.symbol = "orange";
  a.reliability = 1;
  o.attributes.push_back(a);
  a.symbol.clear();
  for (auto [n, v] : {std::pair<const char*, double>{"x", x}, {"y", y}}) {
    a.name = n;
    a.value = v;
    a.variability = 0.03;
    o.attributes.push_back(a);
  }
  p.objects.push_back(o);
  return p;
}

void write_bag(const std::string& path) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  tf2_msgs::TFMessage tf;
  for (int i = 1; i <= 2; ++i) {
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time(1.0);
    t.header.frame_id = "map";
    t.child_frame_id = "r" + std::to_string(i) + "/base_link";
    t.transform.translation.x = i == 1 ? 0.0 : 4.0;
    t.transform.rotation.w = 1.0;
    tf.transforms.push_back(t);
  }
  bag.write("/tf_static", ros::Time(1.0), tf);
  for (int k = 0; k < 6; ++k) {
    const double t = 1.0 + 0.1 * k;
    bag.write("/r1/percepts", ros::Time(t), ball("r1", t, 2.0, 1.0));    // world (2, 1)
    bag.write("/r2/percepts", ros::Time(t + 0.01), ball("r2", t, -2.0, 1.0));  // world (4 - 2, 1)
  }
  bag.close();
}

std::vector<std::vector<std::string>> read_csv(const std::string& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    rows.push_back(f);
  }
  return rows;
}

}  // namespace

TEST(MapEval, FusesTwoRobotsOnABag) {
  ros::Time::init();
  const std::string dir = temp_dir(), bag = dir + "/in.bag", out = dir + "/out.csv";
  write_bag(bag);
  const auto r = run(std::string(MAP_EVAL) + " --model " MRT_MAP_CONFIG_DIR "/robocup.yaml --bag " + bag +
                     " --robots r1,r2 --out " + out + " 2>&1");
  ASSERT_EQ(r.code, 0) << r.text;
  std::string header;
  const auto rows = read_csv(out, header);
  EXPECT_EQ(header, "stamp,robot,id,class,x,y,vx,vy,cov_xx,cov_xy,cov_yy,reliability,sources");
  // 12 updates (6 per robot), one ball anchor each: 12 rows.
  ASSERT_EQ(rows.size(), 12u);
  const auto& last = rows.back();  // r2's last update, at 1.51
  ASSERT_EQ(last.size(), 13u);
  EXPECT_EQ(last[1], "r2");
  EXPECT_EQ(last[3], "Ball");
  // Every observation is exactly (2, 1): the filters and the intersection
  // keep (2, 1) and a zero velocity.
  EXPECT_NEAR(std::stod(last[4]), 2.0, 1e-9);
  EXPECT_NEAR(std::stod(last[5]), 1.0, 1e-9);
  EXPECT_NEAR(std::stod(last[6]), 0.0, 1e-9);
  // Supported by both robots' cameras.
  EXPECT_NE(last[12].find("r1/omnivision"), std::string::npos);
  EXPECT_NE(last[12].find("r2/omnivision"), std::string::npos);
  std::system(("rm -rf " + dir).c_str());
}

TEST(MapEval, UsageAndInputErrors) {
  EXPECT_EQ(run(std::string(MAP_EVAL) + " --help").code, 0);
  const auto missing = run(std::string(MAP_EVAL) + " --model m.yaml 2>&1 >/dev/null");
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(missing.text.rfind("map_eval: ", 0), 0u) << missing.text;
  const std::string dir = temp_dir();
  {
    std::ofstream m(dir + "/bad.yaml");
    m << "classes:\n  Ball: {parent: Nothing}\n";
  }
  const auto bad = run(std::string(MAP_EVAL) + " --model " + dir + "/bad.yaml --bag x.bag --robots r1 --out " + dir +
                       "/o.csv 2>&1");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.text.find("bad.yaml:2:18: unknown parent class 'Nothing'"), std::string::npos) << bad.text;
  std::system(("rm -rf " + dir).c_str());
}
