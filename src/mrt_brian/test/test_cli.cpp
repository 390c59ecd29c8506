// The command-line tools of mrt_brian, run as programs: `--help` exits 0 and
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

TEST(BrianRunCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(BRIAN_RUN);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--profile"), std::string::npos) << "--profile";
  EXPECT_NE(o.text.find("--trace"), std::string::npos) << "--trace";
  EXPECT_NE(o.text.find("--time"), std::string::npos) << "--time";
  EXPECT_NE(o.text.find("--threshold"), std::string::npos) << "--threshold";
  EXPECT_NE(o.text.find("--weight"), std::string::npos) << "--weight";
  EXPECT_NE(o.text.find("--float"), std::string::npos) << "--float";
  EXPECT_NE(o.text.find("--defuzz"), std::string::npos) << "--defuzz";
  EXPECT_NE(o.text.find("config"), std::string::npos) << "config";
  EXPECT_NE(o.text.find("input"), std::string::npos) << "input";
  EXPECT_NE(o.text.find("(us)"), std::string::npos) << "(us)";
}

TEST(BrianRunCli, UnknownOptionExitsTwo) {
  const Output o = err(BRIAN_RUN, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("brian_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(BRIAN_RUN, "--bogus"), "");
}

TEST(BrianRunCli, BadNumberExitsTwo) {
  const Output o = err(BRIAN_RUN, "--threshold abc c i");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("brian_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--threshold"), std::string::npos) << o.text;
  EXPECT_EQ(out(BRIAN_RUN, "--threshold abc c i"), "");
}

TEST(BrianRunCli, BadNameExitsTwo) {
  const Output o = err(BRIAN_RUN, "--profile nope c i");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("brian_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("nope"), std::string::npos) << o.text;
  EXPECT_EQ(out(BRIAN_RUN, "--profile nope c i"), "");
}

TEST(BrianRunCli, MissingPositionalExitsTwo) {
  const Output o = err(BRIAN_RUN, "c");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("brian_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("input"), std::string::npos) << o.text;
  EXPECT_EQ(out(BRIAN_RUN, "c"), "");
}

TEST(BrianCheckCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(BRIAN_CHECK);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("config"), std::string::npos) << "config";
}

TEST(BrianCheckCli, UnknownOptionExitsTwo) {
  const Output o = err(BRIAN_CHECK, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("brian_check: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(BRIAN_CHECK, "--bogus"), "");
}

TEST(BrianCheckCli, TooManyArgumentsExitsTwo) {
  const Output o = err(BRIAN_CHECK, "a b");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("brian_check: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("b"), std::string::npos) << o.text;
  EXPECT_EQ(out(BRIAN_CHECK, "a b"), "");
}
