// Colour look-up table: bin indexing, HSV and RGB ranges with precedence
// and hue wrap-around, samples, save/load.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <string>

#include "mrt_recvision/color_table.h"

using mrt::recvision::ColorClass;
using mrt::recvision::ColorTable;
using mrt::recvision::HsvRange;
using mrt::recvision::RgbRange;

TEST(ColorTable, BinIndexDropsThreeBitsPerChannel) {
  EXPECT_EQ(ColorTable::index(255, 255, 255), 32767);  // 31*1024 + 31*32 + 31
  EXPECT_EQ(ColorTable::index(8, 0, 0), 1024);
  EXPECT_EQ(ColorTable::index(7, 15, 16), 0 + 32 + 2);
}

TEST(ColorTable, HsvRangesClassifyUnderIlluminationChange) {
  ColorTable t;
  t.add_range(HsvRange{0, 360, 0, 1, 0, 0.16}, ColorClass::kBlack);
  t.add_range(HsvRange{0, 360, 0, 0.2, 0.55, 1}, ColorClass::kWhite);
  t.add_range(HsvRange{8, 40, 0.55, 1, 0.3, 1}, ColorClass::kOrange);
  t.add_range(HsvRange{80, 165, 0.3, 1, 0.17, 1}, ColorClass::kGreen);
  // Carpet (40,140,40): H 120, S 0.71, V 0.55; at 70 %: (28,98,28), V 0.38.
  EXPECT_EQ(t.classify(40, 140, 40), ColorClass::kGreen);
  EXPECT_EQ(t.classify(28, 98, 28), ColorClass::kGreen);
  // Line white at 70 %: (175,175,175), bin centre 172: S 0, V 0.67.
  EXPECT_EQ(t.classify(250, 250, 250), ColorClass::kWhite);
  EXPECT_EQ(t.classify(175, 175, 175), ColorClass::kWhite);
  // Ball (255,120,0): H 28; at 70 % (178,84,0): H 28, V 0.7.
  EXPECT_EQ(t.classify(255, 120, 0), ColorClass::kOrange);
  EXPECT_EQ(t.classify(178, 84, 0), ColorClass::kOrange);
  EXPECT_EQ(t.classify(15, 15, 15), ColorClass::kBlack);
  // Sky grey (120,120,130): S 0.08 but V 0.51 < 0.55: nothing.
  EXPECT_EQ(t.classify(120, 120, 130), ColorClass::kNone);
}

TEST(ColorTable, FirstRangeWinsAndHueWraps) {
  ColorTable t;
  t.add_range(HsvRange{345, 7, 0.5, 1, 0.3, 1}, ColorClass::kRed);
  t.add_range(HsvRange{0, 360, 0, 1, 0, 1}, ColorClass::kGreen);  // everything else
  // (255,0,10) -> bin centre (252,4,12): H = 360 - 60*(12-4)/248 = 358.1: red.
  EXPECT_EQ(t.classify(255, 0, 10), ColorClass::kRed);
  // (255,60,0) -> bin centre (252,60,4): H = 60*(60-4)/248 = 13.5: not red.
  EXPECT_EQ(t.classify(255, 60, 0), ColorClass::kGreen);
  EXPECT_EQ(t.count(ColorClass::kNone), 0);
}

TEST(ColorTable, RgbRangeSamplesAndOverlay) {
  ColorTable t;
  t.add_range(RgbRange{200, 255, 0, 50, 0, 50}, ColorClass::kRed);
  EXPECT_EQ(t.classify(220, 10, 10), ColorClass::kRed);
  EXPECT_EQ(t.classify(190, 10, 10), ColorClass::kNone);  // bin centre 188 < 200
  // r bins 25..31 (centres 204..252): 7; g and b bins 0..5 (centres 4..44; 52 > 50): 6 each.
  EXPECT_EQ(t.count(ColorClass::kRed), 7 * 6 * 6);
  ColorTable s;
  s.set(220, 10, 10, ColorClass::kMagenta);
  t.overlay(s);
  EXPECT_EQ(t.classify(223, 12, 9), ColorClass::kMagenta);  // same bin
  EXPECT_EQ(t.count(ColorClass::kRed), 7 * 6 * 6 - 1);
}

TEST(ColorTable, SaveLoadRoundTripAndBadFiles) {
  ColorTable t;
  t.add_range(HsvRange{80, 165, 0.3, 1, 0.17, 1}, ColorClass::kGreen);
  t.set(255, 120, 0, ColorClass::kOrange);
  const std::string path = ::testing::TempDir() + "/lut_roundtrip.png";
  t.save(path);
  const ColorTable u = ColorTable::load(path);
  EXPECT_EQ(u.data(), t.data());
  const std::string bad = ::testing::TempDir() + "/lut_bad.png";
  cv::imwrite(bad, cv::Mat(10, 10, CV_8UC1, cv::Scalar(1)));
  EXPECT_THROW(ColorTable::load(bad), std::runtime_error);
  cv::imwrite(bad, cv::Mat(128, 256, CV_8UC1, cv::Scalar(77)));  // class 77 does not exist
  EXPECT_THROW(ColorTable::load(bad), std::runtime_error);
  std::remove(path.c_str());
  std::remove(bad.c_str());
}
