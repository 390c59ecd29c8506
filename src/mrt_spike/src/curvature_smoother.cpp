#include "mrt_spike/curvature_smoother.h"

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ob = ompl::base;

namespace mrt::spike {

namespace {

double wrap(double a) { return std::remainder(a, 2.0 * M_PI); }

// Where a curve's pieces (arcs, straight lines) meet, as fractions of its
// length: a Reeds-Shepp cusp is sampled exactly, so the heading change over
// distance stays the curvature on both sides of it.
std::vector<double> joints(const ob::DubinsStateSpace::DubinsPath& p) {
  const double l = p.length();
  return {p.length_[0] / l, (p.length_[0] + p.length_[1]) / l};
}
std::vector<double> joints(const ob::ReedsSheppStateSpace::ReedsSheppPath& p) {
  std::vector<double> out;
  double s = 0.0;
  for (int i = 0; i < 4; ++i) out.push_back((s += std::abs(p.length_[i])) / p.totalLength_);
  return out;
}

// The shortest curve of the space from a to b sampled every `h` of its
// length at most and at its joints (both ends included; `arc`: each
// sample's arc length from a, `joint` true for the joints); returns the length.
template <class Space, class CurvePath>
double sample(const Space& space, const Pose& a, const Pose& b, double h, std::vector<Pose>& out,
              std::vector<double>& arc, std::vector<bool>& joint) {
  ob::State* from = space.allocState();
  ob::State* to = space.allocState();
  ob::State* s = space.allocState();
  auto set = [](ob::State* st, const Pose& p) {
    auto* se2 = st->as<ob::SE2StateSpace::StateType>();
    se2->setXY(p.x, p.y);
    se2->setYaw(p.yaw);
  };
  set(from, a), set(to, b);
  bool first = true;
  CurvePath path;
  space.interpolate(from, to, 0.5, first, path, s);  // computes the path once
  const double length = space.distance(from, to);
  const int n = std::max(1, static_cast<int>(std::ceil(length / h)));
  std::vector<std::pair<double, bool>> ts;
  for (int i = 0; i <= n; ++i) ts.push_back({static_cast<double>(i) / n, false});
  if (length > 0.0)
    for (double t : joints(path))
      if (t > 1e-9 && t < 1.0 - 1e-9) ts.push_back({t, true});
  std::sort(ts.begin(), ts.end());
  for (size_t i = 0; i < ts.size(); ++i) {
    const auto [t, j] = ts[i];
    if (i > 0 && t - ts[i - 1].first < 1e-12) continue;  // a joint on a sample, or two joints together
    space.interpolate(from, to, t, first, path, s);
    const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
    out.push_back({se2->getX(), se2->getY(), se2->getYaw()});
    joint.push_back(j);
    arc.push_back(t * length);
  }
  out.front() = a, out.back() = b;  // exactly at the waypoints
  space.freeState(s), space.freeState(to), space.freeState(from);
  return length;
}

// OMPL 1.5's Dubins words assert (aborting the process) when an arc of the
// curves LSL, RSR, LSR, RSL is within 5e-7 rad below a multiple of 2 pi
// (its mod2pi rounds it to 0, and the error, times the straight part,
// fails its 2e-6 check). Whether a's and b's headings come that close to
// it (a band of 1e-6 rad): 1 for a first arc (the caller turns a's heading
// by a trifle), 2 for a last arc (b's), 0 for none.
int dubins_degenerate(const Pose& a, const Pose& b, double rho) {
  const double two_pi = 2.0 * M_PI;
  auto near_below = [two_pi](double x) {  // just below 0 mod 2 pi, but not 0
    const double m = x - two_pi * std::floor(x / two_pi);
    return two_pi - m < 1e-6 && two_pi - m > 1e-12;
  };
  const double dx = b.x - a.x, dy = b.y - a.y, d = std::sqrt(dx * dx + dy * dy) / rho, th = std::atan2(dy, dx);
  const double al = a.yaw - th, be = b.yaw - th;
  const double ca = std::cos(al), sa = std::sin(al), cb = std::cos(be), sb = std::sin(be);
  std::vector<std::pair<double, double>> arcs;  // (t, q) of each word
  const double lsl = std::atan2(cb - ca, d + sa - sb), rsr = std::atan2(ca - cb, d - sa + sb);
  arcs.push_back({lsl - al, be - lsl});
  arcs.push_back({al - rsr, rsr - be});
  const double p_rsl = std::sqrt(std::max(0.0, d * d - 2.0 + 2.0 * (ca * cb + sa * sb - d * (sa + sb))));
  const double rsl = std::atan2(ca + cb, d - sa - sb) - std::atan2(2.0, p_rsl);
  arcs.push_back({al - rsl, be - rsl});
  const double p_lsr = std::sqrt(std::max(0.0, d * d - 2.0 + 2.0 * (ca * cb + sa * sb + d * (sa + sb))));
  const double lsr = std::atan2(-ca - cb, d + sa + sb) - std::atan2(-2.0, p_lsr);
  arcs.push_back({lsr - al, lsr - be});
  for (const auto& [t, q] : arcs) {
    if (near_below(t)) return 1;
    if (near_below(q)) return 2;
  }
  return 0;
}

// Appends a piece, its first pose dropped when it repeats the last one.
void append(std::vector<Pose>& out, const std::vector<Pose>& piece) {
  size_t i = 0;
  if (!out.empty() && !piece.empty()) {
    const Pose& l = out.back();
    const Pose& f = piece.front();
    if (std::hypot(l.x - f.x, l.y - f.y) < 1e-9 && std::abs(wrap(l.yaw - f.yaw)) < 1e-9) i = 1;
  }
  out.insert(out.end(), piece.begin() + static_cast<std::ptrdiff_t>(i), piece.end());
}

}  // namespace

SmoothingOptions::Model smoothing_model(const std::string& name) {
  if (name == "none") return SmoothingOptions::Model::none;
  if (name == "dubins") return SmoothingOptions::Model::dubins;
  if (name == "reeds_shepp") return SmoothingOptions::Model::reeds_shepp;
  throw std::invalid_argument("unknown smoothing '" + name + "' (expected none, dubins or reeds_shepp)");
}

double max_curvature(const std::vector<Pose>& poses) {
  double k = 0.0;
  for (size_t i = 1; i < poses.size(); ++i) {
    const double ds = std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
    const double dth = std::abs(wrap(poses[i].yaw - poses[i - 1].yaw));
    if (ds < 1e-9) {
      if (dth > 1e-6) return std::numeric_limits<double>::infinity();
      continue;
    }
    k = std::max(k, dth / ds);
  }
  return k;
}

double polyline_length(const std::vector<Pose>& poses) {
  double l = 0.0;
  for (size_t i = 1; i < poses.size(); ++i) l += std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
  return l;
}

int corner_count(const std::vector<Pose>& poses) {
  int corners = 0;
  double last = std::numeric_limits<double>::quiet_NaN();
  for (size_t i = 1; i < poses.size(); ++i) {
    const double dx = poses[i].x - poses[i - 1].x, dy = poses[i].y - poses[i - 1].y;
    if (std::hypot(dx, dy) < 1e-9) continue;
    const double dir = std::atan2(dy, dx);
    if (!std::isnan(last) && std::abs(wrap(dir - last)) > 1e-6) ++corners;
    last = dir;
  }
  return corners;
}

std::vector<Pose> waypoint_poses(const std::vector<Cell>& cells, const GridFrame& frame) {
  std::vector<Pose> out;
  for (const Cell& c : cells)
    out.push_back({frame.origin_x + frame.resolution * c.x, frame.origin_y + frame.resolution * c.y, 0.0});
  return out;
}

CurvatureSmoother::CurvatureSmoother(const OccupancyGrid& grid, const GridFrame& frame,
                                     const SmoothingOptions& options)
    : grid_(grid), frame_(frame), options_(options) {
  if (options.model == SmoothingOptions::Model::none) throw std::invalid_argument("smoothing model none");
  if (!(options.turning_radius > 0.0)) throw std::invalid_argument("turning radius must be > 0");
  if (!(options.step > 0.0)) throw std::invalid_argument("smoothing step must be > 0");
  if (options.model == SmoothingOptions::Model::dubins)
    space_ = std::make_shared<ob::DubinsStateSpace>(options.turning_radius);
  else
    space_ = std::make_shared<ob::ReedsSheppStateSpace>(options.turning_radius);
}

bool CurvatureSmoother::free_at(double x, double y) const {
  return grid_.free(static_cast<int>(std::lround((x - frame_.origin_x) / frame_.resolution)),
                    static_cast<int>(std::lround((y - frame_.origin_y) / frame_.resolution)));
}

bool CurvatureSmoother::poses_free(const std::vector<Pose>& poses) const {
  return std::all_of(poses.begin(), poses.end(), [this](const Pose& p) { return free_at(p.x, p.y); });
}

bool CurvatureSmoother::curve(const Pose& a, const Pose& b, std::vector<Pose>& out, double& length) const {
  // checked every half cell, output every `step` and at the joints (cusps)
  const double h = std::min(options_.step, 0.5 * frame_.resolution);
  std::vector<Pose> dense;
  std::vector<bool> joint;
  std::vector<double> arc;
  if (options_.model == SmoothingOptions::Model::dubins) {
    Pose from = a, to = b;  // a heading turned by 1e-4 rad at most where OMPL 1.5 would abort
    for (double eps : {2e-6, -2e-6, 1e-5, -1e-5, 1e-4, -1e-4}) {
      const int side = dubins_degenerate(from, to, options_.turning_radius);
      if (side == 0) break;
      (side == 1 ? from.yaw : to.yaw) = (side == 1 ? a.yaw : b.yaw) + eps;
    }
    length = sample<ob::DubinsStateSpace, ob::DubinsStateSpace::DubinsPath>(
        static_cast<const ob::DubinsStateSpace&>(*space_), from, to, h, dense, arc, joint);
    dense.front() = a, dense.back() = b;
  } else {
    length = sample<ob::ReedsSheppStateSpace, ob::ReedsSheppStateSpace::ReedsSheppPath>(
        static_cast<const ob::ReedsSheppStateSpace&>(*space_), a, b, h, dense, arc, joint);
  }
  if (!poses_free(dense)) return false;
  // output: the ends, the joints (cusps), and no two poses further than
  // `step` apart; Dubins: none within 1 mm of an end (a heading turned there)
  std::vector<size_t> cand;
  for (size_t i = 0; i < dense.size(); ++i) {
    const bool end = i == 0 || i + 1 == dense.size();
    const bool beside = options_.model == SmoothingOptions::Model::dubins && (arc[i] < 1e-3 || length - arc[i] < 1e-3);
    if (end || !beside) cand.push_back(i);
  }
  out.clear();
  double kept = 0.0;  // arc length at the last pose kept
  for (size_t k = 0; k < cand.size(); ++k) {
    const size_t i = cand[k];
    if (k == 0 || k + 1 == cand.size() || joint[i] || arc[cand[k + 1]] - kept > options_.step + 1e-9) {
      out.push_back(dense[i]);
      kept = arc[i];
    }
  }
  return true;
}

// The curve from a to b; a colliding one is split at the middle of the
// straight segment (heading along it), `splits` times at most, then the
// straight segment is kept (turning on the spot at its ends).
void CurvatureSmoother::segment(const Pose& a, const Pose& b, int splits, SmoothedPath& out) const {
  std::vector<Pose> piece;
  double length = 0.0;
  if (curve(a, b, piece, length)) {
    append(out.poses, piece);
    out.length += length;
    return;
  }
  const double dir = std::atan2(b.y - a.y, b.x - a.x);
  if (splits > 0) {
    const Pose m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), dir};
    segment(a, m, splits - 1, out);
    segment(m, b, splits - 1, out);
    return;
  }
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int n = std::max(1, static_cast<int>(std::ceil(len / options_.step)));
  piece.clear();
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    piece.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), dir});
  }
  piece.push_back(b);  // turning on the spot to b's heading
  append(out.poses, piece);
  out.length += len;
  out.fully_smoothed = false;
  ++out.kept_segments;
}

SmoothedPath CurvatureSmoother::smooth(const std::vector<Pose>& waypoints, double start_yaw,
                                       std::optional<double> goal_yaw) const {
  std::vector<Pose> w;  // distinct waypoints
  for (const Pose& p : waypoints)
    if (w.empty() || std::hypot(p.x - w.back().x, p.y - w.back().y) > 1e-9) w.push_back(p);
  SmoothedPath out;
  if (w.size() < 2) {
    if (!w.empty()) out.poses.push_back({w[0].x, w[0].y, goal_yaw.value_or(start_yaw)});
    return out;
  }
  auto dir = [&w](size_t i) { return std::atan2(w[i + 1].y - w[i].y, w[i + 1].x - w[i].x); };
  w.front().yaw = std::isfinite(start_yaw) ? start_yaw : dir(0);
  for (size_t i = 1; i + 1 < w.size(); ++i) {
    const double in = dir(i - 1), out_dir = dir(i);
    const double sx = std::cos(in) + std::cos(out_dir), sy = std::sin(in) + std::sin(out_dir);
    w[i].yaw = std::hypot(sx, sy) < 1e-9 ? out_dir : std::atan2(sy, sx);  // the bisector
  }
  w.back().yaw = goal_yaw.value_or(dir(w.size() - 2));
  for (size_t i = 0; i + 1 < w.size(); ++i) segment(w[i], w[i + 1], options_.max_splits, out);
  out.max_curvature = max_curvature(out.poses);
  return out;
}

}  // namespace mrt::spike
