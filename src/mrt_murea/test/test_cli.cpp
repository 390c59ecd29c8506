// The command-line tools of mrt_murea, run as programs: `--help` exits 0 and
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

TEST(MureaLocalizeCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(MUREA_LOCALIZE);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--map"), std::string::npos) << "--map";
  EXPECT_NE(o.text.find("--percepts"), std::string::npos) << "--percepts";
  EXPECT_NE(o.text.find("--accuracy"), std::string::npos) << "--accuracy";
  EXPECT_NE(o.text.find("--timeout"), std::string::npos) << "--timeout";
  EXPECT_NE(o.text.find("(m)"), std::string::npos) << "(m)";
  EXPECT_NE(o.text.find("(rad)"), std::string::npos) << "(rad)";
}

TEST(MureaLocalizeCli, UnknownOptionExitsTwo) {
  const Output o = err(MUREA_LOCALIZE, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("murea_localize: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(MUREA_LOCALIZE, "--bogus"), "");
}

TEST(MureaLocalizeCli, BadNumberExitsTwo) {
  const Output o = err(MUREA_LOCALIZE, "--map m.yaml --percepts p.csv --timeout soon");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("murea_localize: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--timeout"), std::string::npos) << o.text;
  EXPECT_EQ(out(MUREA_LOCALIZE, "--map m.yaml --percepts p.csv --timeout soon"), "");
}

TEST(MureaLocalizeCli, MissingValueExitsTwo) {
  const Output o = err(MUREA_LOCALIZE, "--map m.yaml --percepts");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("murea_localize: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--percepts"), std::string::npos) << o.text;
  EXPECT_EQ(out(MUREA_LOCALIZE, "--map m.yaml --percepts"), "");
}

TEST(MureaBenchCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(MUREA_BENCH);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("poses"), std::string::npos) << "poses";
  EXPECT_NE(o.text.find("repeats"), std::string::npos) << "repeats";
  EXPECT_NE(o.text.find("world"), std::string::npos) << "world";
}

TEST(MureaBenchCli, UnknownOptionExitsTwo) {
  const Output o = err(MUREA_BENCH, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("murea_bench: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(MUREA_BENCH, "--bogus"), "");
}

TEST(MureaBenchCli, BadNumberExitsTwo) {
  const Output o = err(MUREA_BENCH, "many");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("murea_bench: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("poses"), std::string::npos) << o.text;
  EXPECT_EQ(out(MUREA_BENCH, "many"), "");
}
