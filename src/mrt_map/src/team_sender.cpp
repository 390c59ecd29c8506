#include "mrt_map/team_sender.h"

#include <stdexcept>

#include "mrt_map/kalman.h"

namespace mrt::map {

TeamSender::TeamSender(const ConceptualModel& model, double period, double tolerance)
    : model_(model), period_(period), tolerance_(tolerance) {
  if (!(period > 0.0) || !(tolerance >= 0.0 && tolerance < period))
    throw std::invalid_argument("TeamSender: expected period > 0 and 0 <= tolerance < period");
}

bool TeamSender::deviates(double now, const std::vector<RemoteTrack>& tracks) const {
  const double threshold = model_.team().send_threshold;
  if (!(threshold > 0.0)) return false;
  for (const RemoteTrack& t : tracks) {
    const auto s = sent_.find(t.id);
    if (s == sent_.end()) return true;
    const Estimate dead_reckoned = predict(s->second, model_.at(t.class_index), now);
    if ((dead_reckoned.x.head<2>() - t.estimate.x.head<2>()).norm() > threshold) return true;
  }
  return false;
}

bool TeamSender::due(double now, const std::vector<RemoteTrack>& tracks) const {
  return heartbeat(now) || deviates(now, tracks);
}

void TeamSender::sent(double now, const std::vector<RemoteTrack>& tracks) {
  ++(heartbeat(now) ? periodic_ : on_deviation_);
  last_ = now;
  sent_.clear();
  for (const RemoteTrack& t : tracks) sent_[t.id] = t.estimate;
}

}  // namespace mrt::map
