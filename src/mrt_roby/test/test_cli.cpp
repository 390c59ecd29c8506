// The command-line tools of mrt_roby, run as programs: `--help` exits 0 and
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

TEST(RobyRunCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(ROBY_RUN);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--world"), std::string::npos) << "--world";
  EXPECT_NE(o.text.find("--map"), std::string::npos) << "--map";
  EXPECT_NE(o.text.find("--tasks"), std::string::npos) << "--tasks";
  EXPECT_NE(o.text.find("--brian"), std::string::npos) << "--brian";
  EXPECT_NE(o.text.find("--robot"), std::string::npos) << "--robot";
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << "--duration";
  EXPECT_NE(o.text.find("--truth"), std::string::npos) << "--truth";
  EXPECT_NE(o.text.find("--trace"), std::string::npos) << "--trace";
  EXPECT_NE(o.text.find("(s"), std::string::npos) << "(s";
}

TEST(RobyRunCli, UnknownOptionExitsTwo) {
  const Output o = err(ROBY_RUN, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("roby_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(ROBY_RUN, "--bogus"), "");
}

TEST(RobyRunCli, BadNumberExitsTwo) {
  const Output o = err(ROBY_RUN, "--world w --map m --tasks t --brian b --duration 1x");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("roby_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << o.text;
  EXPECT_EQ(out(ROBY_RUN, "--world w --map m --tasks t --brian b --duration 1x"), "");
}

TEST(RobyRunCli, ZeroDurationExitsTwo) {
  const Output o = err(ROBY_RUN, "--world w --map m --tasks t --brian b --duration 0");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("roby_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << o.text;
  EXPECT_EQ(out(ROBY_RUN, "--world w --map m --tasks t --brian b --duration 0"), "");
}

TEST(RobyRunCli, MissingRequiredExitsTwo) {
  const Output o = err(ROBY_RUN, "--world w --map m --tasks t");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("roby_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--brian"), std::string::npos) << o.text;
  EXPECT_EQ(out(ROBY_RUN, "--world w --map m --tasks t"), "");
}
