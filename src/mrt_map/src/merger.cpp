#include "mrt_map/merger.h"

#include <cmath>

#include "mrt_map/kalman.h"

namespace mrt::map {

std::vector<Observation> Merger::merge(const std::vector<Observation>& observations) const {
  std::vector<Observation> clusters;
  const double gate = model_.tracker().merge_gate;
  for (const Observation& o : observations) {
    int best = -1;
    double best_d = gate;
    for (std::size_t k = 0; k < clusters.size(); ++k) {
      const Observation& c = clusters[k];
      const Vec2 y = o.z - c.z;
      const Mat2 S = o.R + c.R;
      if (y.squaredNorm() > gate * S.trace()) continue;  // cheap: surely outside the gate
      if (!model_.compatible(o.class_index, c.class_index)) continue;
      const double d = y.dot(S.ldlt().solve(y));
      if (d > best_d) continue;
      bool same_sensor = false;
      for (const auto& s : o.sensors) same_sensor = same_sensor || c.sensors.count(s) > 0;
      if (!same_sensor) {  // one sensor sees distinct objects
        best_d = d;
        best = static_cast<int>(k);
      }
    }
    if (best < 0) {
      clusters.push_back(o);
      continue;
    }
    Observation& c = clusters[static_cast<std::size_t>(best)];
    fuse_independent(c.z, c.R, o.z, o.R);
    if (model_.is_a(o.class_index, c.class_index) && o.class_index != c.class_index) {
      c.class_index = o.class_index;
      c.degree = o.degree;
    }
    c.sensors.insert(o.sensors.begin(), o.sensors.end());
    c.stamp = std::max(c.stamp, o.stamp);
  }
  return clusters;
}

bool Merger::compensate(RemoteTrack& t, double now) const {
  const double age = now - t.estimate.stamp;
  if (!(std::fabs(age) <= model_.team().max_latency)) return false;
  if (!t.estimate.x.allFinite() || !t.estimate.P.allFinite() || t.class_index < 0) return false;
  t.estimate = predict(t.estimate, model_.at(t.class_index), now);
  const double e = model_.team().extra_sigma;
  t.estimate.P(0, 0) += e * e;
  t.estimate.P(1, 1) += e * e;
  return true;
}

}  // namespace mrt::map
