// SCARE's distributed coordination (manual ch. 11): every robot runs its
// own Coordinator, publishes its parameters and intention each cycle and
// allocates the whole team from what it last heard of everyone (its own
// entry included, as published), so that robots with the same information
// reach the same allocation. Stale teammates are penalised, silent ones
// dropped. ROS-free; the protocol is in doc/coordination.md.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mrt_common/pose2d.h"
#include "mrt_scare/allocator.h"

namespace mrt::scare {

using common::Point2D;
using common::Pose2D;

/// Estimated time for a robot to reach a point (pluggable: a planner such
/// as SPIKE can give path lengths instead).
class CostModel {
 public:
  virtual ~CostModel() = default;
  virtual double time(const RobotSpec& robot, const Pose2D& from, const Point2D& to) const = 0;
};

/// Straight-line distance / max_speed.
class StraightLineCost : public CostModel {
 public:
  double time(const RobotSpec& robot, const Pose2D& from, const Point2D& to) const override;
};

/// A robot's parameters from its pose and world model: attitude and time
/// to reach per slot (confidence 1, no incumbent).
RobotView robot_view(const ActivitySet& set, const RobotSpec& robot, const Pose2D& pose, const CrispMap& crisp,
                     const CostModel& cost);

/// What one robot tells its teammates each cycle.
struct CoordinationMessage {
  std::string robot_id;
  std::uint32_t seq = 0;
  double stamp = 0.0;  // s, sender's clock
  bool leaving = false;
  double x = 0.0, y = 0.0;           // its position (m), for teammates' coordination parameters
  int intention = -1;                // the slot it executes, -1 none
  /// s it has held its intention at `stamp` (inf: unknown), for the dwell.
  double held = std::numeric_limits<double>::infinity();
  std::vector<double> attitude;      // per slot
  std::vector<double> time;          // per slot, s (inf: target unknown)
  std::vector<double> opportunity;   // per activity, its own estimate
  /// Gossip for the drop decision: each teammate it holds and the newest
  /// stamp it has of that teammate (directly or from others' gossip).
  std::vector<std::pair<std::string, double>> heard;
};

struct CoordinatorOptions {
  double grace = 0.5;           // s of age with no penalty
  double drop_timeout = 1.0;    // s of silence after which a teammate is dropped
  double min_confidence = 0.5;  // confidence just before the drop
  double listen = 0.5;          // s a (re)starting robot only listens before taking a slot
  double hand_back_penalty = 5.0;  // s a slot handed back by the sequencer is published with attitude 0
  /// A teammate's times to reach are brought to the allocation's time (up
  /// to `grace` ahead) with their rate over its last two messages, at most
  /// this many s per s either way (a target that jumps); 0: not at all.
  double max_time_rate = 5.0;
};

/// The age penalty: 1 up to `grace`, then linear down to `min_confidence`
/// at `drop_timeout`.
double age_confidence(double age, const CoordinatorOptions& o);

/// One crisp datum for Mr. BRIAN / MAP.
struct CrispOut {
  std::string name;
  double value = 0.0;
  double reliability = 1.0;
};

class Coordinator {
 public:
  Coordinator(ActivitySet set, RobotSpec self, CoordinatorOptions o = {},
              std::shared_ptr<const CostModel> cost = nullptr);

  /// This robot's message for this cycle (parameters from its pose and its
  /// world model, intention = its current slot); kept as its own entry.
  CoordinationMessage publish(double now, const Pose2D& pose, const CrispMap& crisp);
  /// A teammate's message. False (dropped) when malformed: empty id, wrong
  /// vector sizes, values out of range. Older or repeated sequence numbers
  /// are ignored; `leaving` removes the teammate at once.
  bool receive(const CoordinationMessage& m);
  /// Drops teammates silent for drop_timeout, allocates, and adopts its own
  /// slot, unless teammates still claim it (release before acquire: then it
  /// holds none, waiting(), until they announce they left it). In a cycle
  /// in which it drops a teammate, nobody's dwell holds and the slot
  /// the teammate held carries its hysteresis (a drop-out is re-assigned at
  /// once).
  Allocation step(double now);
  /// The sequencer handed the job `slot` back (a task's `hand_back`): this
  /// robot leaves it at once (intention none) and publishes attitude 0 for
  /// it until now + hand_back_penalty, so that every robot re-allocates it
  /// from the same messages. False for an unknown slot name.
  bool hand_back(const std::string& slot, double now);

  /// The allocation input from the team as known at `now`.
  TeamInput team_input(double now) const;
  double confidence(double age) const { return age_confidence(age, options_); }

  const std::string& id() const { return self_.id; }
  int own_slot() const { return own_slot_; }
  /// When it took its current slot (s, its clock), -1 none.
  double own_since() const { return own_slot_ >= 0 ? since_ : -1.0; }
  /// The allocation gave this robot a slot teammates still claim.
  bool waiting() const { return waiting_; }
  const Allocation& last() const { return last_; }
  const ActivitySet& set() const { return allocator_.set(); }
  std::size_t team_size() const { return team_.size(); }
  /// Teammates dropped so far (silence or leaving).
  std::size_t drops() const { return drops_; }

  /// The crisp data of the last allocation: ScareJob_<Activity> (1/0),
  /// ScareRole_<Activity>_<role> (1/0), ScareMate_<role>_X/_Y/_Index for the
  /// other roles of this robot's schema, ScareTeamSize.
  std::vector<CrispOut> crisp_output() const;

 private:
  Allocator allocator_;
  RobotSpec self_;
  CoordinatorOptions options_;
  std::shared_ptr<const CostModel> cost_;
  std::vector<Slot> slots_;
  std::map<std::string, CoordinationMessage> team_;  // by id, own entry included
  std::uint32_t seq_ = 0;
  int own_slot_ = -1;
  int last_held_ = -1;  // the last slot it held (through waits)
  double since_ = 0.0;  // when it took the slot it holds or last held
  bool waiting_ = false;
  double started_ = -1.0;  // time of the first publish
  std::size_t drops_ = 0;
  std::size_t drops_seen_ = 0;  // drops_ at the last step
  std::vector<int> vacated_;    // slots of teammates dropped since the last step
  std::map<int, double> handed_back_;  // slot -> end of its penalty
  std::map<std::string, double> heard_;  // teammate -> newest stamp known through gossip
  std::map<std::string, std::vector<double>> time_rate_;  // teammate -> per slot, d time / d stamp
  void update_rate(const CoordinationMessage& before, const CoordinationMessage& m);
  /// A held teammate drops out: its slot is vacated, it is forgotten, counted.
  void drop(const std::string& id);
  void forget(const std::string& id);
  double newest(const std::string& id, const CoordinationMessage& m) const;
  Allocation last_;
};

}  // namespace mrt::scare
