#include "mrt_roby/sonar_sectors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::roby {

std::vector<Sector> default_sectors() {
  return {{"ObstacleFront", -25.0, 25.0},
          {"ObstacleFrontLeft", 25.0, 70.0},
          {"ObstacleFrontRight", -70.0, -25.0},
          {"ObstacleLeft", 70.0, 115.0},
          {"ObstacleRight", -115.0, -70.0},
          {"ObstacleBack", 145.0, -145.0}};
}

std::vector<double> even_mounts_deg(std::size_t count) {
  std::vector<double> m;
  for (std::size_t i = 0; i < count; ++i) m.push_back(360.0 * static_cast<double>(i) / count);
  return m;
}

SonarSectors::SonarSectors(std::vector<double> mount_deg, std::vector<Sector> sectors,
                           double max_range, double stale_after)
    : sectors_(std::move(sectors)), ranges_(mount_deg.size(), max_range),
      times_(mount_deg.size(), -std::numeric_limits<double>::infinity()), members_(sectors_.size()),
      max_range_(max_range), stale_after_(stale_after) {
  if (!(max_range > 0.0)) throw std::invalid_argument("max_range must be > 0");
  if (!(stale_after >= 0.0)) throw std::invalid_argument("stale_after must be >= 0");
  for (std::size_t i = 0; i < mount_deg.size(); ++i) add_member(i, mount_deg[i]);
}

void SonarSectors::add_member(std::size_t i, double mount_deg) {
  // Beam axis in (-180, 180].
  const double a = common::rad_to_deg(common::normalize_angle(common::deg_to_rad(mount_deg)));
  for (std::size_t s = 0; s < sectors_.size(); ++s) {
    const bool after_from = a >= sectors_[s].from_deg - 1e-9, before_to = a <= sectors_[s].to_deg + 1e-9;
    const bool wraps = sectors_[s].from_deg > sectors_[s].to_deg;
    if (wraps ? (after_from || before_to) : (after_from && before_to)) members_[s].push_back(i);
  }
}

bool SonarSectors::set_mount(std::size_t sonar, double mount_deg) {
  if (sonar >= ranges_.size() || !std::isfinite(mount_deg)) return false;
  for (auto& m : members_) m.erase(std::remove(m.begin(), m.end(), sonar), m.end());
  add_member(sonar, mount_deg);
  return true;
}

bool SonarSectors::set_range(std::size_t sonar, double range_m, double t, double sensor_max) {
  if (sonar >= ranges_.size() || std::isnan(range_m)) return false;
  if (range_m == -std::numeric_limits<double>::infinity()) range_m = 0.0;  // too close to measure
  if (range_m < 0.0) return false;
  // Beyond the sensor's own max_range a reading says only "nothing within
  // max_range" (REP-117): it counts as that range, not as what it claims.
  if (sensor_max > 0.0) range_m = std::min(range_m, sensor_max);
  ranges_[sonar] = std::min(range_m, max_range_);  // +Inf: nothing in range
  times_[sonar] = t;
  return true;
}

bool SonarSectors::is_stale(std::size_t sonar, double now) const {
  return stale_after_ > 0.0 && !(now - times_[sonar] <= stale_after_);
}

std::vector<double> SonarSectors::distances(double now) const {
  std::vector<double> d(sectors_.size(), max_range_);
  for (std::size_t s = 0; s < sectors_.size(); ++s)
    for (std::size_t i : members_[s]) d[s] = std::min(d[s], is_stale(i, now) ? 0.0 : ranges_[i]);
  return d;
}

std::vector<std::size_t> SonarSectors::stale(double now) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < ranges_.size(); ++i)
    if (is_stale(i, now)) out.push_back(i);
  return out;
}

}  // namespace mrt::roby
