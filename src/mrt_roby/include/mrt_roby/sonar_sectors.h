// Sonar belt -> sector distances, the crisp data of AvoidObstacle. ROS-free.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace mrt::roby {

/// An angular sector of the robot's surroundings (body frame, degrees,
/// counter-clockwise from ahead). A sonar belongs to a sector when its beam
/// axis lies in [from, to], or, when from > to (a sector across 180 deg,
/// behind), in [from, 180] or (-180, to].
struct Sector {
  std::string name;   // crisp datum name, e.g. "ObstacleFront"
  double from_deg = 0.0;
  double to_deg = 0.0;
};

/// The default six sectors of the Roby rule base: Front [-25, 25],
/// FrontLeft [25, 70], FrontRight [-70, -25], Left [70, 115], Right
/// [-115, -70], Back [145, -145] (across 180).
std::vector<Sector> default_sectors();

/// Reduces the last reading of every sonar to the minimum range per sector.
class SonarSectors {
 public:
  /// `mount_deg[i]`: beam axis of sonar i. `max_range`: value of an empty
  /// sector (m). `stale_after` (s, 0 = never): a sonar whose last reading is
  /// older than this reads 0 m, so a silent sonar blocks its sector rather
  /// than leave its last (possibly clear) reading in force.
  SonarSectors(std::vector<double> mount_deg, std::vector<Sector> sectors, double max_range,
               double stale_after = 0.0);

  /// Stores sonar i's reading (m) taken at time `t` (s). As REP-117 says,
  /// +Inf is "nothing within range" (max_range) and -Inf "too close to
  /// measure" (0); NaN or a negative range is refused (returns false) and
  /// the old reading kept.
  /// `sensor_max` (> 0): the sensor's own maximum range (sensor_msgs/Range
  /// max_range); a reading above it counts as sensor_max.
  bool set_range(std::size_t sonar, double range_m, double t = 0.0,
                 double sensor_max = std::numeric_limits<double>::infinity());
  /// Moves sonar i's beam axis (deg, CCW from ahead), e.g. to the direction
  /// tf gives for its Range message's frame. False for a bad index or angle.
  bool set_mount(std::size_t sonar, double mount_deg);
  /// Minimum range per sector (m) at time `now`, in the order of `sectors()`.
  std::vector<double> distances(double now = 0.0) const;
  /// Sonars whose reading is stale at `now` (never read counts as stale).
  std::vector<std::size_t> stale(double now) const;
  const std::vector<Sector>& sectors() const { return sectors_; }
  std::size_t sonar_count() const { return ranges_.size(); }
  /// Sectors each sonar feeds (for tests).
  const std::vector<std::vector<std::size_t>>& members() const { return members_; }

 private:
  std::vector<Sector> sectors_;
  std::vector<double> ranges_;
  std::vector<double> times_;                      // s, of each sonar's reading (-inf: never)
  std::vector<std::vector<std::size_t>> members_;  // per sector, sonar indices
  double max_range_, stale_after_;
  bool is_stale(std::size_t sonar, double now) const;
  void add_member(std::size_t sonar, double mount_deg);
};

/// Evenly spaced sonar mounts, the first facing forward (mrt_sim's `count`).
std::vector<double> even_mounts_deg(std::size_t count);

}  // namespace mrt::roby
