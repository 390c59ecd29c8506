#include <gtest/gtest.h>

#include <sstream>

#include "mrt_common/csv.h"

using namespace mrt::common;

TEST(Csv, ReadsHeaderAndRowsSkippingComments) {
  std::istringstream in("# readings\nt,left_dx, left_dy\n\n0.1,3,-4\n# gap\n0.2, 5 ,6\n");
  const CsvReader r(in, "r.csv");
  ASSERT_EQ(r.header().size(), 3u);
  EXPECT_EQ(r.column("left_dy"), 2u);
  ASSERT_EQ(r.rows().size(), 2u);
  EXPECT_EQ(r.rows()[1].line, 6);
  EXPECT_DOUBLE_EQ(r.number(r.rows()[0], 0), 0.1);
  EXPECT_EQ(r.integer(r.rows()[0], 2), -4);
  EXPECT_EQ(r.integer(r.rows()[1], 1), 5);
  EXPECT_NO_THROW(r.require_header({"t", "left_dx", "left_dy"}));
}

TEST(Csv, ErrorsNameFileLineAndColumn) {
  std::istringstream in("t,dx\n0.1,3\n0.2,x7\n");
  const CsvReader r(in, "r.csv");
  try {
    r.integer(r.rows()[1], 1);
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 5);
    EXPECT_STREQ(e.what(), "r.csv:3:5: expected an integer in column 'dx', got 'x7'");
  }
  std::istringstream short_row("t,dx\n0.1\n");
  try {
    CsvReader bad(short_row, "s.csv");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_STREQ(e.what(), "s.csv:2: expected 2 fields, got 1");
  }
  EXPECT_THROW(r.column("nope"), ParseError);
  EXPECT_THROW(r.require_header({"t", "dy"}), ParseError);
  std::istringstream empty("");
  EXPECT_THROW(CsvReader(empty, "e.csv"), ParseError);
  std::istringstream nan_in("t\nnan\n");
  const CsvReader n(nan_in, "n.csv");
  EXPECT_THROW(n.number(n.rows()[0], 0), ParseError);
}

TEST(Csv, WriterRoundTripsDoubles) {
  std::ostringstream out;
  CsvWriter w(out, {"t", "x"});
  w.row({0.1, 1.0 / 3.0});
  std::istringstream in(out.str());
  const CsvReader r(in, "w.csv");
  EXPECT_EQ(r.number(r.rows()[0], 1), 1.0 / 3.0);  // exact round trip
  EXPECT_EQ(out.str().substr(0, 4), "t,x\n");
}
