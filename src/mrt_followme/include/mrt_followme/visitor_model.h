// The simulated visitor's behaviour (issue 20): it follows the robot at a
// comfortable distance along the robot's own trail (so it walks through the
// doors the robot used), looks at each exhibit of the tour once the robot
// waits there, now and then wanders off to another exhibit and stays, and
// comes back when the robot calls it or after a while. It sees the robot
// (its true pose); the robot sees it only through its camera. ROS-free.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "mrt_followme/museum.h"

namespace mrt::followme {

enum class VisitorState { kFollow, kGoToExhibit, kLook, kWander, kStay, kReturn };
const char* to_string(VisitorState s);

/// Where to walk next: straight to `target` at `speed` (0: stand).
struct VisitorStep {
  Point2D target;
  double speed = 0.0;
};

class VisitorModel {
 public:
  /// `tour`: the exhibits in the order of the tour; `wander`: the exhibit it
  /// wanders to (used when options.wander_after > 0).
  VisitorModel(VisitorOptions options, std::vector<Exhibit> tour, Exhibit wander);

  /// One decision at time `t` (s) from its own position and the robot's.
  VisitorStep update(double t, const Point2D& self, const Pose2D& robot);
  /// The robot calls the visitor back (the dialogue): a wandering visitor
  /// comes back at once.
  void call() { called_ = true; }

  VisitorState state() const { return state_; }
  std::size_t looked() const { return looked_; }   // exhibits of the tour looked at
  bool wandered() const { return wandered_; }
  bool came_back_called() const { return came_back_called_; }

 private:
  VisitorStep follow(const Point2D& self, const Pose2D& robot) const;
  void enter(VisitorState s, double t);

  VisitorOptions opt_;
  std::vector<Exhibit> tour_;
  Exhibit wander_;
  VisitorState state_ = VisitorState::kFollow;
  double since_ = 0.0;
  std::size_t looked_ = 0;
  bool wandered_ = false, called_ = false, came_back_called_ = false;
  std::deque<Point2D> trail_;  // the robot's positions, every 0.1 m, newest last
};

}  // namespace mrt::followme
