#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"

using mrt::common::ParseError;

TEST(ParseError, FormatsFileLineColumn) {
  const ParseError e("behaviors/GoToTarget.rul", 17, 4, "expected ';' after rule");
  EXPECT_STREQ(e.what(), "behaviors/GoToTarget.rul:17:4: expected ';' after rule");
  EXPECT_EQ(e.file(), "behaviors/GoToTarget.rul");
  EXPECT_EQ(e.line(), 17);
  EXPECT_EQ(e.column(), 4);
  EXPECT_EQ(e.message(), "expected ';' after rule");
}

TEST(ParseError, OmitsUnknownPositions) {
  EXPECT_STREQ(ParseError("a.yaml", 3, 0, "bad").what(), "a.yaml:3: bad");
  EXPECT_STREQ(ParseError("a.yaml", 0, 0, "cannot open file").what(), "a.yaml: cannot open file");
}
