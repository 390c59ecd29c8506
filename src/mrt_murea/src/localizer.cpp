#include "mrt_murea/localizer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

#include "mrt_common/angle.h"

namespace mrt::murea {

using mrt::common::kPi;

namespace {

// Rounding guard on the bound's threshold: keeps the bound conservative
// when the centre pose and a sub-cell's pose are computed with different
// rounding (a point exactly on a tolerance edge).
constexpr double kGuard = 1e-9;

std::uint32_t lattice_count(double extent, double step, const char* what) {
  if (!(step > 0.0) || !std::isfinite(step)) throw std::invalid_argument(std::string("Localizer: expected a positive ") + what);
  if (!(extent >= 0.0)) throw std::invalid_argument("Localizer: expected a non-empty region");
  const double n = std::ceil(extent / step - 1e-9) + 1.0;
  if (n > 60000.0) throw std::invalid_argument(std::string("Localizer: ") + what + " too fine for the region");
  return static_cast<std::uint32_t>(n);
}

}  // namespace

Localizer::Localizer(const FeatureMap& map, const SearchOptions& o) : map_(map), opt_(o) {
  const std::array<double, 4> r =
      o.region ? *o.region : std::array<double, 4>{map.min_x(), map.min_y(), map.max_x(), map.max_y()};
  min_x_ = r[0];
  min_y_ = r[1];
  nx_ = lattice_count(r[2] - r[0], o.accuracy_xy, "accuracy_xy");
  ny_ = lattice_count(r[3] - r[1], o.accuracy_xy, "accuracy_xy");
  dx_ = nx_ > 1 ? (r[2] - r[0]) / (nx_ - 1) : 0.0;
  dy_ = ny_ > 1 ? (r[3] - r[1]) / (ny_ - 1) : 0.0;
  if (!(o.accuracy_theta > 0.0) || o.accuracy_theta > 2.0 * kPi)
    throw std::invalid_argument("Localizer: expected 0 < accuracy_theta <= 2 pi");
  wrap_ = !o.heading_range;
  if (wrap_) {
    nt_ = static_cast<std::uint32_t>(std::ceil(2.0 * kPi / o.accuracy_theta - 1e-9));
    dt_ = 2.0 * kPi / nt_;
    t0_ = -kPi;
  } else {
    const auto [lo, hi] = *o.heading_range;
    if (!std::isfinite(lo) || !(hi - lo < 2.0 * kPi)) throw std::invalid_argument("Localizer: expected min <= max < min + 2 pi in heading_range");
    nt_ = lattice_count(hi - lo, o.accuracy_theta, "accuracy_theta");
    dt_ = nt_ > 1 ? (hi - lo) / (nt_ - 1) : 0.0;
    t0_ = lo;
  }
  for (const Tolerance& t : o.tolerance)
    if (!(t.base >= 0.0) || !(t.per_metre >= 0.0))
      throw std::invalid_argument("Localizer: expected non-negative tolerances");
  if (!(o.alt_distance >= 0.0) || !(o.alt_angle >= 0.0) || !(o.ambiguity_margin >= 0.0) || !(o.timeout >= 0.0))
    throw std::invalid_argument("Localizer: expected non-negative alt_distance, alt_angle, ambiguity_margin, timeout");
}

double Localizer::t_at(std::uint32_t k) const { return t0_ + k * dt_; }

Pose2D Localizer::lattice_pose(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
  Pose2D p;
  p.x = x_at(i);
  p.y = y_at(j);
  p.theta = mrt::common::normalize_angle(t_at(k));
  return p;
}

void Localizer::cell_geometry(const Cell& c, double* cx, double* cy, double* ct, double* hx, double* hy,
                              double* ht) const {
  *cx = min_x_ + 0.5 * (c.x0 + c.x1 - 1) * dx_;
  *cy = min_y_ + 0.5 * (c.y0 + c.y1 - 1) * dy_;
  *ct = t0_ + 0.5 * (c.t0 + c.t1 - 1) * dt_;
  *hx = 0.5 * (c.x1 - c.x0 - 1) * dx_;
  *hy = 0.5 * (c.y1 - c.y0 - 1) * dy_;
  *ht = 0.5 * (c.t1 - c.t0 - 1) * dt_;
}

std::vector<Localizer::Prepared> Localizer::prepare(const std::vector<Percept>& percepts) const {
  std::vector<Prepared> out;
  for (const Percept& p : percepts) {
    if (!std::isfinite(p.distance) || !std::isfinite(p.bearing) || !std::isfinite(p.reliability) ||
        p.distance < 0.0 || p.reliability <= 0.0)
      continue;
    const Tolerance& t = opt_.tolerance[static_cast<int>(p.cls)];
    Layer layer = map_.layer(p.cls, p.color);
    const double slack = layer.slack();
    out.push_back({p.distance * std::cos(p.bearing), p.distance * std::sin(p.bearing), p.distance,
                   p.reliability, t.base + t.per_metre * p.distance, slack, std::move(layer)});
  }
  // Heaviest first, so that a cell is abandoned as early as possible.
  std::stable_sort(out.begin(), out.end(), [](const Prepared& a, const Prepared& b) { return a.w > b.w; });
  return out;
}

// Evidence of a leaf, or the bound of a larger cell. Returns early with a
// value below `floor` as soon as the cell cannot reach `floor`.
double Localizer::score(const std::vector<Prepared>& ps, const Cell& c, double floor) const {
  double cx, cy, ct, hx, hy, ht;
  const bool leaf = c.leaf();
  if (leaf) {
    cx = x_at(c.x0);
    cy = y_at(c.y0);
    ct = t_at(c.t0);
    hx = hy = ht = 0.0;
  } else {
    cell_geometry(c, &cx, &cy, &ct, &hx, &hy, &ht);
  }
  const double cs = std::cos(ct), sn = std::sin(ct);
  const double rho_xy = std::hypot(hx, hy);
  const double chord = ht >= kPi ? 2.0 : 2.0 * std::sin(0.5 * ht);  // |e^{ia} - e^{ib}| <= chord
  double remaining = 0.0;
  for (const Prepared& p : ps) remaining += p.w;
  double sum = 0.0;
  for (const Prepared& p : ps) {
    remaining -= p.w;
    const double thr = leaf ? p.tol : p.tol + rho_xy + p.r * chord + p.slack + kGuard;
    const double ox = cs * p.lx - sn * p.ly, oy = sn * p.lx + cs * p.ly;
    if (p.layer.distance(cx + ox, cy + oy) <= thr) sum += p.w;
    if (sum + remaining < floor - kGuard) return sum + remaining;
  }
  return sum;
}

double Localizer::bound(const Cell& cell, const std::vector<Percept>& percepts) const {
  return score(prepare(percepts), cell, -std::numeric_limits<double>::infinity());
}

double Localizer::evidence(const Pose2D& pose, const std::vector<Percept>& percepts) const {
  const double cs = std::cos(pose.theta), sn = std::sin(pose.theta);
  double sum = 0.0;
  for (const Prepared& p : prepare(percepts)) {
    const double ox = cs * p.lx - sn * p.ly, oy = sn * p.lx + cs * p.ly;
    if (p.layer.distance(pose.x + ox, pose.y + oy) <= p.tol) sum += p.w;
  }
  return sum;
}

// The plateau's lattice poses in the box of half-sizes (hi, hj, hk)
// indices around (ci, cj, ck); theta unwrapped around ck. Sets *face when
// one of them lies on a face of the box.
std::vector<std::array<double, 3>> Localizer::plateau_box(const std::vector<Prepared>& ps, double evidence,
                                                           const long c[3], const long h[3], bool* face) const {
  std::vector<std::array<double, 3>> members;
  *face = false;
  for (long k = c[2] - h[2]; k <= c[2] + h[2]; ++k)
    for (long j = std::max(0L, c[1] - h[1]); j <= std::min<long>(ny_ - 1, c[1] + h[1]); ++j)
      for (long i = std::max(0L, c[0] - h[0]); i <= std::min<long>(nx_ - 1, c[0] + h[0]); ++i) {
        if (!wrap_ && (k < 0 || k >= static_cast<long>(nt_))) continue;
        const auto kk = static_cast<std::uint32_t>(((k % static_cast<long>(nt_)) + nt_) % nt_);
        const auto ii = static_cast<std::uint32_t>(i), jj = static_cast<std::uint32_t>(j);
        if (score(ps, Cell{ii, ii + 1, jj, jj + 1, kk, kk + 1}, evidence) < evidence - kGuard) continue;
        members.push_back({x_at(ii), y_at(jj), (k - c[2]) * dt_});
        *face = *face || (h[0] > 0 && std::abs(i - c[0]) == h[0]) || (h[1] > 0 && std::abs(j - c[1]) == h[1]) ||
                (h[2] > 0 && std::abs(k - c[2]) == h[2]);
      }
  return members;
}

Estimate Localizer::plateau(const Hypothesis& best, const std::vector<Percept>& percepts) const {
  const std::vector<Prepared> ps = prepare(percepts);
  const auto index = [](double v, double lo, double d) { return d > 0.0 ? std::lround((v - lo) / d) : 0L; };
  double turn = std::fmod(best.pose.theta - t0_, 2.0 * kPi);  // from the first heading, in [0, 2 pi)
  if (turn < 0.0) turn += 2.0 * kPi;
  long c[3] = {index(best.pose.x, min_x_, dx_), index(best.pose.y, min_y_, dy_), index(turn, 0.0, dt_)};
  const long ht = dt_ > 0.0 ? static_cast<long>(opt_.plateau_theta / dt_) : 0;
  const long h[3] = {dx_ > 0.0 ? static_cast<long>(opt_.plateau_xy / dx_) : 0,
                     dy_ > 0.0 ? static_cast<long>(opt_.plateau_xy / dy_) : 0,
                     wrap_ ? std::min<long>(ht, (nt_ - 1) / 2) : ht};
  Estimate e;
  e.mean = best.pose;
  // The best may lie on the plateau's edge: centre the box on the mean
  // found and look again, a few times.
  for (int pass = 0; pass < 3; ++pass) {
    bool face = false;
    const auto members = plateau_box(ps, best.evidence, c, h, &face);
    if (members.empty()) return e;  // `best` is not a lattice pose of maximal evidence
    const double n = static_cast<double>(members.size());
    double sx = 0, sy = 0, sc = 0, ss = 0;
    for (const auto& m : members) {
      sx += m[0];
      sy += m[1];
      sc += std::cos(m[2]);
      ss += std::sin(m[2]);
    }
    const double mt = std::atan2(ss, sc), box_theta = t0_ + c[2] * dt_;
    e.mean = Pose2D(sx / n, sy / n, box_theta + mt);
    e.poses = members.size();
    e.truncated = face;
    e.tied.clear();
    const std::size_t stride = (members.size() + Estimate::kMaxTied - 1) / Estimate::kMaxTied;
    for (std::size_t i = 0; i < members.size(); i += stride)
      e.tied.emplace_back(members[i][0], members[i][1], box_theta + members[i][2]);
    e.covariance.fill(0.0);
    for (const auto& m : members) {
      const double d[3] = {m[0] - sx / n, m[1] - sy / n, m[2] - mt};
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) e.covariance[3 * a + b] += d[a] * d[b] / n;
    }
    e.covariance[0] += dx_ * dx_ / 12.0;
    e.covariance[4] += dy_ * dy_ / 12.0;
    e.covariance[8] += dt_ * dt_ / 12.0;
    const long next[3] = {index(e.mean.x, min_x_, dx_), index(e.mean.y, min_y_, dy_), c[2] + (dt_ > 0.0 ? std::lround(mt / dt_) : 0L)};
    if (!face || (next[0] == c[0] && next[1] == c[1] && next[2] == c[2])) break;
    std::copy(next, next + 3, c);
  }
  return e;
}

Result Localizer::exhaustive(const std::vector<Percept>& percepts) const {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Prepared> ps = prepare(percepts);
  double total = 0.0;
  for (const Prepared& p : ps) total += p.w;
  Result r;
  r.percepts = ps.size();
  double best = -1.0;
  std::vector<double> ox(ps.size()), oy(ps.size());
  for (std::uint32_t k = 0; k < nt_; ++k) {
    const double t = t_at(k), cs = std::cos(t), sn = std::sin(t);
    for (std::size_t n = 0; n < ps.size(); ++n) {
      ox[n] = cs * ps[n].lx - sn * ps[n].ly;
      oy[n] = sn * ps[n].lx + cs * ps[n].ly;
    }
    for (std::uint32_t j = 0; j < ny_; ++j)
      for (std::uint32_t i = 0; i < nx_; ++i) {
        const double x = x_at(i), y = y_at(j);
        double sum = 0.0, remaining = total;
        for (std::size_t n = 0; n < ps.size() && sum + remaining > best; ++n) {
          remaining -= ps[n].w;
          if (ps[n].layer.distance(x + ox[n], y + oy[n]) <= ps[n].tol) sum += ps[n].w;
        }
        if (sum > best) {
          best = sum;
          r.best = {lattice_pose(i, j, k), sum};
        }
      }
  }
  r.cells = static_cast<std::size_t>(nx_) * ny_ * nt_;
  r.complete = true;
  r.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace mrt::murea
