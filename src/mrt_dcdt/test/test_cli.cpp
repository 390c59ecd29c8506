// The command-line tools of mrt_dcdt, run as programs: `--help` exits 0 and
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

TEST(DcdtAgoraCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(DCDT_AGORA);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--config"), std::string::npos) << "--config";
  EXPECT_NE(o.text.find("--inner-dir"), std::string::npos) << "--inner-dir";
  EXPECT_NE(o.text.find("--no-inner"), std::string::npos) << "--no-inner";
  EXPECT_NE(o.text.find("--no-finder"), std::string::npos) << "--no-finder";
  EXPECT_NE(o.text.find("--id"), std::string::npos) << "--id";
  EXPECT_NE(o.text.find("--publish"), std::string::npos) << "--publish";
  EXPECT_NE(o.text.find("--warranty"), std::string::npos) << "--warranty";
  EXPECT_NE(o.text.find("--text"), std::string::npos) << "--text";
  EXPECT_NE(o.text.find("--xml"), std::string::npos) << "--xml";
  EXPECT_NE(o.text.find("--count"), std::string::npos) << "--count";
  EXPECT_NE(o.text.find("--rate"), std::string::npos) << "--rate";
  EXPECT_NE(o.text.find("--wait-peers"), std::string::npos) << "--wait-peers";
  EXPECT_NE(o.text.find("--subscribe"), std::string::npos) << "--subscribe";
  EXPECT_NE(o.text.find("--expect"), std::string::npos) << "--expect";
  EXPECT_NE(o.text.find("--linger"), std::string::npos) << "--linger";
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << "--duration";
  EXPECT_NE(o.text.find("--out"), std::string::npos) << "--out";
  EXPECT_NE(o.text.find("--check-xml"), std::string::npos) << "--check-xml";
  EXPECT_NE(o.text.find("--check-config"), std::string::npos) << "--check-config";
  EXPECT_NE(o.text.find("recv type=T"), std::string::npos) << "recv type=T";
  EXPECT_NE(o.text.find("(Hz"), std::string::npos) << "(Hz";
}

TEST(DcdtAgoraCli, UnknownOptionExitsTwo) {
  const Output o = err(DCDT_AGORA, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("dcdt_agora: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(DCDT_AGORA, "--bogus"), "");
}

TEST(DcdtAgoraCli, BadNumberExitsTwo) {
  const Output o = err(DCDT_AGORA, "--no-inner --no-finder --count ten");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("dcdt_agora: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--count"), std::string::npos) << o.text;
  EXPECT_EQ(out(DCDT_AGORA, "--no-inner --no-finder --count ten"), "");
}

TEST(DcdtAgoraCli, MissingValueExitsTwo) {
  const Output o = err(DCDT_AGORA, "--no-inner --no-finder --duration");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("dcdt_agora: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--duration"), std::string::npos) << o.text;
  EXPECT_EQ(out(DCDT_AGORA, "--no-inner --no-finder --duration"), "");
}

TEST(DcdtAgoraCli, BadWarrantyExitsTwo) {
  const Output o = err(DCDT_AGORA, "--no-inner --no-finder --warranty maybe");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("dcdt_agora: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("maybe"), std::string::npos) << o.text;
  EXPECT_EQ(out(DCDT_AGORA, "--no-inner --no-finder --warranty maybe"), "");
}
