#include <gtest/gtest.h>

#include "mrt_common/geodesy.h"

using mrt::common::GeoPoint;
using mrt::common::LocalTangentPlane;

// One thousandth of a degree of latitude is R * pi / 180 / 1000
// = 6378137 * 0.0174532925 / 1000 = 111.31949 m north; of longitude at 45 deg
// it is that times cos(45 deg) = 111.31949 * 0.70711 = 78.71477 m east.
TEST(Geodesy, ThousandthOfADegreeAtLatitude45) {
  const LocalTangentPlane ltp({45.0, 9.0});
  const auto p = ltp.to_local({45.001, 9.001});
  EXPECT_NEAR(p.y, 111.31949, 1e-4);
  EXPECT_NEAR(p.x, 78.71477, 1e-4);
}

TEST(Geodesy, RoundTripAndDatum) {
  const LocalTangentPlane ltp({45.4781, 9.2273});
  const auto o = ltp.to_local(ltp.datum());
  EXPECT_DOUBLE_EQ(o.x, 0.0);
  EXPECT_DOUBLE_EQ(o.y, 0.0);
  const GeoPoint g = ltp.to_geodetic({-123.4, 456.7});
  const auto back = ltp.to_local(g);
  EXPECT_NEAR(back.x, -123.4, 1e-9);
  EXPECT_NEAR(back.y, 456.7, 1e-9);
}

TEST(Geodesy, ValidDatum) {
  EXPECT_TRUE(LocalTangentPlane::valid_datum({45.0, 9.0}));
  EXPECT_FALSE(LocalTangentPlane::valid_datum({90.0, 9.0}));
  EXPECT_FALSE(LocalTangentPlane::valid_datum({45.0, std::nan("")}));
}
