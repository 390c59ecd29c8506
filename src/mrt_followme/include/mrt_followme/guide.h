// The guide: FollowMe's sequencer (manual §2.3.2) as four jobs with their
// exceptions — Replan (ask SPIKE for the leg to the next exhibit), Guide
// (follow the plan, waiting whenever the visitor lags behind), WaitVisitor
// (at the exhibit until the visitor has looked at it and is ready) and
// FollowVisitor (the visitor wandered off or was lost: keep near it, call
// it back, then Replan) — and the doors closed on the way (re-plan the leg;
// their walls as obstacle discs for a planner that takes obstacles). Inputs
// are the localizer's pose and the visitor's track; outputs the path point
// for Mr. BRIAN, plan requests and the call to the visitor. The one guide of
// both bringups: the in-process loop (followme_loop.h) and the distributed
// guide_node drive it. ROS-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mrt_followme/museum.h"
#include "mrt_followme/visitor_tracker.h"

namespace mrt::followme {

enum class Job { kReplan, kGuide, kWaitVisitor, kFollowVisitor, kDone };
const char* to_string(Job j);

struct GuideInput {
  double t = 0.0;
  Pose2D pose;                          // the localizer's estimate
  std::optional<VisitorTrack> visitor;  // none before the first sighting
};

struct GuideOutput {
  std::optional<Point2D> goal;          // the path point Mr. BRIAN drives to; none: stand
  std::optional<Point2D> plan_request;  // ask the planner for a path from the pose to here
  bool call_visitor = false;            // the dialogue: "please come back"
};

struct GuideEvent {
  double t = 0.0;
  std::string what;     // arrived, visited, wander, call, back, lost, replan, done
  std::string exhibit;  // the tour's current exhibit
};

/// One disc of a closed door's wall, for a planner that knows obstacles
/// rather than walls (SPIKE's percepts).
struct DoorDisc {
  std::string name;  // <door>_<i>: a planner tracking obstacles by name keeps each
  Point2D center;
  double radius = 0.2;
};

/// The wall of `d` as discs of `radius` every `spacing` m at most, both
/// ends included (at least two): n = max(2, ceil(length / spacing) + 1)
/// discs at a + k (b - a), k = i / (n - 1).
std::vector<DoorDisc> door_discs(const Door& d, double spacing = 0.25, double radius = 0.2);

class Guide {
 public:
  Guide(GuideOptions options, std::vector<Exhibit> tour);

  GuideOutput update(const GuideInput& in);
  /// The planner's answer (world points, start first); empty: no plan,
  /// asked again at the next update.
  void set_plan(std::vector<Point2D> path, double t);
  /// The route is no longer valid (a door closed on it): re-plan.
  void invalidate_plan(double t, const std::string& why);
  /// The tour dialogue: a new tour (the exhibits still to visit, in order).
  void set_tour(std::vector<Exhibit> tour, double t);
  /// A door closed at `t`: kept in closed_doors(), and the leg being guided
  /// re-planned (invalidate_plan) `replan_delay` s later, at the first
  /// update from then (0: at once, for a planner that has the door already;
  /// a planner told by percepts needs a moment to take them).
  void close_door(const Door& d, double t, double replan_delay = 0.0);

  Job job() const { return job_; }
  const std::vector<Exhibit>& tour() const { return tour_; }
  std::size_t current() const { return current_; }     // index in the tour of the next exhibit
  const std::vector<std::string>& visited() const { return visited_; }
  std::size_t wanders() const { return wanders_; }
  std::size_t replans() const { return replans_; }
  bool waiting_for_visitor() const { return waiting_; }
  const std::vector<Point2D>& plan() const { return plan_; }
  const std::vector<GuideEvent>& events() const { return events_; }
  const std::vector<Door>& closed_doors() const { return closed_; }

 private:
  void enter(Job j, double t, const std::string& what);
  void next_exhibit(double t);
  GuideOutput guide(const GuideInput& in);
  GuideOutput wait_visitor(const GuideInput& in);
  GuideOutput follow_visitor(const GuideInput& in);

  GuideOptions opt_;
  std::vector<Exhibit> tour_;
  Job job_ = Job::kReplan;
  std::size_t current_ = 0;
  std::vector<std::string> visited_;
  std::size_t wanders_ = 0, replans_ = 0;
  std::vector<Point2D> plan_;
  std::size_t index_ = 0;
  bool requested_ = false, waiting_ = false, looked_ = false, called_ = false, wandering_ = false;
  double look_ = 0.0, still_ = 0.0, last_t_ = 0.0, dt_ = 0.0, called_at_ = 0.0, entered_ = 0.0;
  std::vector<GuideEvent> events_;
  std::vector<Door> closed_;
  std::optional<double> replan_at_;  // a door closed: re-plan from then
};

}  // namespace mrt::followme
