// Local tangent plane around a datum: the equirectangular projection used by
// the simulator's DGPS and by every localizer that reads a GPS fix (x east,
// y north, metres; latitude and longitude in degrees). ROS-free.
#pragma once

#include <cmath>

#include "mrt_common/angle.h"
#include "mrt_common/pose2d.h"

namespace mrt::common {

/// WGS84 semi-major axis, m: the Earth radius of the projection.
constexpr double kEarthRadius = 6378137.0;

struct GeoPoint {
  double latitude = 0.0;   // degrees
  double longitude = 0.0;  // degrees
};

/// Equirectangular projection around `datum`, exact at the datum and good to
/// a few millimetres over the few hundred metres of a robot's world.
class LocalTangentPlane {
 public:
  explicit LocalTangentPlane(GeoPoint datum) : datum_(datum), cos_lat0_(std::cos(deg_to_rad(datum.latitude))) {}

  Point2D to_local(const GeoPoint& g) const {
    return {deg_to_rad(g.longitude - datum_.longitude) * kEarthRadius * cos_lat0_,
            deg_to_rad(g.latitude - datum_.latitude) * kEarthRadius};
  }

  GeoPoint to_geodetic(const Point2D& p) const {
    return {datum_.latitude + rad_to_deg(p.y / kEarthRadius),
            datum_.longitude + rad_to_deg(p.x / (kEarthRadius * cos_lat0_))};
  }

  const GeoPoint& datum() const { return datum_; }

  /// True when the datum can carry a projection (|latitude| < 90, finite).
  static bool valid_datum(const GeoPoint& g) {
    return std::isfinite(g.latitude) && std::isfinite(g.longitude) && std::fabs(g.latitude) < 90.0;
  }

 private:
  GeoPoint datum_;
  double cos_lat0_;
};

}  // namespace mrt::common
