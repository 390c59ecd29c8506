// The moving obstacles spike_node plans around, ROS-free: objects of the
// obstacle classes from percepts (one track per robot and object name, the
// velocity estimated between sightings when not given) and the anchors of
// MAP's world model (one track per producer and anchor id, removed when the
// producer's next model lacks them), forgotten after a timeout. The tracker
// writes them into an ObstacleSink (WorldPlanner); the node only converts
// messages and transforms.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "mrt_common/percept.h"
#include "mrt_common/pose2d.h"

namespace mrt::spike {

/// Where the tracker puts its obstacles: map frame, m and m/s.
class ObstacleSink {
 public:
  virtual ~ObstacleSink() = default;
  /// Adds or moves obstacle `id`: at (x, y), radius r, velocity (vx, vy).
  virtual void set_obstacle(int id, double x, double y, double r, double vx, double vy) = 0;
  virtual void remove_obstacle(int id) = 0;
};

struct ObstacleTrackerOptions {
  /// Classes that are obstacles, matched exactly (no hierarchy).
  std::vector<std::string> classes{mrt::common::percept_class::kPerson, mrt::common::percept_class::kRobot,
                                   mrt::common::percept_class::kTeammate, mrt::common::percept_class::kOpponent,
                                   mrt::common::percept_class::kObstacle};
  double default_radius = 0.25;  ///< m, a percept object's without `radius`, an anchor's base
  double timeout = 1.0;          ///< s after its last sighting an obstacle is forgotten
  double anchor_sigmas = 1.0;    ///< an anchor's radius grows by this many position std devs
};

/// One anchor of MAP's world model (mrt_msgs/Anchor), in the model's frame.
struct WorldModelAnchor {
  unsigned id = 0;
  std::string membership_class;
  bool tentative = false;
  double x = 0.0, y = 0.0;      ///< m
  double vx = 0.0, vy = 0.0;    ///< m/s
  double var_x = 0.0, var_y = 0.0;  ///< variances of x and y, m^2
};

/// An obstacle as last written to the sink (map frame).
struct TrackedObstacle {
  int id = 0;  ///< the sink's id: 0, 1, 2, ... in order of creation, never reused
  double x = 0.0, y = 0.0, radius = 0.0, vx = 0.0, vy = 0.0;
  double seen = 0.0;  ///< s, the stamp of the last sighting
};

class ObstacleTracker {
 public:
  ObstacleTracker(ObstacleTrackerOptions options, ObstacleSink& sink);

  /// The objects of one percept of `robot` (checked against the ontology by
  /// the caller), positions in the percept's frame, `to_map` that frame's
  /// pose in the map frame, `stamp` in s. An object of an obstacle class is
  /// tracked as "robot/name" at its position (Cartesian or polar form),
  /// with its `radius` (else the default) and its `vx`, `vy` when it has
  /// both (taken as they are), else the velocity between its last two
  /// sightings (0 for the first, or when they are 1 ms apart or less). One
  /// without a finite position is dropped. Returns the objects dropped.
  std::size_t add_percept(const std::string& robot, const std::vector<mrt::common::PerceptObject>& objects,
                          const mrt::common::Pose2D& to_map, double stamp);

  /// MAP's complete world model from `robot`: each anchor of an obstacle
  /// class not tentative is tracked as "world_model:robot/id", position and
  /// velocity rotated into the map frame (a non-finite vx gives 0), radius
  /// default + anchor_sigmas x sqrt(larger of var_x, var_y) (0 when not
  /// finite and positive); that producer's anchors missing from this model
  /// are removed. An anchor without a finite position is dropped. Returns
  /// the anchors dropped.
  std::size_t add_world_model(const std::string& robot, const std::vector<WorldModelAnchor>& anchors,
                              const mrt::common::Pose2D& to_map, double stamp);

  /// Removes the obstacles last seen more than the timeout before `now` (s);
  /// returns how many.
  std::size_t expire(double now);

  /// True once after the obstacles changed (added, moved, removed).
  bool take_changed();
  const std::map<std::string, TrackedObstacle>& tracks() const { return tracks_; }
  std::size_t size() const { return tracks_.size(); }
  /// Objects and anchors dropped so far.
  std::size_t dropped() const { return dropped_; }
  const ObstacleTrackerOptions& options() const { return options_; }

 private:
  bool is_obstacle(const std::string& cls) const;
  void update(const std::string& key, TrackedObstacle o, bool has_velocity);
  void remove(std::map<std::string, TrackedObstacle>::iterator& it);

  ObstacleTrackerOptions options_;
  ObstacleSink& sink_;
  std::map<std::string, TrackedObstacle> tracks_;
  int next_id_ = 0;
  bool changed_ = false;
  std::size_t dropped_ = 0;
};

}  // namespace mrt::spike
