// Sonar belt -> sector distances, the crisp data of AvoidObstacle. ROS-free.
#pragma once

#include <string>
#include <vector>

namespace mrt::scare {

/// An angular sector of the robot's surroundings (body frame, degrees,
/// counter-clockwise from ahead). A sonar belongs to a sector when its beam
/// axis lies in [from, to].
struct Sector {
  std::string name;   // crisp datum name, e.g. "ObstacleFront"
  double from_deg = 0.0;
  double to_deg = 0.0;
};

/// The default five sectors of the Roby rule base: Front [-25, 25],
/// FrontLeft [25, 70], FrontRight [-70, -25], Left [70, 115], Right [-115, -70].
std::vector<Sector> default_sectors();

/// Reduces the last reading of every sonar to the minimum range per sector.
class SonarSectors {
 public:
  /// `mount_deg[i]`: beam axis of sonar i. `max_range`: value of an empty
  /// sector (m).
  SonarSectors(std::vector<double> mount_deg, std::vector<Sector> sectors, double max_range);

  /// Stores sonar i's reading (m); a non-finite or negative one is refused
  /// (returns false) and the old reading kept.
  bool set_range(std::size_t sonar, double range_m);
  /// Minimum range per sector (m), in the order of `sectors()`.
  std::vector<double> distances() const;
  const std::vector<Sector>& sectors() const { return sectors_; }
  std::size_t sonar_count() const { return ranges_.size(); }
  /// Sectors each sonar feeds (for tests).
  const std::vector<std::vector<std::size_t>>& members() const { return members_; }

 private:
  std::vector<Sector> sectors_;
  std::vector<double> ranges_;
  std::vector<std::vector<std::size_t>> members_;  // per sector, sonar indices
  double max_range_;
};

/// Evenly spaced sonar mounts, the first facing forward (mrt_sim's `count`).
std::vector<double> even_mounts_deg(std::size_t count);

}  // namespace mrt::scare
