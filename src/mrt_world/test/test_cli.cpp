// world_map runs as a program: --help exits 0 and lists its options; a
// usage error exits 2; a bad file exits 2 with file:line; a world written
// as a map_server map reads back with the same occupied cells.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "mrt_common/testing/cli_runner.h"

using mrt::common::testing::err;
using mrt::common::testing::help;
using mrt::common::testing::out;
using mrt::common::testing::Output;

TEST(WorldMapCli, HelpAndUsageErrors) {
  const Output h = help(WORLD_MAP);
  EXPECT_EQ(h.code, 0);
  for (const char* opt : {"--resolution", "--out"}) EXPECT_NE(h.text.find(opt), std::string::npos) << opt;
  const Output u = err(WORLD_MAP, "--bogus");
  EXPECT_EQ(u.code, 2);
  EXPECT_NE(u.text.find("world_map: "), std::string::npos) << u.text;
  EXPECT_EQ(err(WORLD_MAP, std::string(MRT_WORLDS_DIR) + "/museum.yaml --resolution -1").code, 2);
}

TEST(WorldMapCli, BadFileNamesLine) {
  const std::string path = ::testing::TempDir() + "world_cli_bad.yaml";
  std::ofstream(path) << "name: x\nbounds: [0, 0, 1]\n";
  const Output bad = err(WORLD_MAP, path);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.text.find("world_cli_bad.yaml:2:"), std::string::npos) << bad.text;
}

// The museum (20 x 12 m) at 0.5 m: 40 x 24 cells; written as a map_server
// map and read back, the same summary line.
TEST(WorldMapCli, RoundTripThroughMapServerFormat) {
  const std::string prefix = ::testing::TempDir() + "world_cli_museum";
  const std::string first = out(WORLD_MAP, std::string(MRT_WORLDS_DIR) + "/museum.yaml --resolution 0.5 --out " + prefix);
  EXPECT_NE(first.find("world museum: bounds [0, 0, 20, 12]"), std::string::npos) << first;
  const auto grid = first.substr(first.find("grid "));
  EXPECT_EQ(grid.rfind("grid 40 x 24 cells of 0.5 m, origin (0, 0, 0), ", 0), 0u) << grid;
  ASSERT_TRUE(std::filesystem::exists(prefix + ".pgm"));
  EXPECT_EQ(out(WORLD_MAP, prefix + ".yaml"), grid);
}
