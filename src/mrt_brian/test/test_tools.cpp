// brian_run end to end: the reference trace of synth reproduced through the
// tool, and bad input reported with file and line, exit 2.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "mrt_brian/lexer.h"

namespace fs = std::filesystem;

namespace {

struct ToolRun {
  int rc;
  std::string out, err;
};

ToolRun run_tool(const std::string& args) {
  const fs::path dir = fs::temp_directory_path();
  const std::string o = (dir / ("brian_run_out_" + std::to_string(::getpid()))).string();
  const std::string e = (dir / ("brian_run_err_" + std::to_string(::getpid()))).string();
  const int rc = std::system((std::string(MRT_BRIAN_RUN) + " " + args + " >" + o + " 2>" + e).c_str());
  ToolRun r{WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, mrt::brian::read_text_file(o), mrt::brian::read_text_file(e)};
  fs::remove(o);
  fs::remove(e);
  return r;
}

const std::string kData = MRT_BRIAN_TEST_DATA;

}  // namespace

TEST(BrianRun, CommandsOfSynthMatchTheReferenceTrace) {
  const ToolRun r = run_tool("--profile legacy " + kData + "/synth " + kData + "/synth/input.txt");
  ASSERT_EQ(r.rc, 0) << r.err;
  // The CMD lines of ../shared/peer/brian/synth/expected.trace.
  EXPECT_EQ(r.out,
            "=== CYCLE 0\n\nCMD Heading 220.000000\nCMD Speed 20.000000\n"
            "=== CYCLE 1\n\nCMD Heading 220.000000\nCMD Mark 1.000000\nCMD Mark2 1.000000\nCMD Mark3 1.000000\nCMD Speed 30.000000\n"
            "=== CYCLE 2\n\nCMD Heading 220.000000\nCMD Mark 1.000000\nCMD Mark2 1.000000\nCMD Mark3 1.000000\nCMD Speed 30.000000\n"
            "=== CYCLE 3\n\nCMD Heading 350.000000\nCMD Speed 10.000000\n");
}

TEST(BrianRun, TraceHasEveryKindOfLine) {
  const ToolRun r = run_tool("--profile legacy --trace " + kData + "/synth/BrianConfigs.ini " + kData + "/synth/input.txt");
  ASSERT_EQ(r.rc, 0) << r.err;
  for (const char* kind : {"\nCRISP ", "\nFUZZY ", "\nPRED ", "\nCANDO ", "\nWANT ", "\nRULE ", "\nPACT ", "\nACT ", "\nCMD "})
    EXPECT_NE(r.out.find(kind), std::string::npos) << kind;
}

// --time: the engine's own time per cycle on the input, in the bench
// format; the IsAac input has 302 cycles (2 hand-written + 300 random).
TEST(BrianRun, TimePrintsTheEnginesMicrosecondsPerCycle) {
  const ToolRun r = run_tool("--profile legacy --time " + kData + "/isaac/bin/BrianConfigs.ini " + kData +
                             "/isaac/input.txt");
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(r.out.find("CMD"), std::string::npos);
  double us = -1;
  ASSERT_EQ(std::sscanf(r.out.c_str(), "engine_us_per_cycle: %lf us", &us), 1) << r.out;
  EXPECT_GT(us, 0.0);
  EXPECT_LT(us, 1000.0);
  EXPECT_NE(r.out.find("\ncycles: 302 count\n"), std::string::npos) << r.out;
}

TEST(BrianRun, BadInputNamesFileAndLine) {
  const fs::path bad = fs::temp_directory_path() / ("brian_bad_input_" + std::to_string(::getpid()) + ".txt");
  std::ofstream(bad) << "x 25\ny 0\n---\nx twenty\n";
  const ToolRun r = run_tool(kData + "/synth " + bad.string());
  fs::remove(bad);
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find(bad.string() + ":4:"), std::string::npos) << r.err;
}

TEST(BrianRun, BadConfigurationAndUsage) {
  EXPECT_EQ(run_tool(kData + "/nonexistent " + kData + "/synth/input.txt").rc, 2);
  EXPECT_EQ(run_tool("--profile nope " + kData + "/synth " + kData + "/synth/input.txt").rc, 2);
  EXPECT_EQ(run_tool(kData + "/synth").rc, 2);
}

// A path that cannot even be examined (here a name longer than NAME_MAX:
// stat fails with ENAMETOOLONG) is a clear error and exit 2, never an
// uncaught std::filesystem::filesystem_error (abort).
TEST(BrianRun, UnexaminablePathIsAnErrorNotACrash) {
  const std::string too_long = fs::temp_directory_path().string() + "/" + std::string(300, 'a');
  const ToolRun r = run_tool(too_long + " " + kData + "/synth/input.txt");
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find(too_long), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("File name too long"), std::string::npos) << r.err;
  const ToolRun in = run_tool(kData + "/synth " + too_long);
  EXPECT_EQ(in.rc, 2);
  EXPECT_NE(in.err.find(too_long + ": cannot open file: File name too long"), std::string::npos) << in.err;
  // brian_check: a usage error (the path), exit 2 with the reason.
  const std::string o = (fs::temp_directory_path() / ("brian_check_err_" + std::to_string(::getpid()))).string();
  const int rc = std::system((std::string(MRT_BRIAN_CHECK) + " " + too_long + " 2>" + o).c_str());
  const std::string err = mrt::brian::read_text_file(o);
  fs::remove(o);
  EXPECT_EQ(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, 2);
  EXPECT_NE(err.find("File name too long"), std::string::npos) << err;
  // A too-long name inside a list file: "cannot open file" on that name.
  const fs::path list = fs::temp_directory_path() / ("brian_list_" + std::to_string(::getpid()) + ".ini");
  const std::string s = kData + "/synth/";
  std::ofstream(list) << s << "ctof.txt\n" << s << "shape_ctof.txt\n" << s << "Predicate.ini\n" << s
                      << "PredicateActions.ini\n" << s << "Cando.ini\n" << std::string(300, 'b') << "\n" << s
                      << "want.txt\n" << s << "s_ftoc.txt\n" << s << "s_shape.txt\n";
  const ToolRun l = run_tool(list.string() + " " + kData + "/synth/input.txt");
  fs::remove(list);
  EXPECT_EQ(l.rc, 2);
  EXPECT_NE(l.err.find(std::string(300, 'b') + ": cannot open file: File name too long"), std::string::npos) << l.err;
}
