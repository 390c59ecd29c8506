// The airboard_frame command-line tool, run as a program.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace {
struct ToolRun {
  std::string out;
  int code = -1;
};

ToolRun run(const std::string& args) {
  ToolRun r;
  FILE* p = ::popen((std::string(AIRBOARD_FRAME) + " " + args + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[512];
  while (std::fgets(buf, sizeof(buf), p)) r.out += buf;
  const int st = ::pclose(p);
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}
}  // namespace

TEST(AirboardFrameTool, EncodesTheGoldenFrame) {
  const ToolRun r = run("encode set_speed 7 1.5 -2.0");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "A5 09 01 07 02 DC 05 00 00 30 F8 FF FF 10 BB\n");
  EXPECT_EQ(run("encode get_info 1").out, "A5 00 07 01 2A 45\n");
}

TEST(AirboardFrameTool, DecodesACaptureAndCountsBadFrames) {
  const ToolRun r = run(std::string("decode ") + AIRBOARD_TEST_DATA + "/capture.hex");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out,
            "SET_SPEED seq=7 1.5 -2\n"
            "HEARTBEAT seq=0\n"
            // 00 13 skipped; the garbage A5 followed by A5 announces 165 bytes
            // (bad length); the altered frame fails its CRC and its 14 bytes
            // after the start byte are skipped.
            "# 2 frames, 1 bad CRC, 1 bad length, 16 bytes skipped\n");
}

TEST(AirboardFrameTool, ReportsBadInputWithFileLineColumn) {
  const std::string file = std::string(AIRBOARD_TEST_DATA) + "/bad_token.hex";
  const ToolRun r = run("decode " + file);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, file + ":2:4: expected a hex byte, got '0G'\n");
  EXPECT_EQ(run("decode /nonexistent/capture.hex").code, 2);
  EXPECT_EQ(run("encode set_speed 1").code, 2);   // no motor
  EXPECT_EQ(run("frobnicate").code, 2);
}
