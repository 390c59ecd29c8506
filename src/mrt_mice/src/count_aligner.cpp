#include "mrt_mice/count_aligner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrt::mice {

void AlignerOptions::validate() const {
  if (!(std::isfinite(delay) && delay >= 0.0)) throw std::invalid_argument("align_delay: expected a number >= 0 (s)");
  if (!(std::isfinite(frame) && frame > 0.0)) throw std::invalid_argument("align_frame: expected a number > 0 (s)");
}

CountAligner::CountAligner(AlignerOptions o) : o_(o) { o_.validate(); }

bool CountAligner::add(int mouse, double t, std::int64_t dx, std::int64_t dy) {
  if ((mouse != 0 && mouse != 1) || !std::isfinite(t)) return false;
  ++stats_.reports;
  if (t < last_raw_[mouse]) {  // against the mouse's previous stamp as given
    ++stats_.out_of_order;
    return false;
  }
  last_raw_[mouse] = t;
  double* cum = cum_[mouse];
  cum[0] += static_cast<double>(dx);
  cum[1] += static_cast<double>(dy);
  if (t <= instant_) {
    // Stamped before the last common instant (a late or stalled stream):
    // its counts go into the next sample rather than being rewritten into
    // one already handed out.
    ++stats_.late;
    t = instant_ + 1e-9;
  }
  t = std::max(t, last_t_[mouse]);  // deferred reports keep their order
  const double span = std::min(o_.frame, t - last_t_[mouse]);
  r_[mouse].push_back({t, cum[0], cum[1], std::max(span, 0.0)});
  last_t_[mouse] = t;
  return true;
}

void CountAligner::value_at(int mouse, double t, double* x, double* y) const {
  double px = base_[mouse][0], py = base_[mouse][1];
  for (const Report& r : r_[mouse]) {
    if (t >= r.t) {
      px = r.x;
      py = r.y;
      continue;
    }
    // t inside this report's gathering span: a share of its counts.
    const double start = r.t - r.span;
    if (r.span > 0.0 && t > start) {
      const double f = (t - start) / r.span;
      px += f * (r.x - px);
      py += f * (r.y - py);
    }
    break;
  }
  *x = px;
  *y = py;
}

MiceCounts CountAligner::take(double now) {
  const double t = std::max(now - o_.delay, instant_);
  std::int64_t d[2][2];
  for (int m = 0; m < 2; ++m) {
    double x, y;
    value_at(m, t, &x, &y);
    const std::int64_t cx = std::llround(x), cy = std::llround(y);
    d[m][0] = cx - out_[m][0];
    d[m][1] = cy - out_[m][1];
    out_[m][0] = cx;
    out_[m][1] = cy;
    // Keep the reports still needed: the last one at or before t is the new base.
    auto& q = r_[m];
    while (!q.empty() && q.front().t <= t) {
      base_[m][0] = q.front().x;
      base_[m][1] = q.front().y;
      q.pop_front();
    }
  }
  instant_ = t;
  return {d[0][0], d[0][1], d[1][0], d[1][1]};
}

void CountAligner::reset() {
  for (int m = 0; m < 2; ++m) {
    r_[m].clear();
    base_[m][0] = base_[m][1] = cum_[m][0] = cum_[m][1] = 0.0;
    out_[m][0] = out_[m][1] = 0;
    last_t_[m] = last_raw_[m] = -1e300;
  }
}

}  // namespace mrt::mice
