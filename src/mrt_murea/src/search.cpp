// Localizer::localize: the best-first search (see doc/method.md, "The search").
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <queue>

#include "mrt_common/angle.h"
#include "mrt_murea/localizer.h"

namespace mrt::murea {

using mrt::common::kPi;

namespace {

struct Node {
  Cell cell;
  double bound;
  std::uint64_t volume;
  // Max-heap order: higher bound first; on ties a leaf first (it is then
  // the answer), then the smaller cell (dives towards leaves).
  bool operator<(const Node& o) const {
    if (bound != o.bound) return bound < o.bound;
    const bool l = cell.leaf(), ol = o.cell.leaf();
    if (l != ol) return ol;
    return volume > o.volume;
  }
};

// CPU time of the calling thread (s).
double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::uint64_t volume(const Cell& c) {
  return static_cast<std::uint64_t>(c.x1 - c.x0) * (c.y1 - c.y0) * (c.t1 - c.t0);
}

}  // namespace

// The search's state, so that each step is a small function.
class Search {
 public:
  Search(const Localizer& loc, const SearchOptions& o, const std::vector<Percept>& percepts)
      : loc_(loc), opt_(o), start_(std::chrono::steady_clock::now()), cpu_start_(thread_cpu_s()),
        ps_(loc.prepare(percepts)) {
    for (const auto& p : ps_) r_max_ = std::max(r_max_, p.r);
  }

  Result run();

 private:
  bool timed_out() {
    if (opt_.timeout <= 0.0 || (++ticks_ & 63) != 0) return false;
    if (opt_.timeout_cpu) return thread_cpu_s() - cpu_start_ > opt_.timeout;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > opt_.timeout;
  }
  double floor() const {
    const double ref = best_ ? best_->evidence : incumbent_.evidence;
    return have_incumbent_ ? ref - opt_.ambiguity_margin : -std::numeric_limits<double>::infinity();
  }
  void push(const Cell& c, double cap);
  std::vector<Cell> children(const Cell& c) const;
  void split(const Node& c) {
    for (const Cell& k : children(c.cell)) push(k, c.bound);
  }
  bool in_zone(const Cell& c) const;
  Hypothesis hypothesis(const Node& n) const {
    return {loc_.lattice_pose(n.cell.x0, n.cell.y0, n.cell.t0), n.bound};
  }
  Hypothesis dive();

  const Localizer& loc_;
  const SearchOptions& opt_;
  // The CPU interval lies inside the wall-clock one (started after it, ended
  // before it), so that a single thread's cpu_ms never exceeds time_ms.
  std::chrono::steady_clock::time_point start_;
  double cpu_start_;
  std::vector<Localizer::Prepared> ps_;
  double r_max_ = 0.0;
  std::priority_queue<Node> queue_;
  std::optional<Hypothesis> best_;
  Hypothesis incumbent_;  // best leaf evaluated so far
  bool have_incumbent_ = false;
  std::size_t cells_ = 0;
  unsigned ticks_ = 0;
  friend class Localizer;
};

// Evaluates a cell and queues it unless it cannot matter. A child's bound
// is capped by its parent's (both bound the child's evidence), so bounds
// never grow down the tree; a leaf's value is exact and below the cap.
void Search::push(const Cell& c, double cap) {
  const double f = floor();
  const double b = std::min(cap, loc_.score(ps_, c, f));
  ++cells_;
  if (b < f - 1e-9) return;
  Node n{c, b, volume(c)};
  if (c.leaf() && (!have_incumbent_ || b > incumbent_.evidence)) {
    incumbent_ = hypothesis(n);
    have_incumbent_ = true;
  }
  if (best_ && in_zone(c)) return;
  queue_.push(n);
}

// Splits the dimensions that contribute most to the cell's uncertainty
// radius (x, y in metres; theta as the arc it sweeps at the farthest
// percept), each in two halves of lattice indices.
std::vector<Cell> Search::children(const Cell& c) const {
  double cx, cy, ct, hx, hy, ht;
  loc_.cell_geometry(c, &cx, &cy, &ct, &hx, &hy, &ht);
  const double contrib[3] = {hx, hy, ht * r_max_};
  const std::uint32_t lo[3] = {c.x0, c.y0, c.t0}, hi[3] = {c.x1, c.y1, c.t1};
  double m = 0.0;
  for (int d = 0; d < 3; ++d)
    if (hi[d] - lo[d] > 1) m = std::max(m, contrib[d]);
  std::uint32_t a[3][2], b[3][2];
  int parts[3];
  for (int d = 0; d < 3; ++d) {
    const bool cut = hi[d] - lo[d] > 1 && contrib[d] >= 0.5 * m;
    const std::uint32_t mid = lo[d] + (hi[d] - lo[d]) / 2;
    parts[d] = cut ? 2 : 1;
    a[d][0] = lo[d];
    b[d][0] = cut ? mid : hi[d];
    a[d][1] = mid;
    b[d][1] = hi[d];
  }
  std::vector<Cell> out;
  for (int i = 0; i < parts[0]; ++i)
    for (int j = 0; j < parts[1]; ++j)
      for (int k = 0; k < parts[2]; ++k) out.push_back({a[0][i], b[0][i], a[1][j], b[1][j], a[2][k], b[2][k]});
  return out;
}

// True when every pose of the cell is within alt_distance and alt_angle of
// the best (so it cannot hold the runner-up).
bool Search::in_zone(const Cell& c) const {
  double cx, cy, ct, hx, hy, ht;
  loc_.cell_geometry(c, &cx, &cy, &ct, &hx, &hy, &ht);
  const Pose2D& b = best_->pose;
  const double fx = std::abs(cx - b.x) + hx, fy = std::abs(cy - b.y) + hy;
  if (std::hypot(fx, fy) > opt_.alt_distance) return false;
  double from = std::fmod(ct - ht - (b.theta - opt_.alt_angle), 2.0 * kPi);
  if (from < 0.0) from += 2.0 * kPi;
  return from + 2.0 * ht <= 2.0 * opt_.alt_angle + 1e-12;
}

// Anytime fallback when no leaf was reached: from the most promising cell,
// follows the child of highest bound down to a leaf.
Hypothesis Search::dive() {
  const double none = -std::numeric_limits<double>::infinity();
  Cell c = queue_.top().cell;
  double value = queue_.top().bound;
  while (!c.leaf()) {
    Cell next = c;
    double next_value = none;
    for (const Cell& k : children(c)) {
      const double v = loc_.score(ps_, k, none);
      if (v > next_value) { next = k; next_value = v; }
    }
    c = next;
    value = next_value;
  }
  const Hypothesis h{loc_.lattice_pose(c.x0, c.y0, c.t0), value};
  return have_incumbent_ && incumbent_.evidence >= h.evidence ? incumbent_ : h;
}

Result Search::run() {
  Result r;
  r.percepts = ps_.size();
  push(loc_.root(), std::numeric_limits<double>::infinity());
  bool cut = false;
  while (!queue_.empty()) {
    if (timed_out()) { cut = true; break; }
    const Node n = queue_.top();
    queue_.pop();
    if (n.bound < floor() - 1e-9) break;  // nothing left can matter
    if (best_ && in_zone(n.cell)) continue;
    if (!n.cell.leaf()) { split(n); continue; }
    if (!best_) { best_ = hypothesis(n); continue; }  // phase 2: look for the runner-up
    r.alternative = hypothesis(n);
    break;
  }
  if (!best_) best_ = !queue_.empty() ? dive() : incumbent_;
  r.best = *best_;
  r.ambiguous = r.alternative.has_value();
  r.complete = !cut;
  r.cells = cells_;
  r.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  return r;
}

Result Localizer::localize(const std::vector<Percept>& percepts) const {
  Search s(*this, opt_, percepts);
  if (s.ps_.empty()) {  // no evidence anywhere: every pose is as good
    Result r;
    double cx, cy, ct, hx, hy, ht;
    cell_geometry(root(), &cx, &cy, &ct, &hx, &hy, &ht);
    r.best = {Pose2D(cx, cy, ct), 0.0};
    r.ambiguous = true;
    r.complete = true;
    return r;
  }
  Result r = s.run();
  if (r.complete) r.estimate = plateau(r.best, percepts);
  else r.estimate.mean = r.best.pose;
  r.cpu_ms = 1e3 * (thread_cpu_s() - s.cpu_start_);
  r.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s.start_).count();
  return r;
}

}  // namespace mrt::murea
