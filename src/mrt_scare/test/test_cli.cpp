// scare_allocate as a program: --help, usage errors (exit 2), file errors
// (exit 2 with file:line), and the worked example's agenda and allocation.
#include <gtest/gtest.h>

#include "mrt_common/testing/cli_runner.h"

namespace t = mrt::common::testing;

namespace {
const std::string kTool = SCARE_ALLOCATE;
const std::string kArgs = std::string("--activities ") + MRT_SCARE_CONFIG_DIR "/robocup_activities.yaml --situation " +
                          MRT_SCARE_TEST_DATA "/passing.yaml";
}  // namespace

TEST(ScareAllocate, HelpAndUsage) {
  const t::Output h = t::help(kTool);
  EXPECT_EQ(h.code, 0);
  EXPECT_NE(h.text.find("--situation"), std::string::npos);
  const t::Output e = t::err(kTool, "--activities x.yaml");
  EXPECT_EQ(e.code, 2);
  EXPECT_EQ(e.text.rfind("scare_allocate: ", 0), 0u);
  EXPECT_EQ(t::err(kTool, kArgs + " --method best").code, 2);
}

TEST(ScareAllocate, FileErrorsNameTheFile) {
  const t::Output e = t::err(kTool, std::string("--activities ") + MRT_SCARE_CONFIG_DIR +
                                        "/robocup_activities.yaml --situation /nonexistent.yaml");
  EXPECT_EQ(e.code, 2);
  EXPECT_NE(e.text.find("/nonexistent.yaml: cannot open file"), std::string::npos);
}

TEST(ScareAllocate, WorkedExample) {
  const t::Output o = t::run("'" + kTool + "' " + kArgs + " --method exact 2>/dev/null");
  EXPECT_EQ(o.code, 0);
  // PassageToMate (opportunity 0.9) heads the agenda; robot2 passes, robot3
  // receives, robot1 defends: 0.6555 + 0.6703 + 0.1355 = 1.4613 (README).
  EXPECT_NE(o.text.find("   1. PassageToMate"), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("allocation (exact, utility 1.461"), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("robot1     Defense\n"), std::string::npos);
  EXPECT_NE(o.text.find("robot2     PassageToMate.passer\n"), std::string::npos);
  EXPECT_NE(o.text.find("robot3     PassageToMate.receiver\n"), std::string::npos);
}
