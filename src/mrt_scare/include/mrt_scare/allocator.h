// SCARE coordination: the decision step (agenda) and the coordination step
// (allocation under cardinality and schema coverage, with hysteresis and
// deterministic tie-breaks). ROS-free; the rules are in doc/coordination.md.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "mrt_scare/activity.h"

namespace mrt::scare {

/// What allocation knows about one robot in one cycle (its parameters as it
/// published them, so that every robot computes from the same numbers).
struct RobotView {
  std::string id;
  std::vector<double> attitude;  // per slot (ActivitySet::slots() order), [0, 1]
  std::vector<double> time;      // per slot: s to reach the role's target (inf: unreachable)
  int incumbent = -1;            // the slot it executes now (its intention), -1 none
  double confidence = 1.0;       // (0, 1]: the age penalty of stale data
  /// s since it took its incumbent slot (inf: unknown or long ago); below
  /// the options' `dwell` it keeps that slot unless cardinality or
  /// coverage cannot be met otherwise.
  double held = std::numeric_limits<double>::infinity();
};

/// One cycle's input: opportunities per activity (degrees in [0, 1]) and
/// the team, in any order (sorted by id inside).
struct TeamInput {
  std::vector<double> opportunity;
  std::vector<RobotView> robots;
  /// Slots whose holder has just dropped out: whoever takes one earns the
  /// hysteresis its holder had, so that the survivors' own hysteresis does
  /// not keep it vacant.
  std::vector<int> vacated;
};

struct AgendaEntry {
  int activity = -1;
  double opportunity = 0.0, priority = 0.0, fit = 0.0;  // the three criteria
  int layer = 0;       // 0: dominated by no other activity, 1: only by layer 0, ...
  double score = 0.0;  // tie-break within a layer: priority * opportunity * fit
};

struct Allocation {
  std::vector<std::string> robots;  // sorted ids
  std::vector<int> slot;            // per robot: slot index, -1 unassigned
  double utility = 0.0;             // objective, hysteresis bonus included
  std::vector<AgendaEntry> agenda;
};

class Allocator {
 public:
  enum class Method { kAuto, kExact, kGreedy, kGreedyLocal };
  explicit Allocator(const ActivitySet& set);

  /// Activities with opportunity >= min_opportunity, ranked: dominance
  /// layers first, then score (higher first), then declaration order.
  std::vector<AgendaEntry> agenda(const TeamInput& in) const;
  /// kAuto: exact up to options.exact_max_robots robots, else greedy + local
  /// search. The input's robots are sorted by id first.
  Allocation allocate(TeamInput in, Method m = Method::kAuto) const;

  /// The fit of robot r for slot s: confidence * attitude / (1 + time / time_scale).
  double fit(const RobotView& r, int s) const;
  /// Utility of robot r (sorted index) in slot s given the agenda's
  /// opportunities, with the incumbent's (or a vacated slot's) hysteresis
  /// bonus; no tie-break term.
  double utility(const TeamInput& in, const RobotView& r, int s) const;
  /// Robot r is within its dwell: it holds a slot taken less than
  /// options.dwell ago.
  bool dwelling(const RobotView& r) const;
  /// Cardinality and coverage of a full assignment (slot per robot, -1 none),
  /// only agenda activities allowed.
  bool feasible(const std::vector<int>& slot, const std::vector<char>& on_agenda) const;
  /// The objective of an assignment (robots sorted), no tie-break term.
  double value(const TeamInput& in, const std::vector<int>& slot) const;

  const ActivitySet& set() const { return set_; }
  int slot_count() const { return static_cast<int>(slots_.size()); }

 private:
  struct Tables;  // per-cycle utilities with the tie-break term
  Tables tables(const TeamInput& in, const std::vector<AgendaEntry>& agenda) const;
  std::vector<int> exact(const Tables& t, const std::vector<AgendaEntry>& agenda) const;
  std::vector<int> greedy(const Tables& t, const std::vector<AgendaEntry>& agenda) const;
  void improve(const Tables& t, std::vector<int>& slot) const;

  ActivitySet set_;
  std::vector<Slot> slots_;
  std::vector<int> first_slot_;  // per activity
};

}  // namespace mrt::scare
