// When a robot sends its own anchors to its teammates: periodically (the
// heartbeat), and in between as soon as a teammate's latency-compensated
// prediction of what was last sent (the class's motion model from the sent
// stamp, as Merger::compensate does) is off the current own estimate by
// more than `team.send_threshold` (the dead-reckoning protocol of
// distributed simulation, IEEE 1278: send on deviation, not on a clock). A
// kicked ball then reaches the teammates one latency after the kick is seen,
// not up to a whole period later, while a rolling one costs no extra message.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "mrt_map/conceptual_model.h"
#include "mrt_map/types.h"

namespace mrt::map {

class TeamSender {
 public:
  /// `model` is held by reference (it must outlive the sender).
  /// `period` (s, > 0): the heartbeat; the threshold is the model's
  /// `team.send_threshold` (m; 0: periodic only). `tolerance` (s, >= 0):
  /// the heartbeat is due this much early, so that a caller checking once
  /// per cycle does not slip a whole cycle on its timer's jitter (map_node:
  /// half a MAP cycle).
  TeamSender(const ConceptualModel& model, double period, double tolerance = 0.0);
  /// True when `tracks` (WorldModel::local_tracks at `now`) should be sent
  /// now: the period has passed since the last send, or a track's estimate
  /// is farther than the threshold from the prediction of its last sent
  /// estimate, or a track that was not sent last time is there.
  bool due(double now, const std::vector<RemoteTrack>& tracks) const;
  /// Records a send of `tracks` at `now`.
  void sent(double now, const std::vector<RemoteTrack>& tracks);
  /// Sends so far: on the heartbeat, on a deviation.
  std::uint64_t periodic() const { return periodic_; }
  std::uint64_t on_deviation() const { return on_deviation_; }

 private:
  bool deviates(double now, const std::vector<RemoteTrack>& tracks) const;
  const ConceptualModel& model_;
  bool heartbeat(double now) const { return now - last_ >= period_ - tolerance_ - 1e-9; }
  double period_, tolerance_;
  double last_ = -1e300;
  std::map<std::uint32_t, Estimate> sent_;  // by anchor id
  std::uint64_t periodic_ = 0, on_deviation_ = 0;
};

}  // namespace mrt::map
