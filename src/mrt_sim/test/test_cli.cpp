// The command-line tools of mrt_sim, run as programs: `--help` exits 0 and
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

TEST(SimRunCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(SIM_RUN);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--world"), std::string::npos) << "--world";
  EXPECT_NE(o.text.find("--robot"), std::string::npos) << "--robot";
  EXPECT_NE(o.text.find("--twist"), std::string::npos) << "--twist";
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << "--duration";
  EXPECT_NE(o.text.find("--out"), std::string::npos) << "--out";
  EXPECT_NE(o.text.find("--mice"), std::string::npos) << "--mice";
  EXPECT_NE(o.text.find("--dt"), std::string::npos) << "--dt";
  EXPECT_NE(o.text.find("(s"), std::string::npos) << "(s";
  EXPECT_NE(o.text.find("(m/s)"), std::string::npos) << "(m/s)";
  EXPECT_NE(o.text.find("(rad/s)"), std::string::npos) << "(rad/s)";
}

TEST(SimRunCli, UnknownOptionExitsTwo) {
  const Output o = err(SIM_RUN, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("sim_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(SIM_RUN, "--bogus"), "");
}

TEST(SimRunCli, BadNumberExitsTwo) {
  const Output o = err(SIM_RUN, "--world w.yaml --twist 1 0 x --duration 1 --out t.csv");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("sim_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--twist"), std::string::npos) << o.text;
  EXPECT_EQ(out(SIM_RUN, "--world w.yaml --twist 1 0 x --duration 1 --out t.csv"), "");
}

TEST(SimRunCli, NegativeDurationExitsTwo) {
  const Output o = err(SIM_RUN, "--world w.yaml --twist 1 0 0 --duration -1 --out t.csv");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("sim_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << o.text;
  EXPECT_EQ(out(SIM_RUN, "--world w.yaml --twist 1 0 0 --duration -1 --out t.csv"), "");
}

TEST(SimRunCli, MissingValueExitsTwo) {
  const Output o = err(SIM_RUN, "--world w.yaml --twist 1 0 0 --out t.csv --duration");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("sim_run: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << o.text;
  EXPECT_EQ(out(SIM_RUN, "--world w.yaml --twist 1 0 0 --out t.csv --duration"), "");
}

TEST(SimBenchCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(SIM_BENCH);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("world"), std::string::npos) << "world";
  EXPECT_NE(o.text.find("seconds"), std::string::npos) << "seconds";
  EXPECT_NE(o.text.find("(s"), std::string::npos) << "(s";
}

TEST(SimBenchCli, UnknownOptionExitsTwo) {
  const Output o = err(SIM_BENCH, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("sim_bench: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(SIM_BENCH, "--bogus"), "");
}

TEST(SimBenchCli, BadNumberExitsTwo) {
  const Output o = err(SIM_BENCH, "w.yaml 1s");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("sim_bench: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("seconds"), std::string::npos) << o.text;
  EXPECT_EQ(out(SIM_BENCH, "w.yaml 1s"), "");
}
