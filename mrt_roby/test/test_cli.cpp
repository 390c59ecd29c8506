// The command-line tools of mrt_roby, run as programs: `--help` exits 0 and
// lists every option; usage errors (unknown option, missing value, bad
// number) exit 2 with "<tool>: " and the offending option on stderr and
// nothing on stdout. Expected values follow from the tools' contract
// (README, "Command-line tool"): help 0, usage error 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace {

struct Output {
  int code = -1;
  std::string text;
};

// Runs `cmd` through the shell; `text` is what it wrote on the stream left
// on the pipe (the command's own redirections pick stdout or stderr).
Output run(const std::string& cmd) {
  Output o;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return o;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), p)) > 0;) o.text.append(buf.data(), n);
  const int status = pclose(p);
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

Output help(const std::string& tool) { return run("'" + tool + "' --help 2>/dev/null"); }
// stderr only; stdout must stay empty on a usage error, so it is checked apart.
Output err(const std::string& tool, const std::string& args) {
  return run("'" + tool + "' " + args + " 2>&1 >/dev/null");
}
std::string out(const std::string& tool, const std::string& args) {
  return run("'" + tool + "' " + args + " 2>/dev/null").text;
}

}  // namespace

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
