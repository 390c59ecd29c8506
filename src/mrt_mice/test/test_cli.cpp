// The command-line tools of mrt_mice, run as programs: `--help` exits 0 and
// lists every option; usage errors (unknown option, missing value, bad
// number) exit 2 with "<tool>: " and the offending option on stderr and
// nothing on stdout. Expected values follow from the tools' contract
// (README, "Command-line tool"): help 0, usage error 2.
#include <gtest/gtest.h>

#include <string>

#include "mrt_common/testing/cli_runner.h"

using mrt::common::testing::err;
using mrt::common::testing::help;
using mrt::common::testing::out;
using mrt::common::testing::Output;

TEST(MiceOdometryCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(MICE_ODOMETRY);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--params"), std::string::npos) << "--params";
  EXPECT_NE(o.text.find("--in"), std::string::npos) << "--in";
  EXPECT_NE(o.text.find("--out"), std::string::npos) << "--out";
  EXPECT_NE(o.text.find("--no-reduction"), std::string::npos) << "--no-reduction";
  EXPECT_NE(o.text.find("(s, m, m, rad"), std::string::npos) << "(s, m, m, rad";
}

TEST(MiceOdometryCli, UnknownOptionExitsTwo) {
  const Output o = err(MICE_ODOMETRY, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_odometry: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_ODOMETRY, "--bogus"), "");
}

TEST(MiceOdometryCli, MissingValueExitsTwo) {
  const Output o = err(MICE_ODOMETRY, "--params p.yaml --in r.csv --out");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_odometry: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--out"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_ODOMETRY, "--params p.yaml --in r.csv --out"), "");
}

TEST(MiceCalibrateCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(MICE_CALIBRATE);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--in"), std::string::npos) << "--in";
  EXPECT_NE(o.text.find("--push-bag"), std::string::npos) << "--push-bag";
  EXPECT_NE(o.text.find("--turn-bag"), std::string::npos) << "--turn-bag";
  EXPECT_NE(o.text.find("--push-distance"), std::string::npos) << "--push-distance";
  EXPECT_NE(o.text.find("--turn-angle-deg"), std::string::npos) << "--turn-angle-deg";
  EXPECT_NE(o.text.find("--topic"), std::string::npos) << "--topic";
  EXPECT_NE(o.text.find("--out"), std::string::npos) << "--out";
  EXPECT_NE(o.text.find("--base"), std::string::npos) << "--base";
  EXPECT_NE(o.text.find("(m)"), std::string::npos) << "(m)";
  EXPECT_NE(o.text.find("(deg)"), std::string::npos) << "(deg)";
}

TEST(MiceCalibrateCli, UnknownOptionExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--bogus"), "");
}

TEST(MiceCalibrateCli, BadNumberExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance abc");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--push-distance"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance abc"), "");
}

TEST(MiceCalibrateCli, ZeroDistanceExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance 0");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--push-distance"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance 0"), "");
}

TEST(MiceCalibrateCli, NoRunsExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--out p.yaml");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--in"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--out p.yaml"), "");
}
