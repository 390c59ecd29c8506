// The percept CSV: a row written and read back; frames in order of first
// appearance; malformed rows named by file:line:column.
#include <gtest/gtest.h>

#include <sstream>

#include "mrt_common/percept_csv.h"

using namespace mrt::common;

TEST(PerceptCsv, WriteAndReadBack) {
  std::ostringstream out;
  write_percept_csv_header(out);
  PerceptObject b("", percept_class::kBall);
  b.set_polar({2.15873, -0.23374, 0.0, 0.0, 0.9}).set_symbol("color", "orange");
  PerceptObject l("", percept_class::kLine);
  l.set_cartesian({1.0, 1.0});  // read as polar: sqrt(2) at pi/4
  write_percept_csv_row(out, "12.500000", b);
  write_percept_csv_row(out, "12.500000", l);
  write_percept_csv_row(out, "12.500000", PerceptObject("", "Ball"));  // no position: no row
  EXPECT_EQ(out.str(),  // recvision_run's header (issue 14)
            "stamp,class,color,distance,bearing,reliability\n"
            "12.500000,Ball,orange,2.1587,-0.23374,0.900\n"
            "12.500000,Line,,1.4142,0.78540,1.000\n");
  std::istringstream in(out.str() + "13,Goal,yellow,4,0.5,1\n12.500000,Wall,,nan,0,1\n");
  const auto frames = read_percept_csv(in, "p.csv");
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].id, "12.500000");
  EXPECT_EQ(frames[0].line, 2);
  ASSERT_EQ(frames[0].objects.size(), 3u);  // the Wall row joins its frame
  EXPECT_EQ(frames[0].objects[0].symbol("color"), "orange");
  EXPECT_DOUBLE_EQ(*frames[0].objects[0].number("distance"), 2.1587);
  EXPECT_DOUBLE_EQ(frames[0].objects[0].find("bearing")->reliability, 0.9);
  EXPECT_TRUE(std::isnan(*frames[0].objects[2].number("distance")));  // the consumer decides
  EXPECT_EQ(frames[1].objects[0].membership_class, "Goal");
}

// The header row is optional (the format of issue 15 had none) and names
// the first column `frame` (murea_localize) or `stamp` (recvision_run): the
// same objects every way.
TEST(PerceptCsv, HeaderRowOptional) {
  std::istringstream bare("# frames 1 and 2\n1,Ball,orange,2,0.5,0.9\n1,Line,,1,0,1\n2,Goal,yellow,4,-0.25,1\n");
  const auto frames = read_percept_csv(bare, "p.csv");
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].line, 2);
  ASSERT_EQ(frames[0].objects.size(), 2u);
  EXPECT_EQ(frames[0].objects[0].membership_class, "Ball");
  EXPECT_DOUBLE_EQ(*frames[0].objects[0].number("bearing"), 0.5);
  EXPECT_DOUBLE_EQ(frames[0].objects[0].find("distance")->reliability, 0.9);
  EXPECT_DOUBLE_EQ(*frames[1].objects[0].number("bearing"), -0.25);
  for (const std::string first : {"frame", "stamp"}) {
    std::istringstream headed(first + ",class,color,distance,bearing,reliability\n1,Ball,orange,2,0.5,0.9\n");
    const auto again = read_percept_csv(headed, "p.csv");
    ASSERT_EQ(again.size(), 1u) << first;
    EXPECT_EQ(again[0].line, 2);
    EXPECT_DOUBLE_EQ(*again[0].objects[0].number("distance"), 2.0);
  }
}

TEST(PerceptCsv, MalformedRowsNamed) {
  auto error = [](const std::string& text) {
    std::istringstream in(text);
    try {
      read_percept_csv(in, "p.csv");
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A first line that is not the header is a record: a misspelt header is
  // named as such.
  EXPECT_EQ(error("time,class,color,distance,bearing,reliability\n"),
            "p.csv:1:18: expected a number in column 'distance', got 'distance' "
            "(a header row is exactly 'frame,class,color,distance,bearing,reliability', or with 'stamp' first)");
  EXPECT_NE(error("frame,class,color,distance,bearing,reliability\n1,Ball,,x,0,1\n").find("p.csv:2:9: expected a number in column 'distance'"),
            std::string::npos)
      << error("frame,class,color,distance,bearing,reliability\n1,Ball,,x,0,1\n");
  EXPECT_NE(error("frame,class,color,distance,bearing,reliability\n,Ball,,1,0,1\n").find("p.csv:2:1: expected a frame id"),
            std::string::npos);
}
