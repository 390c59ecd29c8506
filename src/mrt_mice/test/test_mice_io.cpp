// File formats and the command-line tools.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

#include "mrt_mice/mice_io.h"

using namespace mrt::mice;
using mrt::common::ParseError;

namespace {

const char* kParams =
    "left:  {x: 0.0, y: 0.1, yaw: -1.5707963267948966, counts_per_m: 10000}\n"
    "right: {x: 0.0, y: -0.1, yaw: -1.5707963267948966, counts_per_m: 10000}\n"
    "detection_factor: 2.0\n";

TEST(Params, Parse) {
  const MiceParams p = parse_params(kParams, "p.yaml");
  EXPECT_NEAR(p.distance(), 0.2, 1e-12);
  EXPECT_EQ(p.left.counts_per_m, 10000.0);
  EXPECT_EQ(p.detection_factor, 2.0);
  EXPECT_EQ(p.detection_relative, 0.0);
}

TEST(Params, ShippedConfigurationsLoad) {
  // mrt_mice/config: side by side (Fig. 4.1) and the staggered example.
  const std::string dir = std::string(MRT_MICE_CONFIG_DIR) + "/";
  const MiceParams side = load_params(dir + "ianus3.yaml");
  EXPECT_NEAR(side.distance(), 0.2, 1e-12);
  const MiceParams staggered = load_params(dir + "ianus3_staggered.yaml");
  // |(-0.24, -0.04)| = sqrt(0.0592)
  EXPECT_NEAR(staggered.distance(), std::sqrt(0.0592), 1e-12);
}

TEST(Params, RoundTripThroughWriter) {
  const MiceParams p = parse_params(kParams, "p.yaml");
  std::ostringstream out;
  write_params(out, p);
  const MiceParams q = parse_params(out.str(), "q.yaml");
  EXPECT_NEAR(q.left.mount.theta, p.left.mount.theta, 1e-9);
  EXPECT_NEAR(q.right.mount.y, p.right.mount.y, 1e-12);
  EXPECT_EQ(q.detection_factor, 2.0);
  EXPECT_NE(out.str().find("D_m: 0.2"), std::string::npos) << out.str();
}

void expect_error(const std::string& text, int line, const std::string& what) {
  try {
    parse_params(text, "bad.yaml");
    FAIL() << "no error for:\n" << text;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "bad.yaml");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(Params, ErrorsNameTheLine) {
  expect_error("left: {x: 0, y: 0.1, counts_per_m: 1000}\n", 1, "'right'");
  expect_error("left: {x: 0, y: 0.1, counts_per_m: 1000}\nright: {x: 0, y: oops, counts_per_m: 1}\n",
               2, "expected a number for 'y'");
  expect_error("left: {x: 0, y: 0.1, counts_per_m: 1000}\nright:\n  x: 0\n  y: 0\n  counts_per_m: -3\n",
               5, "counts_per_m > 0");
  expect_error("left: {x: 0, y: 0.1, z: 3, counts_per_m: 1000}\n", 1, "unknown key 'z'");
  expect_error("left: [1, 2\n", 2, "");
  // A misspelt optional key is an error, not a silent default.
  expect_error(std::string(kParams) + "\ndetection_fatcor: 3\n", 5, "unknown key 'detection_fatcor'");
  // mice_calibrate's own sections are known.
  EXPECT_NO_THROW(parse_params(std::string(kParams) + "derived: {D_m: 0.2}\ncalibration: {pushes: 10}\n", "ok.yaml"));
}

TEST(ReadingsCsv, ParseAndErrors) {
  std::istringstream ok("t,left_dx,left_dy,right_dx,right_dy\n0.0,1,2,3,4\n# c\n0.02,-1,0,0,7\n");
  const auto rows = parse_readings_csv(ok, "r.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].counts.right_dy, 7);
  EXPECT_EQ(rows[1].line, 4);
  std::istringstream bad("t,left_dx,left_dy,right_dx,right_dy\n0.0,1,2,3,4\n0.02,1,2.5,3,4\n");
  try {
    parse_readings_csv(bad, "r.csv");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 8);
    EXPECT_NE(std::string(e.what()).find("left_dy"), std::string::npos);
  }
  std::istringstream back("t,left_dx,left_dy,right_dx,right_dy\n1.0,1,2,3,4\n0.5,1,2,3,4\n");
  EXPECT_THROW(parse_readings_csv(back, "r.csv"), ParseError);
  std::istringstream hdr("t,lx,ly,rx,ry\n");
  EXPECT_THROW(parse_readings_csv(hdr, "r.csv"), ParseError);
}

TEST(CalibrationCsv, SumsSamplesOfARun) {
  std::istringstream in(
      "run,kind,amount,left_dx,left_dy,right_dx,right_dy\n"
      "1,push,0.5,10,0,10,0\n1,push,0.5,5,1,5,1\n2,turn,6.283185307179586,0,100,0,-100\n");
  const auto runs = parse_calibration_csv(in, "c.csv");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].counts.left_dx, 15);
  EXPECT_EQ(runs[0].counts.left_dy, 1);
  EXPECT_EQ(runs[1].kind, CalibrationRun::Kind::kTurn);
  EXPECT_EQ(runs[0].source, "c.csv:2");
  std::istringstream bad("run,kind,amount,left_dx,left_dy,right_dx,right_dy\n1,spin,1,0,0,0,0\n");
  try {
    parse_calibration_csv(bad, "c.csv");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 3);
  }
}

// Per-process file names: several test runs may share the machine.
std::string tmp(const std::string& name) {
  return ::testing::TempDir() + "mrt_mice_" + std::to_string(::getpid()) + "_" + name;
}

const std::string kStderr = tmp("stderr");

int run(const std::string& cmd) {
  const int st = std::system((cmd + " 2>" + kStderr).c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Tools, MiceOdometryRunsAndReportsBadLines) {
  const std::string params = tmp("params.yaml"), in = tmp("in.csv"), out = tmp("out.csv");
  std::ofstream(params) << kParams;
  {
    // Manual placement (mouse y axes forward), 10000 counts/m: 10 samples
    // of 0.03 rad in place (each mouse runs 0.1 m * 0.03 = 3 mm = 30
    // counts, the right one forward), then 10 of 1 cm straight ahead.
    std::ofstream f(in);
    f << "t,left_dx,left_dy,right_dx,right_dy\n";
    for (int i = 0; i < 10; ++i) f << i * 0.02 << ",0,-30,0,30\n";
    for (int i = 10; i < 20; ++i) f << i * 0.02 << ",0,100,0,100\n";
    f << "0.4,40,100,0,100\n";  // left reads 4 mm across the line: flagged
  }
  const std::string tool = std::string(MRT_MICE_TOOL_DIR) + "/mice_odometry";
  ASSERT_EQ(run(tool + " --params " + params + " --in " + in + " --out " + out), 0)
      << slurp(kStderr);
  std::istringstream res(slurp(out));
  std::string line;
  std::getline(res, line);
  EXPECT_EQ(line, "t,x,y,theta,flag");
  std::vector<std::vector<double>> rows;
  while (std::getline(res, line)) {
    std::vector<double> v;
    std::istringstream ls(line);
    std::string field;
    while (std::getline(ls, field, ',')) v.push_back(std::stod(field));
    ASSERT_EQ(v.size(), 5u) << line;
    rows.push_back(v);
  }
  ASSERT_EQ(rows.size(), 21u);
  for (int i = 0; i < 20; ++i) {
    // By hand: theta = 0.03 (i + 1) while turning, then 0.3; the straight
    // samples go 1 cm each along the heading 0.3 rad.
    const double theta = 0.03 * std::min(i + 1, 10);
    const double d = 0.01 * std::max(i - 9, 0);
    EXPECT_NEAR(rows[i][0], 0.02 * i, 1e-12) << "row " << i;
    EXPECT_NEAR(rows[i][1], d * std::cos(0.3), 1e-12) << "row " << i;
    EXPECT_NEAR(rows[i][2], d * std::sin(0.3), 1e-12) << "row " << i;
    EXPECT_NEAR(rows[i][3], theta, 1e-12) << "row " << i;
    EXPECT_EQ(rows[i][4], 0.0) << "row " << i;
  }
  EXPECT_NEAR(rows[20][0], 0.4, 1e-12);
  EXPECT_EQ(rows[20][4], 1.0);

  std::ofstream(in, std::ios::app) << "0.42,1,x,3,4\n";
  EXPECT_EQ(run(tool + " --params " + params + " --in " + in + " --out " + out), 2);
  const std::string err = slurp(kStderr);
  EXPECT_NE(err.find(in + ":23:8:"), std::string::npos) << err;
  EXPECT_EQ(run(tool + " --params /nonexistent.yaml --in " + in + " --out " + out), 2);
  EXPECT_EQ(run(tool + " --in " + in), 2);
}

TEST(Tools, MiceCalibrateWritesParams) {
  const std::string in = tmp("calib.csv"), out = tmp("calib.yaml"), txt = tmp("calib.txt");
  {
    // Manual placement, D = 0.2 m, 10000 counts/m: a 0.5 m push reads 5000
    // counts on y, a 2 pi turn 2 pi * 0.1 m = 6283 counts, opposite signs.
    std::ofstream f(in);
    f << "run,kind,amount,left_dx,left_dy,right_dx,right_dy\n";
    for (int i = 0; i < 10; ++i) f << i << ",push,0.5,0,5000,0,5000\n";
    for (int i = 10; i < 15; ++i) f << i << ",turn,6.283185307179586,0,-6283,0,6283\n";
  }
  const std::string tool = std::string(MRT_MICE_TOOL_DIR) + "/mice_calibrate";
  ASSERT_EQ(run(tool + " --in " + in + " --out " + out + " > " + txt), 0)
      << slurp(kStderr);
  const MiceParams p = load_params(out);
  EXPECT_NEAR(p.distance(), 0.2, 1e-4);
  EXPECT_NEAR(p.left.counts_per_m, 10000.0, 1e-6);
  EXPECT_NEAR(p.left.mount.theta, -M_PI / 2, 1e-9);
  EXPECT_NE(slurp(txt).find("D: 199.9"), std::string::npos) << slurp(txt);
  std::ofstream(in) << "run,kind,amount,left_dx,left_dy,right_dx,right_dy\n1,push,0.5,0,5000,0,5000\n";
  EXPECT_EQ(run(tool + " --in " + in + " --out " + out), 2);  // no turn
}

}  // namespace
