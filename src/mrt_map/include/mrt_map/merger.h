// Merger (manual chapter 8): perceived objects produced by different
// sensors of one robot that belong to the same real object are joined
// (class compatibility + Mahalanobis gating, information fusion: the
// sensors are independent); teammates' anchors are brought to the current
// time (latency compensation) before the Tracker fuses them (covariance
// intersection, or information fusion per the class's `fusion`).
#pragma once

#include <vector>

#include "mrt_map/conceptual_model.h"
#include "mrt_map/types.h"

namespace mrt::map {

class Merger {
 public:
  explicit Merger(const ConceptualModel& model) : model_(model) {}

  /// Joins observations of one cycle: each observation goes into the
  /// cluster (from a different sensor, of a compatible class) at the
  /// smallest Mahalanobis distance (z1-z2)'(R1+R2)^-1(z1-z2) within the
  /// merge gate; a cluster's class is the most specific of its members'.
  std::vector<Observation> merge(const std::vector<Observation>& observations) const;

  /// A teammate's anchor predicted from its stamp to `now` with its class's
  /// motion model, its position variances increased by team.extra_sigma^2
  /// (the teammate's own localisation error, which its covariance does not
  /// hold in our frame); false when it is older than team.max_latency, from the
  /// future by more than that, or not finite.
  bool compensate(RemoteTrack& track, double now) const;

 private:
  const ConceptualModel& model_;
};

}  // namespace mrt::map
