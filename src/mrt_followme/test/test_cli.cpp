// followme_run as a program: --help exits 0 and lists every option; usage
// errors exit 2 with "followme_run: " on stderr and nothing on stdout; a
// tour naming an unknown exhibit exits 2 (README, "Command-line tool").
#include <gtest/gtest.h>

#include <string>

#include "mrt_common/testing/cli_runner.h"

using mrt::common::testing::err;
using mrt::common::testing::help;
using mrt::common::testing::out;
using mrt::common::testing::Output;

TEST(FollowMeRunCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(FOLLOWME_RUN);
  EXPECT_EQ(o.code, 0);
  for (const char* opt : {"--world", "--config", "--brian", "--package", "--tour", "--robot", "--duration", "--close-door",
                          "--close-at-leg", "--wander-after", "--truth", "--trace"})
    EXPECT_NE(o.text.find(opt), std::string::npos) << opt;
}

TEST(FollowMeRunCli, UsageErrorsExitTwo) {
  for (const char* args : {"--bogus", "--world w --config c --brian b --duration 1x",
                           "--world w --config c --brian b --duration 0", "--world w --config c",
                           "--world w --config c --brian b --package mrt_roby"}) {
    const Output o = err(FOLLOWME_RUN, args);
    EXPECT_EQ(o.code, 2) << args;
    EXPECT_NE(o.text.find("followme_run: "), std::string::npos) << o.text;
    EXPECT_EQ(out(FOLLOWME_RUN, args), "") << args;
  }
}

TEST(FollowMeRunCli, UnknownExhibitExitsTwo) {
  const std::string root = MRT_FOLLOWME_ROOT;
  const std::string args = "--world " MRT_WORLDS_DIR "/museum.yaml --config " + root +
                           "/config/followme.yaml --brian " + root + "/config/brian/BrianConfigs.ini --tour statue,mona_lisa";
  const Output o = err(FOLLOWME_RUN, args);
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("unknown exhibit 'mona_lisa'"), std::string::npos) << o.text;
}
