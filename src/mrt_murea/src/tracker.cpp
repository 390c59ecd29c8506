#include "mrt_murea/tracker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "mrt_common/angle.h"

namespace mrt::murea {

namespace {

using M3 = std::array<double, 9>;

M3 mul(const M3& a, const M3& b) {
  M3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}

M3 transpose(const M3& a) {
  return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}

// a m a^T
M3 sandwich(const M3& a, const M3& m) { return mul(mul(a, m), transpose(a)); }

bool finite_pose(const Pose2D& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta); }

}  // namespace

Covariance3 compose_covariance(const Pose2D& pose, const Covariance3& p, const Pose2D& delta,
                               const Covariance3& q) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  // d(pose * delta)/d(pose) and d(pose * delta)/d(delta).
  const M3 j1{1, 0, -s * delta.x - c * delta.y, 0, 1, c * delta.x - s * delta.y, 0, 0, 1};
  const M3 j2{c, -s, 0, s, c, 0, 0, 0, 1};
  const M3 a = sandwich(j1, p), b = sandwich(j2, q);
  M3 out;
  for (int i = 0; i < 9; ++i) out[i] = a[i] + b[i];
  return out;
}

double max_evidence(const Localizer& loc, const std::vector<Percept>& percepts) {
  double total = 0.0;
  for (const Localizer::Prepared& p : loc.prepare(percepts)) total += p.w;
  return total;
}

Tracker::Tracker(const FeatureMap& map, const TrackerOptions& o) : map_(map), opt_(o) {
  if (!(o.window_sigmas > 0.0) || !(o.min_window_xy > 0.0) || !(o.max_window_xy >= o.min_window_xy) ||
      !(o.min_window_theta > 0.0) || !(o.max_window_theta >= o.min_window_theta) || !(o.max_window_theta < 3.0))
    throw std::invalid_argument("Tracker: expected 0 < min_window <= max_window (theta < 3 rad), window_sigmas > 0");
  if (!(o.collapse_fraction >= 0.0 && o.collapse_fraction <= 1.0) || o.collapse_frames < 1)
    throw std::invalid_argument("Tracker: expected collapse_fraction in [0, 1] and collapse_frames >= 1");
  if (o.settle_frames < 0) throw std::invalid_argument("Tracker: expected settle_frames >= 0");
  Localizer check(map_, opt_.search);  // validates the search options once
}

void Tracker::predict(const Pose2D& delta, const Covariance3& q) {
  if (!finite_pose(delta)) return;
  cov_ = compose_covariance(pose_, cov_, delta, q);
  pose_ = pose_ * delta;
  for (Mode& m : modes_) {
    m.covariance = compose_covariance(m.pose, m.covariance, delta, q);
    m.pose = m.pose * delta;
  }
}

void Tracker::set_search_options(const SearchOptions& search) {
  Localizer check(map_, search);  // throws before anything changes
  opt_.search = search;
}

void Tracker::set_pose(const Pose2D& pose, const Covariance3& covariance) {
  pose_ = pose;
  cov_ = covariance;
  tracking_ = has_prior_ = true;
  collapsed_frames_ = 0;
  unconfirmed_ = 0;
  modes_.clear();
}

void Tracker::reset() {
  tracking_ = has_prior_ = false;
  collapsed_frames_ = 0;
  modes_.clear();
}

const Hypothesis* Tracker::resolve_by_prior(const Result& r) const {
  if (!has_prior_ || !(opt_.prior_gate > 0.0) || !r.complete || !r.alternative) return nullptr;
  // The prior's covariance, at least the lattice's quantisation.
  Eigen::Matrix3d s = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(cov_.data());
  s.diagonal() += Eigen::Vector3d(std::pow(opt_.search.accuracy_xy, 2), std::pow(opt_.search.accuracy_xy, 2),
                                  std::pow(opt_.search.accuracy_theta, 2));
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(s);
  const auto admitted = [&](const Pose2D& p) {
    const Eigen::Vector3d d(p.x - pose_.x, p.y - pose_.y, mrt::common::angle_diff(p.theta, pose_.theta));
    const double m = d.dot(ldlt.solve(d));
    return std::isfinite(m) && m <= opt_.prior_gate;
  };
  const bool best = admitted(r.best.pose), alt = admitted(r.alternative->pose);
  if (best == alt) return nullptr;
  return best ? &r.best : &*r.alternative;
}

std::array<double, 4> Tracker::window_of(const Pose2D& p, const Covariance3& c) const {
  const double sd = std::sqrt(std::max({c[0], c[4], 0.0}));
  const double h = std::clamp(opt_.window_sigmas * sd, opt_.min_window_xy, opt_.max_window_xy);
  return {p.x - h, p.y - h, p.x + h, p.y + h};
}

std::array<double, 2> Tracker::heading_window_of(const Pose2D& p, const Covariance3& c) const {
  const double sd = std::sqrt(std::max(c[8], 0.0));
  const double h = std::clamp(opt_.window_sigmas * sd, opt_.min_window_theta, opt_.max_window_theta);
  return {p.theta - h, p.theta + h};
}

std::array<double, 4> Tracker::window() const { return window_of(pose_, cov_); }

std::array<double, 2> Tracker::heading_window() const { return heading_window_of(pose_, cov_); }

bool Tracker::refine_pose(const Localizer& loc, const std::vector<Percept>& percepts, bool with_prior,
                          const Pose2D* prior, const Covariance3* prior_cov) {
  if (!opt_.refine.enabled) return false;
  const Refined f = refine(loc, percepts, pose_, with_prior ? prior : nullptr, with_prior ? prior_cov : nullptr,
                           opt_.refine);
  if (!f.ok) return false;
  pose_ = f.pose;
  cov_ = f.covariance;
  return true;
}

TrackResult Tracker::global_update(const std::vector<Percept>& percepts, double total) {
  TrackResult out;
  out.mode = TrackMode::Global;
  out.max_evidence = total;
  const Localizer loc(map_, opt_.search);
  out.search = loc.localize(percepts);
  const Result& r = out.search;
  out.collapsed = r.best.evidence < opt_.collapse_fraction * total || total <= 0.0;
  // A search cut short by its timeout has not looked for the runner-up: its
  // best may be one of two modes (the symmetric field's mirror) as likely
  // as the other, so it is not tracked either (unless track_ambiguous).
  // An ambiguous one may be resolved by the prior (the mirror is far from
  // where odometry carried the last pose).
  const Hypothesis* chosen = resolve_by_prior(r);
  out.resolved = chosen != nullptr;
  modes_.clear();
  frames_since_global_ = 0;
  const bool undecided = (r.ambiguous && !chosen) || !r.complete;
  if (out.collapsed || (undecided && !opt_.track_ambiguous)) {
    // Nothing trustworthy, two modes, or not known: stay lost, keep the last
    // pose; two modes the prior did not tell apart widen it.
    if (r.ambiguous && has_prior_) {
      cov_[0] += opt_.lost_growth_xy * opt_.lost_growth_xy;
      cov_[4] += opt_.lost_growth_xy * opt_.lost_growth_xy;
      cov_[8] += opt_.lost_growth_theta * opt_.lost_growth_theta;
    }
    if (!out.collapsed && r.ambiguous && r.complete && opt_.ambiguous_global_period > 0)
      keep_modes(loc, r, percepts);
    out.modes = modes_.size();
    out.lost = true;
    out.pose = pose_;
    out.covariance = cov_;
    return out;
  }
  if (chosen && chosen != &r.best) {  // the runner-up: its own plateau
    const Estimate e = loc.plateau(*chosen, percepts);
    pose_ = e.mean;
    cov_ = e.covariance;
  } else if (r.complete) {
    pose_ = r.estimate.mean;
    cov_ = r.estimate.covariance;
  } else {  // anytime result: as uncertain as the largest window
    pose_ = r.best.pose;
    cov_ = {};
    cov_[0] = cov_[4] = std::pow(opt_.max_window_xy / opt_.window_sigmas, 2);
    cov_[8] = std::pow(opt_.max_window_theta / opt_.window_sigmas, 2);
  }
  out.refined = refine_pose(loc, percepts, false);
  tracking_ = has_prior_ = true;
  collapsed_frames_ = 0;
  unconfirmed_ = opt_.settle_frames;
  out.settled = settled();
  out.pose = pose_;
  out.covariance = cov_;
  return out;
}

void Tracker::keep_modes(const Localizer& loc, const Result& r, const std::vector<Percept>& percepts) {
  const Estimate alt = loc.plateau(*r.alternative, percepts);
  modes_ = {Mode{r.estimate.mean, r.estimate.covariance}, Mode{alt.mean, alt.covariance}};
}

TrackResult Tracker::modes_update(const std::vector<Percept>& percepts, double total) {
  TrackResult out;
  out.mode = TrackMode::Tracking;  // windowed searches, one per mode
  out.max_evidence = total;
  ++frames_since_global_;
  std::vector<SearchOptions> so(modes_.size(), opt_.search);
  std::vector<Result> rs;
  for (std::size_t i = 0; i < modes_.size(); ++i) {
    so[i].region = window_of(modes_[i].pose, modes_[i].covariance);
    so[i].heading_range = heading_window_of(modes_[i].pose, modes_[i].covariance);
    rs.push_back(Localizer(map_, so[i]).localize(percepts));
  }
  const std::size_t b = rs[0].best.evidence >= rs[1].best.evidence ? 0 : 1, o = 1 - b;
  out.search = rs[b];
  out.collapsed = total > 0.0 && rs[b].best.evidence < opt_.collapse_fraction * total;
  // The prior (after a loss) may admit one mode alone, as in global_update.
  Result pair;
  pair.best = rs[b].best;
  pair.alternative = rs[o].best;
  pair.complete = true;
  const Hypothesis* chosen = total > 0.0 && !out.collapsed ? resolve_by_prior(pair) : nullptr;
  const bool apart = rs[b].best.evidence - rs[o].best.evidence > opt_.search.ambiguity_margin;
  if (total > 0.0 && !out.collapsed && (chosen || apart)) {
    // One mode stands out: a global search confirms it before tracking
    // (a third pose, missed by the pair, may have as much evidence; the
    // global search then reports the ambiguity anew). Once per decision.
    modes_.clear();
    return global_update(percepts, total);
  } else if (out.collapsed) {
    modes_.clear();  // neither mode holds: a global search next
  } else {
    if (total > 0.0)  // each mode follows its windowed search
      for (std::size_t i = 0; i < modes_.size(); ++i)
        if (rs[i].complete) modes_[i] = {rs[i].estimate.mean, rs[i].estimate.covariance};
    out.search.alternative = rs[o].best;
    out.search.ambiguous = true;
    if (has_prior_) {  // as a global search that stays ambiguous
      cov_[0] += opt_.lost_growth_xy * opt_.lost_growth_xy;
      cov_[4] += opt_.lost_growth_xy * opt_.lost_growth_xy;
      cov_[8] += opt_.lost_growth_theta * opt_.lost_growth_theta;
    }
  }
  out.modes = modes_.size();
  out.lost = !tracking_;
  out.pose = pose_;
  out.covariance = cov_;
  return out;
}

TrackResult Tracker::update(const std::vector<Percept>& percepts) {
  const double total = max_evidence(Localizer(map_, opt_.search), percepts);
  if (!tracking_ && modes_.size() == 2 && frames_since_global_ + 1 < opt_.ambiguous_global_period)
    return modes_update(percepts, total);
  if (!tracking_) return global_update(percepts, total);
  SearchOptions so = opt_.search;
  so.region = window();
  so.heading_range = heading_window();
  const Localizer loc(map_, so);
  TrackResult out;
  out.mode = TrackMode::Tracking;
  out.max_evidence = total;
  out.search = loc.localize(percepts);
  const Result& r = out.search;
  out.collapsed = total > 0.0 && r.best.evidence < opt_.collapse_fraction * total;
  if (total <= 0.0) {
    // No usable percepts: odometry only.
  } else if (out.collapsed) {
    if (++collapsed_frames_ >= opt_.collapse_frames) tracking_ = false;  // kidnapped: global next
  } else {
    collapsed_frames_ = 0;
    const Pose2D predicted = pose_;
    const Covariance3 predicted_cov = cov_;
    if (r.complete) {
      pose_ = r.estimate.mean;
      cov_ = r.estimate.covariance;
    } else {  // anytime result: keep the prediction's uncertainty
      pose_ = r.best.pose;
      const auto w = window();
      cov_[0] = std::max(cov_[0], std::pow((w[2] - w[0]) / 2 / opt_.window_sigmas, 2));
      cov_[4] = std::max(cov_[4], cov_[0]);
    }
    out.refined = refine_pose(loc, percepts, true, &predicted, &predicted_cov);
    if (unconfirmed_ > 0) --unconfirmed_;
  }
  out.lost = !tracking_;
  out.settled = settled();
  out.pose = pose_;
  out.covariance = cov_;
  return out;
}

}  // namespace mrt::murea
