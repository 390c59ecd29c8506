// The team's rule bases (config/brian) are clean for Mr. BRIAN's checker
// (manual §10.4.7, brian_check) and load; a broken copy is reported, so the
// check can fail.
#include <gtest/gtest.h>

#include <string>

#include "mrt_brian/brian.h"
#include "mrt_brian/checker.h"

namespace {

const std::string kConfig = MRT_ROBOCUP_CONFIG;

std::string report(const std::vector<mrt::brian::Diagnostic>& d) {
  std::string s;
  for (const auto& x : d) s += x.file + ":" + std::to_string(x.line) + ": " + x.message + "\n";
  return s;
}

TEST(RuleBases, DifferentialIsCheckerClean) {
  const auto d = mrt::brian::Checker().check_path(kConfig + "/brian/differential/BrianConfigs.ini");
  EXPECT_TRUE(d.empty()) << report(d);
  EXPECT_NO_THROW(mrt::brian::Brian::from_path(kConfig + "/brian/differential/BrianConfigs.ini"));
}

TEST(RuleBases, OmniIsCheckerClean) {
  const auto d = mrt::brian::Checker().check_path(kConfig + "/brian/omni/BrianConfigs.ini");
  EXPECT_TRUE(d.empty()) << report(d);
  EXPECT_NO_THROW(mrt::brian::Brian::from_path(kConfig + "/brian/omni/BrianConfigs.ini"));
}

// Both rule bases have the same behaviours (the shared CANDO and WANT files
// name them): 9 at level 1, AvoidObstacle at 2, AvoidCollision and LeaveArea at 3.
TEST(RuleBases, SameHierarchy) {
  const auto diff = mrt::brian::Brian::from_path(kConfig + "/brian/differential/BrianConfigs.ini");
  const auto omni = mrt::brian::Brian::from_path(kConfig + "/brian/omni/BrianConfigs.ini");
  EXPECT_EQ(diff->cando().size(), 12u);
  EXPECT_EQ(omni->cando().size(), 12u);
}

TEST(RuleBases, BrokenCopyIsReported) {
  const auto d = mrt::brian::Checker().check_path(std::string(MRT_ROBOCUP_TEST_DATA) + "/broken/BrianConfigs.ini");
  ASSERT_FALSE(d.empty());
  EXPECT_NE(report(d).find("BallBehind"), std::string::npos) << report(d);
}

}  // namespace
