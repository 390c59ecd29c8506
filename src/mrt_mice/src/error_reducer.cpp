#include "mrt_mice/error_reducer.h"

#include <cmath>

namespace mrt::mice {

namespace {
double dot(const Point2D& a, const Point2D& b) { return a.x * b.x + a.y * b.y; }
double norm(const Point2D& a) { return std::hypot(a.x, a.y); }
Point2D scaled(const Point2D& a, double k) { return {a.x * k, a.y * k}; }
}  // namespace

const char* to_string(Correction c) {
  switch (c) {
    case Correction::kNone: return "none";
    case Correction::kLeftScaled: return "left_scaled";
    case Correction::kRightScaled: return "right_scaled";
    case Correction::kLeftRebuilt: return "left_rebuilt";
    case Correction::kRightRebuilt: return "right_rebuilt";
    case Correction::kUncorrectable: return "uncorrectable";
  }
  return "?";
}

ErrorReducer::ErrorReducer(const ArcModel& model, double min_projection, double max_scale)
    : e_(model.joining_direction()), min_projection_(min_projection), max_scale_(max_scale) {}

bool ErrorReducer::rebuild(const Point2D& good, bool left_is_bad, Reduction* r) const {
  if (!have_last_) return false;
  const double lg = norm(good);
  if (lg <= 0.0) return false;
  // Constant velocities: the bad mouse keeps its last direction and its
  // length ratio to the good one.
  if (left_is_bad) {
    r->u_left = scaled(last_left_dir_, lg / last_ratio_);
    r->correction = Correction::kLeftRebuilt;
  } else {
    r->u_right = scaled(last_right_dir_, lg * last_ratio_);
    r->correction = Correction::kRightRebuilt;
  }
  return true;
}

Reduction ErrorReducer::reduce(const ArcSolution& s, const Point2D& ul, const Point2D& ur,
                               bool flagged) {
  (void)s;
  Reduction r;
  r.u_left = ul;
  r.u_right = ur;
  const double nl = norm(ul), nr = norm(ur);
  if (!flagged) {
    if (nl > 0.0 && nr > 0.0 && nl > min_projection_ && nr > min_projection_) {
      last_left_dir_ = scaled(ul, 1.0 / nl);
      last_right_dir_ = scaled(ur, 1.0 / nr);
      last_ratio_ = nr / nl;
      have_last_ = true;
    }
    return r;
  }
  const double pl = dot(ul, e_), pr = dot(ur, e_);
  // The under-reading mouse has the smaller projection (same sign).
  const bool left_short = std::fabs(pl) < std::fabs(pr);
  const double p_short = left_short ? pl : pr, p_long = left_short ? pr : pl;
  if (std::fabs(p_short) >= min_projection_ && p_short * p_long > 0.0) {
    const double k = p_long / p_short;  // >= 1
    if (k <= max_scale_) {
      r.scale = k;
      if (left_short) {
        r.u_left = scaled(ul, k);
        r.correction = Correction::kLeftScaled;
      } else {
        r.u_right = scaled(ur, k);
        r.correction = Correction::kRightScaled;
      }
      return r;
    }
  }
  // The short mouse read too little to carry a direction: rebuild it.
  if (rebuild(left_short ? ur : ul, left_short, &r)) {
    const double n_old = left_short ? nl : nr;
    const double n_new = norm(left_short ? r.u_left : r.u_right);
    r.scale = n_old > 0.0 ? n_new / n_old : 0.0;
    return r;
  }
  r.correction = Correction::kUncorrectable;
  return r;
}

}  // namespace mrt::mice
