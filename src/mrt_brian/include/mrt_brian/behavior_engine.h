// Behavior Engine (manual §10.3.6): activates the behaviours whose CANDO
// passes the filter and runs them level by level (level 1 first, lowest
// priority), calling an observer between levels so that the predicate
// actions can be evaluated on the proposals made so far.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "mrt_brian/behavior.h"
#include "mrt_brian/cando_filter.h"

namespace mrt::brian {

class HierarchyObserver {
 public:
  virtual ~HierarchyObserver() = default;
  /// Manual profile: before every level above the lowest.
  virtual void before_level(int /*level*/) {}
  /// Legacy profile: before every active behaviour of level >= 2.
  virtual void before_behavior(int /*behavior*/) {}
};

class BehaviorEngine {
 public:
  BehaviorEngine();
  /// Adds a behaviour; its id is the order of addition.
  int add(std::unique_ptr<Behavior> b);
  int size() const { return static_cast<int>(behaviors_.size()); }
  const Behavior& behavior(int id) const { return *behaviors_[static_cast<std::size_t>(id)]; }
  /// Sets the threshold of the default ThresholdFilter (manual §10.4.4);
  /// the legacy profile's WANT filter follows it too (Brian reads
  /// threshold() every cycle).
  void set_threshold(double value);
  /// The threshold last set (by set_threshold, or of a ThresholdFilter given
  /// to set_filter); 0.49 by default.
  double threshold() const { return threshold_; }
  void set_filter(std::unique_ptr<CandoFilter> f);
  const CandoFilter& filter() const { return *filter_; }
  /// Orders the behaviours (levels ascending, names alphabetically inside a
  /// level). Legacy: the first missing level number ends the hierarchy.
  void finalize(Profile profile);
  /// Levels that run, in order, each with its behaviour ids.
  const std::vector<std::pair<int, std::vector<int>>>& schedule() const { return schedule_; }
  std::size_t max_proposals() const;

  /// Runs the active behaviours. `active` gets 1 for each activated one.
  void run(const std::vector<FuzzyValue>& cando, BehaviorContext& ctx, HierarchyObserver* observer,
           std::vector<std::uint8_t>& active) const;

 private:
  std::vector<std::unique_ptr<Behavior>> behaviors_;
  std::unique_ptr<CandoFilter> filter_;
  std::vector<std::pair<int, std::vector<int>>> schedule_;
  Profile profile_ = Profile::kManual;
  double threshold_ = 0.49;
};

}  // namespace mrt::brian
