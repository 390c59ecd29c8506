// The command-line tools of mrt_mice, run as programs: `--help` exits 0 and
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

TEST(MiceOdometryCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(MICE_ODOMETRY);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--params"), std::string::npos) << "--params";
  EXPECT_NE(o.text.find("--in"), std::string::npos) << "--in";
  EXPECT_NE(o.text.find("--out"), std::string::npos) << "--out";
  EXPECT_NE(o.text.find("--no-reduction"), std::string::npos) << "--no-reduction";
  EXPECT_NE(o.text.find("(s, m, m, rad"), std::string::npos) << "(s, m, m, rad";
}

TEST(MiceOdometryCli, UnknownOptionExitsTwo) {
  const Output o = err(MICE_ODOMETRY, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_odometry: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_ODOMETRY, "--bogus"), "");
}

TEST(MiceOdometryCli, MissingValueExitsTwo) {
  const Output o = err(MICE_ODOMETRY, "--params p.yaml --in r.csv --out");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_odometry: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--out"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_ODOMETRY, "--params p.yaml --in r.csv --out"), "");
}

TEST(MiceCalibrateCli, HelpExitsZeroAndListsEveryOption) {
  const Output o = help(MICE_CALIBRATE);
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.text.find("--in"), std::string::npos) << "--in";
  EXPECT_NE(o.text.find("--push-bag"), std::string::npos) << "--push-bag";
  EXPECT_NE(o.text.find("--turn-bag"), std::string::npos) << "--turn-bag";
  EXPECT_NE(o.text.find("--push-distance"), std::string::npos) << "--push-distance";
  EXPECT_NE(o.text.find("--turn-angle-deg"), std::string::npos) << "--turn-angle-deg";
  EXPECT_NE(o.text.find("--topic"), std::string::npos) << "--topic";
  EXPECT_NE(o.text.find("--out"), std::string::npos) << "--out";
  EXPECT_NE(o.text.find("--base"), std::string::npos) << "--base";
  EXPECT_NE(o.text.find("(m)"), std::string::npos) << "(m)";
  EXPECT_NE(o.text.find("(deg)"), std::string::npos) << "(deg)";
}

TEST(MiceCalibrateCli, UnknownOptionExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--bogus");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--bogus"), "");
}

TEST(MiceCalibrateCli, BadNumberExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance abc");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--push-distance"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance abc"), "");
}

TEST(MiceCalibrateCli, ZeroDistanceExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance 0");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--push-distance"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--in r.csv --out p.yaml --push-distance 0"), "");
}

TEST(MiceCalibrateCli, NoRunsExitsTwo) {
  const Output o = err(MICE_CALIBRATE, "--out p.yaml");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.text.find("mice_calibrate: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--in"), std::string::npos) << o.text;
  EXPECT_EQ(out(MICE_CALIBRATE, "--out p.yaml"), "");
}
