#include "mrt_murea/scan.h"

#include <algorithm>
#include <cmath>

namespace mrt::murea {

std::vector<Percept> scan_percepts(const std::vector<float>& ranges, const ScanGeometry& g, int max_beams,
                                   std::size_t* invalid) {
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double r = ranges[i];
    if (std::isfinite(r) && r > g.range_min && r < g.range_max) valid.push_back(i);
  }
  if (invalid) *invalid += ranges.size() - valid.size();
  const std::size_t n = valid.size(), k = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(max_beams, 1)));
  std::vector<Percept> out;
  out.reserve(k);
  for (std::size_t j = 0; j < k; ++j) {
    const std::size_t i = valid[j * n / k];  // k <= n: distinct, increasing
    Percept p;
    p.cls = FeatureClass::Wall;
    p.distance = ranges[i];
    p.bearing = g.angle_min + static_cast<double>(i) * g.angle_increment;
    p.reliability = 1.0;
    out.push_back(p);
  }
  return out;
}

}  // namespace mrt::murea
