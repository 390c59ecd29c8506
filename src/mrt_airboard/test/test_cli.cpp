// The command-line tools of mrt_airboard, run as programs: `--help` exits 0 and
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

TEST(AirboardFrameCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(AIRBOARD_FRAME);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("encode"), std::string::npos) << "encode";
  EXPECT_NE(o.text.find("decode"), std::string::npos) << "decode";
}

TEST(AirboardFrameCli, UnknownOptionExitsTwo) {
  const Output o = err(AIRBOARD_FRAME, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("airboard_frame: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(AIRBOARD_FRAME, "--bogus"), "");
}

TEST(AirboardFrameCli, UnknownSubcommandExitsTwo) {
  const Output o = err(AIRBOARD_FRAME, "frobnicate");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("airboard_frame: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("frobnicate"), std::string::npos) << o.text;
  EXPECT_EQ(out(AIRBOARD_FRAME, "frobnicate"), "");
}

TEST(AirboardFrameCli, BadSequenceNumberExitsTwo) {
  const Output o = err(AIRBOARD_FRAME, "encode get_state 300");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("airboard_frame: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("seq"), std::string::npos) << o.text;
  EXPECT_EQ(out(AIRBOARD_FRAME, "encode get_state 300"), "");
}

TEST(AirboardFrameCli, UnknownFrameTypeExitsTwo) {
  const Output o = err(AIRBOARD_FRAME, "encode set_nothing 1");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("airboard_frame: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("set_nothing"), std::string::npos) << o.text;
  EXPECT_EQ(out(AIRBOARD_FRAME, "encode set_nothing 1"), "");
}

TEST(AirboardFrameCli, UnknownDecodeOptionExitsTwo) {
  const Output o = err(AIRBOARD_FRAME, "decode --hex");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("airboard_frame: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--hex"), std::string::npos) << o.text;
  EXPECT_EQ(out(AIRBOARD_FRAME, "decode --hex"), "");
}

TEST(AirboardFrameCli, SubcommandHelpListsItsArguments) {
  const Output e = help(std::string(AIRBOARD_FRAME) + "' 'encode");
  EXPECT_EQ(e.code, 0);
  for (const char* s : {"set_speed", "set_pwm", "set_gains", "set_stream", "get_state", "heartbeat", "get_info",
                        "(rad/s)", "(ms", "seq"})
    EXPECT_NE(e.text.find(s), std::string::npos) << s;
  const Output d = help(std::string(AIRBOARD_FRAME) + "' 'decode");
  EXPECT_EQ(d.code, 0);
  EXPECT_NE(d.text.find("--binary"), std::string::npos) << d.text;
}
