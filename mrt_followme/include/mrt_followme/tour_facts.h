// The facts of the tour that SCARE's task machines read (the distributed
// FollowMe, config/tasks.yaml): how far the robot is from the exhibit's stop,
// whether the visitor has looked at the exhibit, is ready to go on, has
// wandered off, is back, is lagging behind. Inputs: the localizer's pose and
// the visitor as MAP tracks it (camera only). ROS-free; the same thresholds
// as the in-process guide (GuideOptions).
#pragma once

#include <optional>

#include "mrt_followme/museum.h"

namespace mrt::followme {

struct TourFacts {
  double exhibit_distance = 1e9;  // m, the pose to the current exhibit's stop
  bool visitor_seen = false;      // MAP has a track of the visitor
  double visitor_distance = 1e9;  // m, from the robot (when seen)
  double visitor_bearing = 0.0;   // rad, CCW from the robot's heading
  bool looked = false;            // stood within look_radius of the spot for look_time
  bool ready = false;             // looked, left the spot (half look_radius), stands within ready_distance of the robot
  bool wandered = false;          // stands beyond ready_distance from the robot and wander_distance from the spot, or lost
  bool lost = false;              // out of sight for lost_time
  bool back = false;              // within ready_distance of the robot
  bool lagging = false;           // farther than keep_max (until back within keep_resume)
  bool still = false;             // standing still for call_after
};

class TourFactsTracker {
 public:
  explicit TourFactsTracker(GuideOptions o) : opt_(o) {}

  /// A new exhibit: what was looked at is forgotten.
  void set_exhibit(const Exhibit& e);
  /// One update at `t` (s): `visitor` is MAP's track of the visitor (world
  /// frame), none when it has none; `speed` its speed (m/s).
  TourFacts update(double t, const Pose2D& pose, const std::optional<Point2D>& visitor, double speed);

  const std::optional<Exhibit>& exhibit() const { return exhibit_; }

 private:
  GuideOptions opt_;
  std::optional<Exhibit> exhibit_;
  double last_t_ = -1.0, looked_for_ = 0.0, last_seen_ = -1e9, still_since_ = -1.0;
  bool lagging_ = false;
};

}  // namespace mrt::followme
