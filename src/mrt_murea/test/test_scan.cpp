// scan_percepts(): a laser scan's valid beams as Wall percepts, subsampled
// evenly; expected values worked out by hand below.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mrt_murea/scan.h"

namespace {

using mrt::murea::FeatureClass;
using mrt::murea::ScanGeometry;
using mrt::murea::scan_percepts;

TEST(ScanPercepts, ValidBeamsOnly) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  // Beam i at -1 + 0.5 i rad; valid: finite and 0.05 < r < 8.
  const std::vector<float> ranges{1.0f, nan, 0.01f, 2.0f, inf, 9.0f, 3.0f, 8.0f, 0.05f};
  std::size_t invalid = 0;
  const auto ps = scan_percepts(ranges, ScanGeometry{-1.0, 0.5, 0.05f, 8.0}, 30, &invalid);  // 0.05f as a LaserScan has it
  // Beams 0, 3, 6 at bearings -1, 0.5, 2; the other six are invalid.
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_EQ(invalid, 6u);
  const double d[3] = {1, 2, 3}, b[3] = {-1.0, 0.5, 2.0};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(ps[k].cls, FeatureClass::Wall);
    EXPECT_DOUBLE_EQ(ps[k].distance, d[k]);
    EXPECT_DOUBLE_EQ(ps[k].bearing, b[k]);
    EXPECT_DOUBLE_EQ(ps[k].reliability, 1.0);
  }
}

TEST(ScanPercepts, EvenSubsamplingOfTheValidBeams) {
  // 12 beams, beams 1 and 4 invalid (0): the valid ones are 0, 2, 3, 5, ...,
  // 11 (10 of them, range = index + 1). Four of ten: valid positions
  // floor(j 10 / 4) = 0, 2, 5, 7, i.e. beams 0, 3, 7, 9.
  std::vector<float> ranges;
  for (int i = 0; i < 12; ++i) ranges.push_back(i == 1 || i == 4 ? 0.0f : static_cast<float>(i + 1));
  const auto ps = scan_percepts(ranges, ScanGeometry{0.0, 0.1, 0.1, 100.0}, 4);
  ASSERT_EQ(ps.size(), 4u);
  const int beams[4] = {0, 3, 7, 9};
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(ps[k].distance, beams[k] + 1);
    EXPECT_NEAR(ps[k].bearing, 0.1 * beams[k], 1e-12);
  }
  // At most one beam: the first valid one; none from an empty scan.
  const auto one = scan_percepts(ranges, ScanGeometry{0.0, 0.1, 0.1, 100.0}, 0);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_DOUBLE_EQ(one[0].distance, 1.0);
  EXPECT_TRUE(scan_percepts({}, ScanGeometry{0.0, 0.1, 0.1, 100.0}, 30).empty());
}

}  // namespace
