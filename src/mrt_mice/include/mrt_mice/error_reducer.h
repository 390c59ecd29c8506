// Error reduction under the §4.2 hypothesis: a mouse under-reads the length
// of its path, never its direction.
#pragma once

#include "mrt_mice/arc_model.h"

namespace mrt::mice {

enum class Correction {
  kNone,           ///< nothing to correct (not flagged)
  kLeftScaled,     ///< the left reading was lengthened to satisfy the constraint
  kRightScaled,    ///< the right reading was lengthened
  kLeftRebuilt,    ///< the left mouse read (almost) nothing: direction from the last good sample
  kRightRebuilt,   ///< same for the right mouse
  kUncorrectable,  ///< inconsistent with the hypothesis; readings left as they are
};

const char* to_string(Correction c);

struct Reduction {
  Point2D u_left, u_right;  // corrected motions in base_link (m)
  Correction correction = Correction::kNone;
  double scale = 1.0;       // factor applied to the corrected mouse's length
};

/// Each reading u_i is only ever too short: the true motion is s_i u_i with
/// s_i >= 1. The constraint (s_r u_r - s_l u_l) . e = 0 is one equation in
/// two unknowns. If one mouse is right (s = 1), the other's scale follows
/// exactly: the mouse with the smaller projection on the joining line is
/// the one that under-read and is lengthened to match the other. If both
/// under-read, this is the least correction that satisfies the constraint:
/// the error is reduced, not removed (the pose stays short of the truth by
/// the better mouse's loss only).
///
/// When the short mouse's projection is too small to carry a scale (it read
/// nearly nothing, or moved almost across the line), it is rebuilt from the
/// last consistent sample (constant velocities between samples): that
/// sample's direction of the bad mouse, and its length ratio to the good
/// mouse applied to the good mouse's length now. The constraint is not
/// enforced on the rebuilt sample (it holds if the motion did not change).
class ErrorReducer {
 public:
  /// `min_projection`: projections (m) below this are not scaled; `max_scale`
  /// caps the lengthening factor.
  ErrorReducer(const ArcModel& model, double min_projection, double max_scale = 20.0);

  /// Corrects a flagged sample; records the directions of consistent ones.
  Reduction reduce(const ArcSolution& s, const Point2D& u_left, const Point2D& u_right,
                   bool flagged);
  void reset() { have_last_ = false; }

 private:
  bool rebuild(const Point2D& good, bool left_is_bad, Reduction* r) const;

  Point2D e_;
  double min_projection_;
  double max_scale_;
  bool have_last_ = false;
  Point2D last_left_dir_, last_right_dir_;  // unit vectors in base_link
  double last_ratio_ = 1.0;                 // |u_r| / |u_l| of the last consistent sample
};

}  // namespace mrt::mice
