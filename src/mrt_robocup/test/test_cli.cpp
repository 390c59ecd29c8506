// robocup_run: --help exits 0, usage and file errors exit 2, and a short
// run on the match file given as --world prints the summary.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace {

int run(const std::string& args, std::string* out = nullptr) {
  const std::string cmd = std::string(ROBOCUP_RUN) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  std::array<char, 512> buf{};
  std::string text;
  while (fgets(buf.data(), buf.size(), p)) text += buf.data();
  const int status = pclose(p);
  if (out) *out = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(RobocupRun, HelpAndUsageErrors) {
  EXPECT_EQ(run("--help"), 0);
  EXPECT_EQ(run("--seed many"), 2);
  EXPECT_EQ(run("--bogus"), 2);
  std::string out;
  EXPECT_EQ(run("--world /nonexistent.yaml", &out), 2);
  EXPECT_NE(out.find("/nonexistent.yaml"), std::string::npos) << out;
}

TEST(RobocupRun, MatchFileAsWorld) {
  std::string out;
  ASSERT_EQ(run(std::string("--world ") + MRT_ROBOCUP_CONFIG + "/msl_match.yaml --seed 1 --duration 3", &out), 0) << out;
  EXPECT_NE(out.find("score: "), std::string::npos) << out;
  EXPECT_NE(out.find("simulated: 3.0 s"), std::string::npos) << out;
  EXPECT_NE(out.find("role_changes_per_minute: "), std::string::npos) << out;
}

}  // namespace
