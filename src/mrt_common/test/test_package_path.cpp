// ROS package paths without ROS (package_path.h) on a made-up tree:
//   <tmp>/ws/src/alpha/package.xml           <name>alpha</name>
//   <tmp>/ws/src/group/beta_dir/package.xml  <name>beta</name>  (crawled)
//   <tmp>/ws/src/group/beta_dir/inner/package.xml  (inside a package: not crawled)
//   <tmp>/ws/src/ignored/CATKIN_IGNORE, ignored/gamma/package.xml
//   <tmp>/share/delta/package.xml            <name>delta</name> (an install space)
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "mrt_common/package_path.h"

namespace fs = std::filesystem;
using namespace mrt::common;

namespace {

class PackagePath : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(::testing::TempDir()) / ("mrt_package_path_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    package(root_ / "ws/src/alpha", "alpha");
    package(root_ / "ws/src/group/beta_dir", "beta");
    package(root_ / "ws/src/group/beta_dir/inner", "inner");
    package(root_ / "ws/src/ignored/gamma", "gamma");
    std::ofstream(root_ / "ws/src/ignored/CATKIN_IGNORE");
    package(root_ / "share/delta", "delta");
    path_ = (root_ / "ws/src").string() + ":" + (root_ / "share").string();
  }
  void TearDown() override { fs::remove_all(root_); }

  static void package(const fs::path& dir, const std::string& name) {
    fs::create_directories(dir);
    std::ofstream(dir / "package.xml") << "<?xml version=\"1.0\"?>\n<package format=\"2\">\n  <name> " << name
                                       << " </name>\n  <version>0.1.0</version>\n</package>\n";
  }

  fs::path root_;
  std::string path_;
};

}  // namespace

TEST_F(PackagePath, FindsPackagesAsRospackDoes) {
  EXPECT_EQ(find_package_dir("alpha", path_), (root_ / "ws/src/alpha").string());
  EXPECT_EQ(find_package_dir("beta", path_), (root_ / "ws/src/group/beta_dir").string());
  EXPECT_EQ(find_package_dir("delta", path_), (root_ / "share/delta").string());
  EXPECT_EQ(find_package_dir("inner", path_), "");   // below a package
  EXPECT_EQ(find_package_dir("gamma", path_), "");   // CATKIN_IGNORE
  EXPECT_EQ(find_package_dir("zeta", path_), "");
  EXPECT_EQ(find_package_dir("alpha", ""), "");
  // A root that is itself the package.
  EXPECT_EQ(find_package_dir("delta", (root_ / "share/delta").string()), (root_ / "share/delta").string());
}

TEST_F(PackagePath, ResolvesPackageUrlsThroughAFinder) {
  const PackageFinder finder = [&](const std::string& n) { return find_package_dir(n, path_); };
  EXPECT_EQ(resolve_package_url("package://alpha/config/x.txt", finder), (root_ / "ws/src/alpha/config/x.txt").string());
  EXPECT_EQ(resolve_package_url("package://delta", finder), (root_ / "share/delta").string());
  // Other paths stay as they are.
  EXPECT_EQ(resolve_package_url("../x.txt", finder), "../x.txt");
  EXPECT_EQ(resolve_package_url("/abs/x.txt", finder), "/abs/x.txt");
  EXPECT_TRUE(is_package_url("package://a/b"));
  EXPECT_FALSE(is_package_url("file://a/b"));
  try {
    resolve_package_url("package://zeta/x.txt", finder);
    FAIL() << "no error for an unknown package";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("package 'zeta'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(resolve_package_url("package:///x.txt", finder), std::invalid_argument);
  // Explicit roots (what a build gives a ROS-free program) come first.
  const PackageFinder roots = package_finder({{"alpha", "/elsewhere/alpha"}});
  EXPECT_EQ(resolve_package_url("package://alpha/f", roots), "/elsewhere/alpha/f");
}
