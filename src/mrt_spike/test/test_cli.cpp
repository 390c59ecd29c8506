// spike_plan and spike_bench run as programs: `--help` exits 0 and lists the
// options; usage errors exit 2 naming the tool and the option, nothing on
// stdout; a bad map file exits 2 with file:line; no path exits 1 with the
// reason and the nearest point (README, "CLI").
#include <gtest/gtest.h>

#include <string>

#include "mrt_common/testing/cli_runner.h"

using mrt::common::testing::err;
using mrt::common::testing::help;
using mrt::common::testing::out;
using mrt::common::testing::Output;

namespace {
const std::string kData = MRT_SPIKE_TEST_DATA;
}

TEST(SpikePlanCli, HelpAndUsageErrors) {
  const Output h = help(SPIKE_PLAN);
  EXPECT_EQ(h.code, 0);
  for (const char* opt : {"--map", "--start", "--goal", "--scen", "--queries", "--algo", "--out", "--graph"})
    EXPECT_NE(h.text.find(opt), std::string::npos) << opt;
  const Output u = err(SPIKE_PLAN, "--bogus");
  EXPECT_EQ(u.code, 2);
  EXPECT_NE(u.text.find("spike_plan: "), std::string::npos) << u.text;
  EXPECT_NE(u.text.find("--bogus"), std::string::npos) << u.text;
  EXPECT_EQ(out(SPIKE_PLAN, "--bogus"), "");
  EXPECT_EQ(err(SPIKE_PLAN, "--map m --algo dijkstra").code, 2);
}

TEST(SpikePlanCli, BadMapAndNoPath) {
  const Output bad = err(SPIKE_PLAN, "--map " + kData + "/bad_char.map --start 0 0 --goal 1 1");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.text.find("bad_char.map:6:2: "), std::string::npos) << bad.text;
  // (16, 0) is in the wall of passage32.map: no path, exit 1
  const Output none =
      mrt::common::testing::run(std::string("'") + SPIKE_PLAN + "' --map " + kData + "/passage32.map --start 16 0 --goal 2 2 2>/dev/null");
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.text.find("no path: start (16, 0) is inside an obstacle; nearest reachable point"), std::string::npos)
      << none.text;
}

TEST(SpikeBenchCli, HelpAndUsageErrors) {
  const Output h = help(SPIKE_BENCH);
  EXPECT_EQ(h.code, 0);
  for (const char* opt : {"--map", "--dir", "--every", "--scale", "--msl", "--building", "--ompl"})
    EXPECT_NE(h.text.find(opt), std::string::npos) << opt;
  // spike_plan's options too (issue 16: "spike_bench with the same options")
  for (const char* opt : {"--start", "--goal", "--scen", "--queries", "--algo", "--ompl-planner", "--out"})
    EXPECT_NE(h.text.find(opt), std::string::npos) << opt;
  EXPECT_EQ(err(SPIKE_BENCH, "--map m --algo dijkstra").code, 2);
  const Output u = err(SPIKE_BENCH, "--every 0");
  EXPECT_EQ(u.code, 2);
  EXPECT_NE(u.text.find("spike_bench: "), std::string::npos) << u.text;
}

// The query and path lines spike_bench --out writes, without the timings.
std::string without_times(const std::string& file) {
  const Output o = mrt::common::testing::run("sed -e 's/ time_us .*//' '" + file + "'");
  return o.text;
}

// spike_bench takes spike_plan's command line, --out included, and writes
// the same outcomes: the A* (optimal, deterministic) on every query of
// passage32's scenario and on one --start/--goal query.
TEST(SpikeBenchCli, SpikePlansOptionsAndOutput) {
  const std::string dir = ::testing::TempDir();
  const std::string args = " --map " + kData + "/passage32.map --scen " + kData + "/passage32.map.scen --algo astar";
  ASSERT_EQ(mrt::common::testing::run(std::string("'") + SPIKE_PLAN + "'" + args + " --out " + dir + "plan.txt").code, 0);
  const Output b = mrt::common::testing::run(std::string("'") + SPIKE_BENCH + "'" + args + " --every 1 --out " + dir +
                                            "bench.txt");
  ASSERT_EQ(b.code, 0) << b.text;
  EXPECT_NE(b.text.find("passage32.astar.solved: 100 %"), std::string::npos) << b.text;
  const std::string plan = without_times(dir + "plan.txt");
  EXPECT_NE(plan.find("query 0 solved 1 length "), std::string::npos) << plan;
  EXPECT_EQ(without_times(dir + "bench.txt"), plan);
  const std::string one = " --map " + kData + "/passage32.map --start 2 2 --goal 29 2 --algo astar";
  ASSERT_EQ(mrt::common::testing::run(std::string("'") + SPIKE_PLAN + "'" + one + " --out " + dir + "p1.txt").code, 0);
  ASSERT_EQ(mrt::common::testing::run(std::string("'") + SPIKE_BENCH + "'" + one + " --out " + dir + "b1.txt").code, 0);
  EXPECT_EQ(without_times(dir + "b1.txt"), without_times(dir + "p1.txt"));
  EXPECT_NE(without_times(dir + "p1.txt").find("query 0 solved 1"), std::string::npos);
}

// --smoothing on the museum (the default world): SPIKE's paths and their
// Dubins smoothing, the curvature within the bound 1/0.5 = 2 1/m (chords of
// 5 cm on arcs of 0.5 m: 1.0004 times it); a bad model is a usage error.
TEST(SpikeBenchCli, Smoothing) {
  const Output b = mrt::common::testing::run(std::string("'") + SPIKE_BENCH +
                                             "' --smoothing dubins --turning-radius 0.5 --world-queries 5");
  ASSERT_EQ(b.code, 0) << b.text;
  for (const char* line : {"museum.smoothing.solved: 5 count", "museum.unsmoothed.max_curvature: ",
                           "museum.unsmoothed.mean_length: ", "museum.dubins.mean_length: ",
                           "museum.dubins.curvature_bound: 2 1/m", "museum.dubins.median_time: ",
                           "museum.dubins.smoothing_only.median_time: "})
    EXPECT_NE(b.text.find(line), std::string::npos) << line << "\n" << b.text;
  const size_t k = b.text.find("museum.dubins.max_curvature_fully_smoothed: ");
  ASSERT_NE(k, std::string::npos);
  EXPECT_LE(std::stod(b.text.substr(k + 44)), 2.0 * 1.001) << b.text;
  EXPECT_EQ(err(SPIKE_BENCH, "--smoothing bezier").code, 2);
  EXPECT_NE(help(SPIKE_BENCH).text.find("--turning-radius"), std::string::npos);
}
