// FollowMe in one process, without ROS: the mrt_sim museum, the visitor
// behaviour model steering its mover, the robot's encoders and camera
// percepts, MUREA (mrt_murea's Tracker) localizing on the landmarks, the
// visitor tracker, the guide's jobs, SPIKE (mrt_spike's WorldPlanner)
// planning each leg, the sonar sectors and Mr. BRIAN with Roby's rule base
// in closed loop, in simulated time. Used by followme_run, the gtests and
// the benchmark; the ROS bringup wires the same pieces as nodes. ROS-free.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrt_followme/guide.h"
#include "mrt_followme/museum.h"
#include "mrt_followme/visitor_model.h"

namespace mrt::sim {
struct World;
}

namespace mrt::followme {

struct FollowMeLoopOptions {
  std::string world;        // mrt_sim world file (the museum)
  std::string config;       // config/followme.yaml
  std::string brian;        // rule base (config/brian: Roby's, shared)
  /// Package directories for the rule base's package:// paths (what a build
  /// gives a ROS-free program); packages not here: ROS_PACKAGE_PATH.
  std::map<std::string, std::string> packages;
  std::string robot = "robot1";
  std::vector<std::string> tour;  // empty: the config's
  double duration = 600.0;  // s of simulated time at most
  double brian_rate = 10.0; // Hz of the guide and Mr. BRIAN
  std::string close_door;   // a door closed ...
  int close_at_leg = -1;    // ... when the leg to this exhibit (0-based) starts
  int wander_after = -1;    // >= 0: overrides the visitor's wander_after (0: never wanders)
  bool use_ground_truth = false;  // pose from the truth instead of MUREA (debug)
};

struct DoorCrossing {
  double t = 0.0;
  std::string door;         // the config's door the robot went through
};

struct FollowMeResult {
  std::vector<std::string> visited;   // exhibits of the tour, in the order visited
  std::size_t wanders = 0;            // wanders handled (followed, called back, re-planned)
  std::size_t replans = 0;            // plans asked of SPIKE
  bool completed = false;
  double time = 0.0;                  // s until the tour was completed (or the end)
  double max_unseen = 0.0;            // s, longest time the visitor was out of the camera's sight
  double min_person_gap = 1e9;        // m, robot footprint to any person's (ground truth)
  std::string nearest_person;
  double min_clearance = 1e9;         // m, robot footprint to walls and posts
  double max_pose_error = 0.0;        // m, MUREA vs ground truth (after the first fix)
  double max_wait_at_exhibit = 0.0;   // s, longest WaitVisitor
  std::vector<double> waits;          // s, each WaitVisitor's duration
  std::size_t follow_goals = 0;       // cycles in FollowVisitor with a goal (the robot followed)
  std::vector<DoorCrossing> doors;    // in order
  std::vector<std::vector<Point2D>> plans;  // every plan SPIKE gave
  std::vector<GuideEvent> events;
  std::string visitor_state;          // the visitor model's last state
};

/// One cycle's state for a progress callback (the tool's trace).
struct FollowMeTick {
  double t = 0.0;
  Pose2D truth, estimate;
  Point2D visitor;
  Job job = Job::kReplan;
  VisitorState visitor_state = VisitorState::kFollow;
};

/// What a viewer shows of one moment: the people, the plan, the doors closed.
struct FollowMeView {
  struct Person {
    std::string name, color;
    Point2D position;
    double radius = 0.25;
  };
  std::vector<Person> people;
  std::vector<Point2D> plan;
  std::vector<std::string> closed_doors;
  std::optional<Point2D> visitor_track;  // where the robot thinks its visitor is
  bool visitor_in_sight = false;
};

/// The closed loop, one guide cycle (1 / brian_rate s of simulated time) at
/// a time, for the node and the tools.
class FollowMeSession {
 public:
  explicit FollowMeSession(const FollowMeLoopOptions& o);
  ~FollowMeSession();
  FollowMeSession(const FollowMeSession&) = delete;
  FollowMeSession& operator=(const FollowMeSession&) = delete;

  /// Runs one cycle; false once the tour is completed or the time is up.
  bool cycle();
  /// The tour dialogue: a new tour (names of exhibits); "" when accepted,
  /// else why not. The visitor model is told the same tour.
  std::string set_tour(const std::vector<std::string>& names);
  /// Closes a door of the configuration now (the guide re-plans).
  void close_door(const std::string& name);

  double time() const;
  FollowMeTick tick() const;
  FollowMeView view() const;
  /// The measures so far (visited, wanders, ... filled in at every cycle).
  const FollowMeResult& result() const;
  const Guide& guide() const;
  const FollowMeConfig& config() const;
  const mrt::sim::World& world() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

FollowMeResult run_followme_loop(const FollowMeLoopOptions& o,
                                 const std::function<void(const FollowMeTick&)>& tick = {});

}  // namespace mrt::followme
